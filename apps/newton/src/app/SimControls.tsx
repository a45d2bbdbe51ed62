import { useI18n } from '../i18n/i18n.tsx';
import { IconButton } from '../ui/IconButton.tsx';
import { LiveText } from './LiveText.tsx';
import { PauseIcon, PlayIcon, ResetAllIcon, ResetIcon, SlowIcon, StepIcon } from './icons.tsx';

export interface SimControlsProps {
  readonly paused: boolean;
  readonly slow: boolean;
  /**
   * Simulated time (s); as a function, the time's text rewrites itself while playing (the screen
   * around it need not re-render).
   */
  readonly time: number | (() => number);
  readonly onTogglePlay: () => void;
  readonly onStep: () => void;
  readonly onToggleSlow: () => void;
  /** Restart: this setup again from the start. */
  readonly onReset: () => void;
  /** Reset all: every setting back to its default too. */
  readonly onResetAll?: () => void;
}

/** Play / pause, single step, slow motion and reset, with the simulated time. */
export function SimControls(props: SimControlsProps) {
  const { t, unit } = useI18n();
  const { paused, slow, time } = props;
  const playLabel = paused ? t('controls.play') : t('controls.pause');
  return (
    <div role="toolbar" aria-label={t('controls.label')} className="sim-controls">
      <IconButton
        aria-label={playLabel}
        tip={playLabel}
        onClick={props.onTogglePlay}
        color="primary"
        data-action="play"
      >
        {paused ? <PlayIcon /> : <PauseIcon />}
      </IconButton>
      <IconButton
        aria-label={t('controls.step')}
        tip={t('controls.step')}
        onClick={props.onStep}
        disabled={!paused}
        data-action="step"
      >
        <StepIcon />
      </IconButton>
      <IconButton
        aria-label={t('controls.slow')}
        tip={t('controls.slow')}
        aria-pressed={slow}
        onClick={props.onToggleSlow}
        data-action="slow"
      >
        <SlowIcon />
      </IconButton>
      <IconButton
        aria-label={t('controls.reset')}
        tip={t('controls.reset')}
        onClick={props.onReset}
        data-action="reset"
      >
        <ResetIcon />
      </IconButton>
      {props.onResetAll !== undefined && (
        <IconButton
          aria-label={t('controls.resetAll')}
          tip={t('controls.resetAll')}
          onClick={props.onResetAll}
          data-action="reset-all"
        >
          <ResetAllIcon />
        </IconButton>
      )}
      <div className="ui-body2 ui-secondary ui-numbers sim-controls__time" data-readout="time">
        {typeof time === 'number' ? (
          t('controls.time', { value: unit(time, 's', 2, 2) })
        ) : (
          // Rewritten in place five times a second while playing, without a render: with 50
          // particles on a slow phone a React render for each new time cost about 1 ms a frame,
          // and each new text still costs the page a layout and a paint (Reactions at 4x CPU:
          // 1-3 ms of main-thread time a frame at ten a second). Paused, it shows the exact time.
          <LiveText
            active={!paused}
            text={() => t('controls.time', { value: unit(time(), 's', 2, 2) })}
          />
        )}
      </div>
    </div>
  );
}
