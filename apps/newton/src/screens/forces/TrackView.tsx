import { Box, ButtonBase, Typography } from '@mui/material';
import { CANVAS_PIXEL_RATIO } from '../../app/theme.ts';
import { drawArrow, type OverlayDrawer, type PhysicalCanvasElement } from '@physical/canvas';
import { PhysicalCanvas } from '@physical/react';
import { forwardRef, useCallback, useEffect, useImperativeHandle, useRef } from 'react';
import { EditIcon } from '../../app/icons.tsx';
import { simulatedTime } from '../../app/use-simulation.ts';
import type { TimeSeries } from '../../graphs/time-series.ts';
import { useI18n } from '../../i18n/i18n.tsx';
import {
  SQUARE_SIZE,
  START_X,
  TRACK_HEIGHT,
  TRACK_LENGTH,
  arrowLength,
  displacement,
  measuredAcceleration,
  opacityFor,
  type ForcesTrack,
} from './forces-scene.ts';

export interface TrackViewProps {
  readonly name: string;
  readonly track: ForcesTrack;
  readonly color: string;
  readonly paused: boolean;
  readonly timeScale: number;
  readonly position: TimeSeries;
  readonly velocity: TimeSeries;
  readonly acceleration: TimeSeries;
  readonly force: TimeSeries;
  readonly onEdit: () => void;
  readonly onPauseChange: (paused: boolean) => void;
  /** True while the learner's force F acts (after Start, before the stop). */
  readonly forceOn: boolean;
  /** The square's mass is the learner's to find: shown as "?", and its shade gives nothing away. */
  readonly hiddenMass?: boolean;
}

/** Height (CSS px) the force label needs above the square; less, and it goes beside it. */
const LABEL_HEIGHT = 16;
const LABEL_FONT = '600 14px system-ui, sans-serif';
/** The ruler's numbers: their font and the height (CSS px) of a line of it. */
const RULER_FONT = '13px system-ui, sans-serif';
const RULER_HEIGHT = 15;
/** CSS px kept between the force label and a ruler number; a number closer is left out. */
const LABEL_GAP = 3;
/** The ruler's numbers, every two metres ("2 m"...): made once, not each frame. */
const RULER_NUMBERS: readonly { readonly metre: number; readonly text: string }[] = Array.from(
  { length: Math.floor((TRACK_LENGTH - 0.5 - START_X) / 2) },
  (_, i) => ({ metre: 2 * (i + 1), text: `${2 * (i + 1)} m` }),
);
/** Widths (CSS px) of texts already measured, by font and text: a frame measures nothing new. */
const widths = new Map<string, Map<string, number>>();
/** The width of `text` in `font`, which must be the context's font now. */
function textWidth(context: CanvasRenderingContext2D, font: string, text: string): number {
  let byText = widths.get(font);
  if (byText === undefined) {
    byText = new Map();
    widths.set(font, byText);
  }
  let width = byText.get(text);
  if (width === undefined) {
    width = context.measureText(text).width;
    byText.set(text, width);
  }
  return width;
}
const VIEW_BOX = { x: -0.15, y: 0, width: TRACK_LENGTH + 0.3, height: TRACK_HEIGHT };

