import type { PhysicalCanvasElement } from '@physical/canvas';
import { useEffect, useRef, useState, type KeyboardEvent, type PointerEvent } from 'react';
import { useI18n } from '../i18n/i18n.tsx';

/** The ruler's length (m) and the marks on it: a tick every 10 cm, a number every 50 cm. */
export const RULER_LENGTH = 2;
const TICK = 0.1;
const NUMBERED = 0.5;
/** How far an arrow key moves the ruler (m); with Shift, ten times as far. */
export const RULER_KEY_STEP = 0.05;
const RULER_HEIGHT = 34;

/** Props of {@link Ruler}. */
export interface RulerProps {
  /** The canvas the ruler measures on: its scale turns metres into pixels. */
  readonly canvas: () => PhysicalCanvasElement | null;
  /** Changes when the canvas' scale may have changed (a new scene, a rotation). */
  readonly version?: unknown;
}

/** Pixels per metre on `canvas` (CSS px), or 0 before it has a size. */
function pixelsPerMetre(canvas: PhysicalCanvasElement | null): number {
  if (canvas === null) return 0;
  const a = canvas.worldToScreen({ x: 0, y: 0 });
  const b = canvas.worldToScreen({ x: 1, y: 0 });
  const scale = b.x - a.x;
  return Number.isFinite(scale) && scale > 0 ? scale : 0;
}

/**
 * A ruler laid over the simulation (PhET's measuring tape): 2 m long, marked every 10 cm and
 * numbered every 50 cm in metres, at the canvas' scale. A finger or the mouse drags it anywhere
 * over the stage; focused, the arrow keys move it 5 cm (50 cm with Shift). It sits in the
 * stage's positioned box, over the canvas.
 */
export function Ruler({ canvas, version }: RulerProps) {
  const { t, number } = useI18n();
  const [scale, setScale] = useState(0);
  // The left end's place in the stage (CSS px), set when first shown.
  const [place, setPlace] = useState<{ x: number; y: number } | null>(null);
  const ref = useRef<HTMLDivElement | null>(null);
  const drag = useRef<{ pointerId: number; dx: number; dy: number } | null>(null);

  // The canvas' scale now and whenever its size changes.
  useEffect(() => {
    const element = canvas();
    const measure = (): void => setScale(pixelsPerMetre(canvas()));
    measure();
    if (element === null) return;
    const observer = new ResizeObserver(measure);
    observer.observe(element);
    return () => observer.disconnect();
  }, [canvas, version]);

  // First shown: across the middle of the canvas, near its left side.
  useEffect(() => {
    if (place !== null || scale === 0) return;
    const element = canvas();
    const stage = ref.current?.offsetParent;
    if (element === null || !(stage instanceof HTMLElement)) return;
    const box = element.getBoundingClientRect();
    const origin = stage.getBoundingClientRect();
    setPlace({
      x: box.left - origin.left + Math.max(8, (box.width - RULER_LENGTH * scale) / 2),
      y: box.top - origin.top + box.height * 0.25,
    });
  }, [canvas, place, scale]);

  const width = RULER_LENGTH * scale;
  const move = (dx: number, dy: number): void =>
    setPlace((old) => (old === null ? old : { x: old.x + dx, y: old.y + dy }));

  const onPointerDown = (event: PointerEvent<HTMLDivElement>): void => {
    if (place === null) return;
    event.currentTarget.setPointerCapture(event.pointerId);
    drag.current = {
      pointerId: event.pointerId,
      dx: event.clientX - place.x,
      dy: event.clientY - place.y,
    };
    event.preventDefault();
  };
  const onPointerMove = (event: PointerEvent<HTMLDivElement>): void => {
    const current = drag.current;
    if (current === null || current.pointerId !== event.pointerId) return;
    setPlace({ x: event.clientX - current.dx, y: event.clientY - current.dy });
  };
  const onPointerUp = (event: PointerEvent<HTMLDivElement>): void => {
    if (drag.current?.pointerId === event.pointerId) drag.current = null;
  };
  const onKeyDown = (event: KeyboardEvent<HTMLDivElement>): void => {
    const step = RULER_KEY_STEP * (event.shiftKey ? 10 : 1) * scale;
    const keys: Record<string, [number, number]> = {
      ArrowLeft: [-step, 0],
      ArrowRight: [step, 0],
      ArrowUp: [0, -step],
      ArrowDown: [0, step],
    };
    const by = keys[event.key];
    if (by === undefined) return;
    event.preventDefault();
    move(by[0], by[1]);
  };

  const marks: number[] = [];
  for (let i = 0; i * NUMBERED <= RULER_LENGTH + 1e-9; i++) marks.push(i * NUMBERED);
  return (
    <div
      ref={ref}
      tabIndex={0}
      role="group"
      aria-roledescription={t('lab.ruler')}
      aria-label={t('lab.rulerLabel', { length: number(RULER_LENGTH, 0) })}
      data-ruler=""
      data-metres-per-pixel={scale === 0 ? '' : String(1 / scale)}
      onPointerDown={onPointerDown}
      onPointerMove={onPointerMove}
      onPointerUp={onPointerUp}
      onPointerCancel={onPointerUp}
      onKeyDown={onKeyDown}
      className="ruler"
      style={{
        transform: place === null ? undefined : `translate(${place.x}px, ${place.y}px)`,
        visibility: place === null || scale === 0 ? 'hidden' : 'visible',
        width: `${width}px`,
        height: `${RULER_HEIGHT}px`,
        // A tick every 10 cm, at the canvas' scale.
        backgroundImage: `repeating-linear-gradient(to right, var(--color-ruler-ink) 0 1px, transparent 1px ${TICK * scale}px)`,
      }}
    >
      {marks.map((mark) => (
        <span
          key={mark}
          aria-hidden="true"
          data-mark={mark}
          className={mark === RULER_LENGTH ? 'ruler__mark ruler__mark--end' : 'ruler__mark'}
          style={{ left: `${mark * scale}px` }}
        >
          {/* The number beside its mark, kept inside the ruler at both ends. */}
          <span>{mark === RULER_LENGTH ? `${number(mark, 1)} m` : number(mark, 1)}</span>
        </span>
      ))}
    </div>
  );
}
