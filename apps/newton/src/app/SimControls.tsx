import { Box, IconButton, ToggleButton, Tooltip, Typography } from '@mui/material';
import { useI18n } from '../i18n/i18n.tsx';
import { Live } from './Live.tsx';
import { PauseIcon, PlayIcon, ResetAllIcon, ResetIcon, SlowIcon, StepIcon } from './icons.tsx';

export interface SimControlsProps {
  readonly paused: boolean;
  readonly slow: boolean;
  /**
   * Simulated time (s); as a function, the time's text re-renders on its own while playing (the
   * screen around it need not).
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
    <Box
      role="toolbar"
      aria-label={t('controls.label')}
      sx={{
        display: 'flex',
        flexWrap: 'wrap',
        alignItems: 'center',
        columnGap: 0.25,
        px: 0.5,
        minHeight: 52,
      }}
    >
      <Tooltip title={playLabel}>
        <IconButton
          aria-label={playLabel}
          onClick={props.onTogglePlay}
          color="primary"
          size="large"
          data-action="play"
        >
          {paused ? <PlayIcon /> : <PauseIcon />}
        </IconButton>
      </Tooltip>
      <Tooltip title={t('controls.step')}>
        <span>
          <IconButton
            aria-label={t('controls.step')}
            onClick={props.onStep}
            disabled={!paused}
            size="large"
            data-action="step"
          >
            <StepIcon />
          </IconButton>
        </span>
      </Tooltip>
      <Tooltip title={t('controls.slow')}>
        <ToggleButton
          value="slow"
          selected={slow}
          onChange={props.onToggleSlow}
          aria-label={t('controls.slow')}
          size="small"
          color="primary"
          sx={{ border: 0, borderRadius: '50%', p: 1.5, minWidth: 48, minHeight: 48 }}
          data-action="slow"
        >
          <SlowIcon />
        </ToggleButton>
      </Tooltip>
      <Tooltip title={t('controls.reset')}>
        <IconButton
          aria-label={t('controls.reset')}
          onClick={props.onReset}
          size="large"
          data-action="reset"
        >
          <ResetIcon />
        </IconButton>
      </Tooltip>
      {props.onResetAll !== undefined && (
        <Tooltip title={t('controls.resetAll')}>
          <IconButton
            aria-label={t('controls.resetAll')}
            onClick={props.onResetAll}
            size="large"
            data-action="reset-all"
          >
            <ResetAllIcon />
          </IconButton>
        </Tooltip>
      )}
      <Typography
        variant="body2"
        sx={{ ml: 'auto', fontVariantNumeric: 'tabular-nums', color: 'text.secondary', pr: 1 }}
        data-readout="time"
      >
        {typeof time === 'number' ? (
          t('controls.time', { value: unit(time, 's', 2, 2) })
        ) : (
          <Live active={!paused} watch={() => String(time())}>
            {() => t('controls.time', { value: unit(time(), 's', 2, 2) })}
          </Live>
        )}
      </Typography>
    </Box>
  );
}
