import { Box, Typography, useMediaQuery } from '@mui/material';
import { useEffect, type ReactNode } from 'react';
import { SimControls, type SimControlsProps } from './SimControls.tsx';

/** Canvas and panel side by side: a wide screen, or any phone held sideways. */
export const SIDE_BY_SIDE = '(min-width: 960px), (orientation: landscape)';
/** A short landscape phone: the law's text shrinks to one line. */
const SHORT_LANDSCAPE = '(orientation: landscape) and (max-height: 500px)';
/** A small portrait phone (320x568 to 375x667): the law's text shrinks to two lines. */
const SHORT_PORTRAIT = '(orientation: portrait) and (max-height: 720px)';

export interface ScreenLayoutProps {
  readonly id: string;
  readonly active: boolean;
  /** The law's statement, shown on top. */
  readonly law: string;
  /** The simulation: takes the room that is left. */
  readonly stage: ReactNode;
  /** Readouts, graphs and the screen's own settings: they scroll when the phone is small. */
  readonly panel: ReactNode;
  /**
   * The screen's main buttons (Apply force, Start): always on the screen, below the panel,
   * never scrolled away.
   */
  readonly actions?: ReactNode;
  readonly controls: SimControlsProps;
}

/**
 * A screen: the law on top, the canvas filling the rest, then readouts and controls within thumb
 * reach. Side by side (canvas left, panel right) when the screen is wide or turned sideways. The
 * page itself never scrolls: on a small phone only the panel does, and the main buttons and the
 * simulation controls stay where the thumb is.
 */
export function ScreenLayout({
  id,
  active,
  law,
  stage,
  panel,
  actions,
  controls,
}: ScreenLayoutProps) {
  const sideBySide = useMediaQuery(SIDE_BY_SIDE, { noSsr: true });
  // The first screen is on the page (its code loaded on demand): the app is ready.
  useEffect(() => {
    if (active) document.documentElement.dataset['ready'] = 'true';
  }, [active]);
  const simControls = (
    <Box sx={{ borderTop: '1px solid rgba(255, 255, 255, 0.08)', flexShrink: 0 }}>
      <SimControls {...controls} />
    </Box>
  );
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
          flexShrink: 0,
          lineHeight: 1.4,
          color: 'text.primary',
          bgcolor: 'rgba(130, 177, 255, 0.08)',
          borderBottom: '1px solid rgba(255, 255, 255, 0.08)',
          [`@media ${SHORT_PORTRAIT}`]: {
            py: 0.5,
            display: '-webkit-box',
            WebkitLineClamp: 2,
            WebkitBoxOrient: 'vertical',
            overflow: 'hidden',
            // Two lines and the padding: no third line peeks out under the ellipsis.
            maxHeight: 'calc(2.8em + 8px)',
          },
          [`@media ${SHORT_LANDSCAPE}`]: {
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
          flexDirection: sideBySide ? 'row' : 'column',
        }}
      >
        <Box
          sx={{
            flex: '1 1 0',
            // Upright, the canvas keeps at least this share of the screen; the panel scrolls.
            minHeight: sideBySide ? 0 : '50%',
            minWidth: 0,
            display: 'flex',
            flexDirection: 'column',
          }}
        >
          <Box sx={{ flex: 1, minHeight: 0, minWidth: 0, position: 'relative', display: 'flex' }}>
            {stage}
          </Box>
        </Box>
        <Box
          sx={{
            display: 'flex',
            flexDirection: 'column',
            minHeight: 0,
            ...(sideBySide
              ? {
                  width: 'clamp(256px, 42%, 380px)',
                  flexShrink: 0,
                  borderLeft: '1px solid rgba(255, 255, 255, 0.08)',
                }
              : { flex: '0 1 auto' }),
          }}
        >
          <Box
            data-panel={id}
            sx={{
              flex: sideBySide ? '1 1 auto' : '0 1 auto',
              minHeight: 0,
              overflowY: 'auto',
              overscrollBehavior: 'contain',
              display: 'flex',
              flexDirection: 'column',
              gap: 0.5,
              px: 1,
              pt: 0.5,
              pb: 0.5,
            }}
          >
            {panel}
          </Box>
          {actions !== undefined && (
            <Box
              data-actions={id}
              sx={{
                display: 'flex',
                gap: 1,
                px: 1,
                py: 0.5,
                flexShrink: 0,
                borderTop: '1px solid rgba(255, 255, 255, 0.08)',
              }}
            >
              {actions}
            </Box>
          )}
          {sideBySide && simControls}
        </Box>
      </Box>
      {!sideBySide && simControls}
    </Box>
  );
}
