import { Box, Typography } from '@mui/material';
import { useEffect, type ReactNode } from 'react';
import { SimControls, type SimControlsProps } from './SimControls.tsx';

/** Canvas and panel side by side: a wide screen, or a phone held sideways. */
export const SIDE_BY_SIDE = '(min-width: 960px), (orientation: landscape) and (min-width: 640px)';
/** A short landscape phone: the law's text shrinks to one line. */
const SHORT = '(orientation: landscape) and (max-height: 500px)';

export interface ScreenLayoutProps {
  readonly id: string;
  readonly active: boolean;
  /** The law's statement, shown on top. */
  readonly law: string;
  /** The simulation: takes the room that is left. */
  readonly stage: ReactNode;
  /** Readouts, graphs and the screen's own buttons. */
  readonly panel: ReactNode;
  readonly controls: SimControlsProps;
}

/**
 * A screen: the law on top, the canvas filling the rest, then readouts and controls within thumb
 * reach. Side by side (canvas left, panel right) when the screen is wide and short.
 */
export function ScreenLayout({ id, active, law, stage, panel, controls }: ScreenLayoutProps) {
  // The first screen is on the page (its code loaded on demand): the app is ready.
  useEffect(() => {
    if (active) document.documentElement.dataset['ready'] = 'true';
  }, [active]);
  return (
    <Box
      component="section"
      id={id}
      aria-labelledby={`${id}-law`}
      sx={{
        display: active ? 'flex' : 'none',
        flexDirection: 'column',
        height: '100%',
        minHeight: 0,
      }}
    >
      <Typography
        id={`${id}-law`}
        component="p"
        variant="body2"
        sx={{
          px: 2,
          py: 1,
          lineHeight: 1.4,
          color: 'text.primary',
          bgcolor: 'rgba(130, 177, 255, 0.08)',
          borderBottom: '1px solid rgba(255, 255, 255, 0.08)',
          [`@media ${SHORT}`]: {
            py: 0.5,
            whiteSpace: 'nowrap',
            overflow: 'hidden',
            textOverflow: 'ellipsis',
          },
        }}
        title={law}
      >
        {law}
      </Typography>
      <Box
        sx={{
          flex: 1,
          minHeight: 0,
          display: 'flex',
          flexDirection: 'column',
          [`@media ${SIDE_BY_SIDE}`]: {
            flexDirection: 'row',
          },
        }}
      >
        <Box sx={{ flex: 1, minHeight: 180, minWidth: 0, position: 'relative', display: 'flex' }}>
          {stage}
        </Box>
        <Box
          sx={{
            display: 'flex',
            flexDirection: 'column',
            gap: 0.5,
            px: 1,
            pt: 0.5,
            [`@media ${SIDE_BY_SIDE}`]: {
              width: 360,
              flexShrink: 0,
              pb: 1,
              overflowY: 'auto',
              borderLeft: '1px solid rgba(255, 255, 255, 0.08)',
            },
          }}
        >
          {panel}
        </Box>
      </Box>
      <Box sx={{ borderTop: '1px solid rgba(255, 255, 255, 0.08)' }}>
        <SimControls {...controls} />
      </Box>
    </Box>
  );
}
