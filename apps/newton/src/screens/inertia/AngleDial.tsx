import { Box } from '@mui/material';
import { useRef, type KeyboardEvent, type PointerEvent } from 'react';

export interface AngleDialProps {
  /** Degrees counter-clockwise from "right", 0..359. */
  readonly angle: number;
  readonly onChange: (angle: number) => void;
  /** Sides of the polygon drawn in the middle. */
  readonly sides: number;
  readonly label: string;
  readonly valueText: string;
}

const SIZE = 240;
const C = SIZE / 2;
const BODY = 34;
const ARROW = 100;

const wrap = (degrees: number): number => ((Math.round(degrees) % 360) + 360) % 360;

/**
 * The force dialog's picture: the object in the middle and an arrow around it. Drag anywhere to
 * point the arrow; with focus, arrow keys turn it by 5 degrees, Page Up/Down by 45, Home points
 * it right.
 */
export function AngleDial({ angle, onChange, sides, label, valueText }: AngleDialProps) {
  const svgRef = useRef<SVGSVGElement | null>(null);
  const dragging = useRef(false);

  const fromPointer = (event: PointerEvent<SVGSVGElement>): void => {
    const rect = svgRef.current!.getBoundingClientRect();
    const x = event.clientX - rect.left - rect.width / 2;
    const y = event.clientY - rect.top - rect.height / 2;
    if (Math.hypot(x, y) < 4) return;
    onChange(wrap((Math.atan2(-y, x) * 180) / Math.PI));
  };

  const onKeyDown = (event: KeyboardEvent<SVGSVGElement>): void => {
    const steps: Record<string, number> = {
      ArrowUp: 5,
      ArrowRight: 5,
      ArrowDown: -5,
      ArrowLeft: -5,
      PageUp: 45,
      PageDown: -45,
    };
    if (event.key === 'Home') onChange(0);
    else if (event.key === 'End') onChange(270);
    else if (event.key in steps) onChange(wrap(angle + steps[event.key]!));
    else return;
    event.preventDefault();
  };

  const radians = (angle * Math.PI) / 180;
  const ux = Math.cos(radians);
  const uy = -Math.sin(radians);
  const start = BODY + 8;
  const tipX = C + ux * ARROW;
  const tipY = C + uy * ARROW;
  const headBase = ARROW - 16;
  const bx = C + ux * headBase;
  const by = C + uy * headBase;
  const polygon = Array.from({ length: sides }, (_, i) => {
    const a = -Math.PI / 2 + (2 * Math.PI * i) / sides;
    return `${C + BODY * Math.cos(a)},${C + BODY * Math.sin(a)}`;
  }).join(' ');

  return (
    <Box sx={{ display: 'flex', justifyContent: 'center' }}>
      <svg
        ref={svgRef}
        width={SIZE}
        height={SIZE}
        viewBox={`0 0 ${SIZE} ${SIZE}`}
        role="slider"
        tabIndex={0}
        aria-label={label}
        aria-valuemin={0}
        aria-valuemax={359}
        aria-valuenow={angle}
        aria-valuetext={valueText}
        data-testid="angle-dial"
        onKeyDown={onKeyDown}
        onPointerDown={(event) => {
          dragging.current = true;
          event.currentTarget.setPointerCapture(event.pointerId);
          fromPointer(event);
        }}
        onPointerMove={(event) => dragging.current && fromPointer(event)}
        onPointerUp={() => (dragging.current = false)}
        onPointerCancel={() => (dragging.current = false)}
        style={{ touchAction: 'none', cursor: 'grab', outlineOffset: 4, borderRadius: '50%' }}
      >
        <circle cx={C} cy={C} r={ARROW + 6} fill="#1b2631" stroke="rgba(255,255,255,0.2)" />
        {[0, 90, 180, 270].map((tick) => {
          const a = (tick * Math.PI) / 180;
          return (
            <line
              key={tick}
              x1={C + Math.cos(a) * (ARROW - 4)}
              y1={C - Math.sin(a) * (ARROW - 4)}
              x2={C + Math.cos(a) * (ARROW + 6)}
              y2={C - Math.sin(a) * (ARROW + 6)}
              stroke="rgba(255,255,255,0.45)"
              strokeWidth={2}
            />
          );
        })}
        <polygon points={polygon} fill="#4fc3f7" stroke="rgba(0,0,0,0.45)" />
        <line
          x1={C + ux * start}
          y1={C + uy * start}
          x2={bx}
          y2={by}
          stroke="#ff8a65"
          strokeWidth={6}
          strokeLinecap="round"
        />
        <polygon
          points={`${tipX},${tipY} ${bx - uy * 11},${by + ux * 11} ${bx + uy * 11},${by - ux * 11}`}
          fill="#ff8a65"
        />
        <circle cx={tipX} cy={tipY} r={16} fill="rgba(255,138,101,0.18)" />
      </svg>
    </Box>
  );
}
