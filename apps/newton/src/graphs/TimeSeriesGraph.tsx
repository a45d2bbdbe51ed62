import { useEffect, useRef } from 'react';
import { CANVAS_PIXEL_RATIO } from '../app/theme.ts';
import { useI18n } from '../i18n/i18n.tsx';
import { niceStep, type TimeSeries } from './time-series.ts';

/** One line of a graph. */
export interface GraphLine {
  readonly series: TimeSeries;
  readonly color: string;
  readonly label: string;
  /** Dashed, so a line lying exactly on another stays visible. */
  readonly dashed?: boolean;
}

export interface TimeSeriesGraphProps {
  readonly title: string;
  /** Unit of the vertical axis, e.g. "m/s". */
  readonly unit: string;
  readonly lines: readonly GraphLine[];
  /** Seconds shown (the graph scrolls once time passes it). */
  readonly window?: number;
  /** The vertical axis always includes [0, minSpan]. */
  readonly minSpan?: number;
  readonly height?: number;
}

const AXIS = 'rgba(255, 255, 255, 0.6)';
const GRID = 'rgba(255, 255, 255, 0.1)';
const TEXT = 'rgba(255, 255, 255, 0.7)';

/**
 * A small live time-series graph on a canvas: each line's samples against simulated time, with
 * a grid, ticks and a legend. Draws one animation frame after a series, the size or the locale
 * changed, and nothing otherwise: no loop runs while nothing changes.
 */