/** One track of the Forces screen: the canvas, its ruler and force arrow, its label and readouts. */
export const TrackView = forwardRef<PhysicalCanvasElement | null, TrackViewProps>(
  function TrackView(props, ref) {
    const { name, track, color, paused, timeScale, position, velocity, onEdit } = props;
    const { acceleration, force } = props;
    const { t, unit } = useI18n();
    const canvasRef = useRef<PhysicalCanvasElement | null>(null);
    useImperativeHandle(ref, () => canvasRef.current!, []);
    const trackRef = useRef(track);
    trackRef.current = track;
    const forceOnRef = useRef(props.forceOn);
    forceOnRef.current = props.forceOn;
    const labelsRef = useRef({ force: '', balanced: '' });
    labelsRef.current = {
      force: `F = ΣF = ${unit(track.force, 'N', 2)}`,
      balanced: t('forces.balanced'),
    };
    useEffect(() => {
      canvasRef.current?.invalidate();
    }, [props.forceOn]);

    useEffect(() => {
      canvasRef.current?.setStyle(track.square, {
        fill: color,
        stroke: '#ffffff',
        lineWidth: 1.5,
        opacity: props.hiddenMass === true ? 0.6 : opacityFor(track.settings.mass),
        label: name,
        labelColor: '#ffffff',
      });
    }, [track, color, name, props.hiddenMass]);

    const drawOverlay = useCallback<OverlayDrawer>(
      (context, canvas) => {
        const current = trackRef.current;
        const time = simulatedTime(current.world);
        if (position.times.length === 0 || time > position.lastTime) {
          position.push(time, displacement(current));
          velocity.push(time, current.square.linearVelocity.x);
          acceleration.push(time, measuredAcceleration(current) ?? 0);
          force.push(time, forceOnRef.current ? current.force : 0);
        }
        const scale = canvas.viewport.scale;
        // Ruler: a tick every metre from the start, labelled every two.
        context.save();
        context.strokeStyle = 'rgba(255, 255, 255, 0.35)';
        context.lineWidth = 1 / scale;
        context.beginPath();
        const base = TRACK_HEIGHT - 0.02;
        context.moveTo(START_X, base);
        context.lineTo(TRACK_LENGTH, base);
        for (let metre = 0; START_X + metre <= TRACK_LENGTH; metre++) {
          const x = START_X + metre;
          context.moveTo(x, base);
          context.lineTo(x, base - (metre % 2 === 0 ? 0.22 : 0.12));
        }
        context.stroke();
        const ratio = canvas.viewport.devicePixelRatio;
        context.setTransform(ratio, 0, 0, ratio, 0, 0);
        const square = current.square.position;
        const on = forceOnRef.current && current.force > 0;
        // The force and the sum of forces, labelled with their values: placed first, so that the
        // ruler's numbers it would cover are left out (on a short track it runs over their row).
        const label = canvas.worldToScreen({ x: square.x, y: square.y - SQUARE_SIZE / 2 - 0.08 });
        context.font = LABEL_FONT;
        const text = on ? labelsRef.current.force : labelsRef.current.balanced;
        const width = textWidth(context, LABEL_FONT, text);
        const room = context.canvas.width / ratio - width - 4;
        let labelX: number;
        let labelY: number;
        let labelTop: number;
        if (label.y >= LABEL_HEIGHT) {
          labelX = Math.max(4, Math.min(room, label.x - SQUARE_SIZE * scale * 0.5));
          labelY = label.y;
          labelTop = labelY - LABEL_HEIGHT;
        } else {
          // A short track (a small phone): no room above the square, so the label goes beside
          // it, past the arrow's tip, rather than cut off at the canvas's top edge.
          const tip = canvas.worldToScreen({
            x: square.x + SQUARE_SIZE / 2 + (on ? arrowLength(current.force) : 0),
            y: square.y,
          });
          labelX = Math.max(4, Math.min(room, tip.x + 6));
          labelY = tip.y + LABEL_HEIGHT / 2;
          labelTop = tip.y - LABEL_HEIGHT / 2;
        }
        context.fillStyle = 'rgba(255, 255, 255, 0.7)';
        context.font = RULER_FONT;
        context.textAlign = 'center';
        context.textBaseline = 'bottom';
        for (const { metre, text: number } of RULER_NUMBERS) {
          const point = canvas.worldToScreen({ x: START_X + metre, y: base - 0.24 });
          const half = textWidth(context, RULER_FONT, number) / 2;
          const clear =
            point.x + half + LABEL_GAP < labelX ||
            point.x - half - LABEL_GAP > labelX + width ||
            point.y + LABEL_GAP < labelTop ||
            point.y - RULER_HEIGHT - LABEL_GAP > labelY;
          if (clear) context.fillText(number, point.x, point.y);
        }
        context.font = LABEL_FONT;
        context.textAlign = 'left';
        context.fillStyle = on ? '#ff8a65' : 'rgba(255, 255, 255, 0.85)';
        context.fillText(text, labelX, labelY);
        context.restore();
        if (on) {
          drawArrow(
            context,
            scale,
            { x: square.x + SQUARE_SIZE / 2, y: square.y },
            { x: arrowLength(current.force), y: 0 },
            { kind: 'force', width: 4 },
          );
        }
      },
      [position, velocity, acceleration, force],
    );

    const settings = track.settings;
    const forceText = unit(track.force, 'N', 2);
    const massText = props.hiddenMass === true ? '? kg' : unit(settings.mass, 'kg', 2);
    const measured = measuredAcceleration(track);
    return (
      <Box
        sx={{
          position: 'relative',
          flex: 1,
          minHeight: 96,
          maxHeight: 200,
          display: 'flex',
          flexDirection: 'column',
        }}
        data-track={name}
      >
        <Box
          sx={{
            display: 'flex',
            flexWrap: 'wrap',
            alignItems: 'center',
            gap: 0.5,
            px: 0.5,
            pt: 0.5,
          }}
        >
          <ButtonBase
            onClick={onEdit}
            data-action={`edit-${name}`}
            sx={{
              minHeight: 48,
              px: 1,
              gap: 0.75,
              borderRadius: 2,
              bgcolor: 'rgba(0, 0, 0, 0.55)',
              border: `1px solid ${color}`,
              typography: 'body2',
            }}
          >
            <Box component="span" sx={{ color, fontWeight: 700 }}>
              {name}
            </Box>
            <span>
              <span data-readout={`mass-${name}`}>{massText}</span> · F ={' '}
              <b data-readout={`force-${name}`}>{forceText}</b>
            </span>
            <EditIcon size={18} />
          </ButtonBase>
          <Typography
            variant="body2"
            component="div"
            data-readout={`motion-${name}`}
            sx={{
              ml: 'auto',
              px: 0.75,
              fontSize: '0.8125rem',
              borderRadius: 1,
              fontVariantNumeric: 'tabular-nums',
              whiteSpace: 'nowrap',
            }}
          >
            x = <span data-readout={`x-${name}`}>{unit(displacement(track), 'm', 2, 2)}</span>
            {' · '}v = {unit(track.square.linearVelocity.x, 'm/s', 2, 2)}
            {' · '}a ={' '}
            <span data-readout={`a-${name}`}>
              {measured === null ? '–' : unit(measured, 'm/s²', 3, 3)}
            </span>
          </Typography>
        </Box>
        <Box
          sx={{ flex: 1, minHeight: 40, display: 'flex' }}
          // The track's label says "activate to edit": Enter and Space open the editor, as a
          // tap does (before the canvas's own Space, which would pause it).
          onKeyDownCapture={(event) => {
            if (event.key !== 'Enter' && event.key !== ' ') return;
            if (event.target !== canvasRef.current || event.repeat) return;
            event.preventDefault();
            event.stopPropagation();
            onEdit();
          }}
        >
          <PhysicalCanvas
            maxPixelRatio={CANVAS_PIXEL_RATIO}
            ref={canvasRef}
            paused={paused}
            world={track.world}
            fit="contain"
            viewBox={VIEW_BOX}
            timeScale={timeScale}
            drawOverlay={drawOverlay}
            onBodyTap={onEdit}
            onBackgroundTap={onEdit}
            onPauseChange={({ paused: value }) => props.onPauseChange(value)}
            aria-label={t('forces.canvas', {
              name,
              mass: massText,
              force: forceText,
            })}
            style={{ flex: 1, height: 'auto' }}
          />
        </Box>
      </Box>
    );
  },
);
