import { useI18n } from '../i18n/i18n.tsx';
import { IconButton } from '../ui/IconButton.tsx';
import { Slider } from '../ui/Slider.tsx';
import { StepBackIcon } from './lab-icons.tsx';

/** Props of {@link RewindBar}. */
export interface RewindBarProps {
  /** Saved moments (a {@link SnapshotHistory}'s length). */
  readonly length: number;
  /** The moment shown: 0 the oldest, `length - 1` the newest. */
  readonly index: number;
  /** Simulated time (s) of a saved moment. */
  readonly timeAt: (index: number) => number;
  /** Go to the saved moment `index` (the simulation pauses there). */
  readonly onSeek: (index: number) => void;
}

/**
 * Step back and scrub: a button that goes back one saved step, and a slider over the saved last
 * seconds. Playing on from a moment before the newest starts a new future from there.
 */
export function RewindBar({ length, index, timeAt, onSeek }: RewindBarProps) {
  const { t, unit } = useI18n();
  const last = Math.max(0, length - 1);
  const label = t('lab.stepBack');
  return (
    <div className="rewind">
      <IconButton
        aria-label={label}
        tip={label}
        onClick={() => onSeek(index - 1)}
        disabled={index <= 0}
        data-action="step-back"
      >
        <StepBackIcon />
      </IconButton>
      <Slider
        value={Math.min(index, last)}
        min={0}
        max={Math.max(1, last)}
        step={1}
        disabled={length < 2}
        onChange={onSeek}
        aria-label={t('lab.rewind')}
        valueText={(value) => t('controls.time', { value: unit(timeAt(value), 's', 2, 2) })}
        control="rewind"
        className="rewind__slider"
      />
    </div>
  );
}
