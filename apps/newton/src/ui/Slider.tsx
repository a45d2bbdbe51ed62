import type { KeyboardEvent } from 'react';

/** Props of {@link Slider}. */
export interface SliderProps {
  readonly value: number;
  readonly min: number;
  readonly max: number;
  readonly step: number;
  readonly onChange: (value: number) => void;
  readonly disabled?: boolean;
  readonly 'aria-label'?: string;
  readonly 'aria-labelledby'?: string;
  /** What a screen reader says for a value ("35 %", "Time 1.20 s"). */
  readonly valueText?: (value: number) => string;
  /** The `data-control` of the slider's box, naming it for tests and tools. */
  readonly control?: string;
  readonly className?: string;
}

/** Page Up and Page Down move this many steps, as MUI's slider does (a native one moves 10 %). */
const PAGE_STEPS = 10;

/**
 * A Material slider as a native range input (role slider; arrows, Home and End as the browser
 * gives them), its filled part drawn from `--fill`.
 */
export function Slider({
  value,
  min,
  max,
  step,
  onChange,
  disabled = false,
  valueText,
  control,
  className,
  ...aria
}: SliderProps) {
  const clamped = Math.min(max, Math.max(min, value));
  const fill = max > min ? ((clamped - min) / (max - min)) * 100 : 0;
  const onKeyDown = (event: KeyboardEvent<HTMLInputElement>): void => {
    if (event.key !== 'PageUp' && event.key !== 'PageDown') return;
    event.preventDefault();
    const by = (event.key === 'PageUp' ? 1 : -1) * PAGE_STEPS * step;
    const next = Math.min(max, Math.max(min, clamped + by));
    if (next !== clamped) onChange(next);
  };
  return (
    <span
      className={className === undefined ? 'ui-slider' : `ui-slider ${className}`}
      data-control={control}
    >
      <input
        type="range"
        className="ui-slider__input"
        min={min}
        max={max}
        step={step}
        value={clamped}
        disabled={disabled}
        onChange={(event) => onChange(Number(event.currentTarget.value))}
        onKeyDown={onKeyDown}
        // Said by the browser too; written out for tools that read the attribute (as MUI's was).
        aria-valuenow={clamped}
        aria-valuetext={valueText?.(clamped)}
        style={{ ['--fill' as string]: `${fill}%` }}
        {...aria}
      />
    </span>
  );
}
