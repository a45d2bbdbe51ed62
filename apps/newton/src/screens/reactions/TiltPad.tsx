import { Box } from '@mui/material';
import { IconButton } from '../../ui/IconButton.tsx';
import type { ReactElement } from 'react';
import {
  ArrowDownIcon,
  ArrowLeftIcon,
  ArrowRightIcon,
  ArrowUpIcon,
  LevelIcon,
} from '../../app/icons.tsx';
import { useI18n, type MessageKey } from '../../i18n/i18n.tsx';

/** Tilt change per press. */
export const TILT_STEP = 0.25;

export interface TiltPadProps {
  /** Nudges the tilt by (dx, dy); (0, 0) with `level` levels it. */
  readonly onNudge: (dx: number, dy: number) => void;
  readonly onLevel: () => void;
}

const BUTTONS: readonly {
  key: MessageKey;
  dx: number;
  dy: number;
  icon: ReactElement;
  area: string;
}[] = [
  { key: 'reactions.tiltUp', dx: 0, dy: -1, icon: <ArrowUpIcon />, area: 'up' },
  { key: 'reactions.tiltLeft', dx: -1, dy: 0, icon: <ArrowLeftIcon />, area: 'left' },
  { key: 'reactions.tiltRight', dx: 1, dy: 0, icon: <ArrowRightIcon />, area: 'right' },
  { key: 'reactions.tiltDown', dx: 0, dy: 1, icon: <ArrowDownIcon />, area: 'down' },
];

/** The desktop's stand-in for tilting the phone: four arrows and "level" in the middle. */
export function TiltPad({ onNudge, onLevel }: TiltPadProps) {
  const { t } = useI18n();
  return (
    <Box
      role="group"
      aria-label={t('reactions.tiltPad')}
      sx={{
        display: 'grid',
        gridTemplateAreas: '". up ." "left level right" ". down ."',
        gridTemplateColumns: 'repeat(3, 48px)',
        gridTemplateRows: 'repeat(3, 48px)',
        placeItems: 'center',
      }}
    >
      {BUTTONS.map(({ key, dx, dy, icon, area }) => (
        <IconButton
          key={key}
          aria-label={t(key)}
          tip={t(key)}
          onClick={() => onNudge(dx * TILT_STEP, dy * TILT_STEP)}
          style={{ gridArea: area }}
          data-action={`tilt-${area}`}
        >
          {icon}
        </IconButton>
      ))}
      <IconButton
        aria-label={t('reactions.tiltLevel')}
        tip={t('reactions.tiltLevel')}
        onClick={onLevel}
        style={{ gridArea: 'level' }}
        data-action="tilt-level"
      >
        <LevelIcon size={20} />
      </IconButton>
    </Box>
  );
}
