import { createTheme } from '@mui/material';

/** The learner asked for less motion: no transitions, no ripples, no fading arrows. */
export const REDUCED_MOTION =
  typeof matchMedia === 'function' && matchMedia('(prefers-reduced-motion: reduce)').matches;

/** A touch screen with no hover (a phone or tablet): tooltips wait for a long press. */
const TOUCH = typeof matchMedia === 'function' && matchMedia('(hover: none)').matches;

/** Material Design's dark theme, as the thesis chose; system fonts keep the download small. */
export const theme = createTheme({
  ...(REDUCED_MOTION ? { transitions: { create: () => 'none' } } : {}),
  palette: {
    mode: 'dark',
    primary: { main: '#82b1ff' },
    secondary: { main: '#ffb74d' },
    background: { default: '#121212', paper: '#1e1e1e' },
  },
  typography: {
    fontFamily: 'Roboto, system-ui, -apple-system, "Segoe UI", "Helvetica Neue", Arial, sans-serif',
    button: { textTransform: 'none', fontWeight: 600 },
    // Labels at 13 px or more: 12 px captions are hard to read on a phone held at arm's length.
    caption: { fontSize: '0.8125rem' },
  },
  shape: { borderRadius: 12 },
  components: {
    MuiButton: { defaultProps: { disableElevation: true } },
    MuiButtonBase: { defaultProps: { disableRipple: REDUCED_MOTION } },
    MuiTooltip: {
      // On a touch screen a tooltip opens on a long press only: a tap's emulated hover and the
      // focus it leaves would open one that stays on the screen until the next tap elsewhere.
      defaultProps: TOUCH ? { disableHoverListener: true, disableFocusListener: true } : {},
      styleOverrides: { tooltip: { fontSize: '0.8125rem' } },
    },
  },
});

/** Colours of the two squares on the Forces screen (and of their graph lines). */
export const SQUARE_COLORS = ['#4fc3f7', '#ffb74d'] as const;

/**
 * Device pixels per CSS px the simulation canvases draw at, at most: on a 3x phone a full-density
 * canvas fills 9 device pixels per CSS px each frame, and under 4x CPU throttling Reactions with
 * 50 particles drew 37-43 frames/s at 3x, 45-54 at 2x and 60 at 1x (npm run bench:newton).
 * Reactions drops to 1x when its frames stay slow (`PixelRatioGovernor`).
 */
export const CANVAS_PIXEL_RATIO = 2;