export function TimeSeriesGraph({
  title,
  unit,
  lines,
  window = 10,
  minSpan = 1,
  height = 120,
}: TimeSeriesGraphProps) {
  const canvasRef = useRef<HTMLCanvasElement | null>(null);
  const { number } = useI18n();
  const latest = useRef({ lines, window, minSpan, number, unit });
  latest.current = { lines, window, minSpan, number, unit };

  const scheduleRef = useRef<() => void>(() => undefined);
  useEffect(() => {
    const canvas = canvasRef.current!;
    let frame = 0;
    let drawn = '';
    const schedule = (): void => {
      if (frame === 0) frame = requestAnimationFrame(draw);
    };
    scheduleRef.current = schedule;
    const draw = (): void => {
      frame = 0;
      const { lines, window, minSpan, number, unit } = latest.current;
      const width = canvas.clientWidth;
      const heightPx = canvas.clientHeight;
      // No sharper than the simulation's canvas (theme.ts): a 3x phone's graph would fill 2.25
      // times the pixels of a 2x one, on a CPU that may raster the canvas itself.
      const ratio = Math.min(globalThis.devicePixelRatio || 1, CANVAS_PIXEL_RATIO);
      const key = `${lines.map((line) => line.series.version).join(',')}|${width}x${heightPx}@${ratio}|${unit}|${number(1.5)}`;
      if (key === drawn || width === 0 || heightPx === 0) return;
      drawn = key;
      canvas.width = Math.round(width * ratio);
      canvas.height = Math.round(heightPx * ratio);
      const context = canvas.getContext('2d')!;
      context.setTransform(ratio, 0, 0, ratio, 0, 0);
      context.clearRect(0, 0, width, heightPx);
      const left = 44;
      const right = 8;
      const top = 8;
      const bottom = 20;
      const plotW = Math.max(10, width - left - right);
      const plotH = Math.max(10, heightPx - top - bottom);

      let tEnd = 0;
      let low = 0;
      let high = minSpan;
      for (const { series } of lines) {
        tEnd = Math.max(tEnd, series.lastTime);
      }
      const tStart = Math.max(0, tEnd - window);
      for (const { series } of lines) {
        for (let i = 0; i < series.times.length; i++) {
          if (series.times[i]! < tStart) continue;
          low = Math.min(low, series.values[i]!);
          high = Math.max(high, series.values[i]!);
        }
      }
      const pad = (high - low) * 0.08;
      high += pad;
      if (low < 0) low -= pad;
      const xOf = (t: number): number => left + ((t - tStart) / window) * plotW;
      const yOf = (v: number): number => top + (1 - (v - low) / (high - low)) * plotH;

      context.font = '12px system-ui, sans-serif';
      context.lineWidth = 1;
      // Horizontal grid and value ticks.
      const vStep = niceStep(high - low, 4);
      context.textAlign = 'right';
      context.textBaseline = 'middle';
      for (let v = Math.ceil(low / vStep) * vStep; v <= high; v += vStep) {
        const y = Math.round(yOf(v)) + 0.5;
        context.strokeStyle = Math.abs(v) < vStep * 1e-6 ? AXIS : GRID;
        context.beginPath();
        context.moveTo(left, y);
        context.lineTo(left + plotW, y);
        context.stroke();
        context.fillStyle = TEXT;
        context.fillText(number(v, 2), left - 4, y);
      }
      // Time ticks.
      const tStep = niceStep(window, 5);
      context.textAlign = 'center';
      context.textBaseline = 'top';
      for (let t = Math.ceil(tStart / tStep) * tStep; t <= tStart + window + 1e-9; t += tStep) {
        const x = Math.round(xOf(t)) + 0.5;
        context.strokeStyle = GRID;
        context.beginPath();
        context.moveTo(x, top);
        context.lineTo(x, top + plotH);
        context.stroke();
        context.fillStyle = TEXT;
        context.fillText(`${number(t, 1)} s`, Math.min(x, left + plotW - 12), top + plotH + 4);
      }
      context.strokeStyle = AXIS;
      context.strokeRect(left + 0.5, top + 0.5, plotW, plotH);
      context.fillStyle = TEXT;
      context.textAlign = 'left';
      context.textBaseline = 'top';
      context.fillText(unit, 2, 2);
      // Lines.
      context.save();
      context.beginPath();
      context.rect(left, top, plotW, plotH);
      context.clip();
      context.lineWidth = 2;
      context.lineJoin = 'round';
      for (const { series, color, dashed } of lines) {
        context.strokeStyle = color;
        context.setLineDash(dashed === true ? [6, 5] : []);
        context.beginPath();
        let started = false;
        for (let i = 0; i < series.times.length; i++) {
          if (series.times[i]! < tStart - 0.1) continue;
          const x = xOf(series.times[i]!);
          const y = yOf(series.values[i]!);
          if (started) context.lineTo(x, y);
          else context.moveTo(x, y);
          started = true;
        }
        context.stroke();
      }
      context.restore();
    };
    const resize = new ResizeObserver(schedule);
    resize.observe(canvas);
    schedule();
    return () => {
      resize.disconnect();
      if (frame !== 0) cancelAnimationFrame(frame);
      scheduleRef.current = () => undefined;
    };
  }, []);

  // Redraw when a line's samples change (and after renders: locale, unit, lines).
  useEffect(() => {
    const stops = lines.map((line) => line.series.subscribe(() => scheduleRef.current()));
    scheduleRef.current();
    return () => {
      for (const stop of stops) stop();
    };
  });

  const summary = lines
    .map((line) =>
      line.series.last === null
        ? line.label
        : `${line.label}: ${number(line.series.last, 2)} ${unit}`,
    )
    .join(', ');

  return (
    <figure className="graph">
      <figcaption className="graph__caption">
        <span className="ui-caption ui-secondary graph__title">{title}</span>
        {lines.length > 1 &&
          lines.map((line) => (
            <span key={line.label} className="ui-caption graph__key">
              <span className="graph__swatch" style={{ background: line.color }} />
              {line.label}
            </span>
          ))}
      </figcaption>
      <canvas
        ref={canvasRef}
        role="img"
        aria-label={`${title}. ${summary}`}
        style={{ display: 'block', width: '100%', height }}
      />
    </figure>
  );
}
