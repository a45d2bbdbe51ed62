import { createTheme } from '@mui/material';
import { REDUCED_MOTION, TOUCH } from './theme.ts';
import { TOKENS } from './theme-tokens.ts';

const { color, font, size } = TOKENS;

/**
 * Material Design's dark theme for the parts drawn with MUI (Forces, Reactions and the dialogs,
 * loaded after the first screen), made from the same tokens as the first screen's stylesheet.
 */
export const muiTheme = createTheme({
  ...(REDUCED_MOTION ? { transitions: { create: () => 'none' } } : {}),
  palette: {
    mode: 'dark',
    primary: { main: color.primary },
    secondary: { main: color.secondary },
    background: { default: color.background, paper: color.paper },
  },
  typography: {
    fontFamily: font.family,
    button: { textTransform: 'none', fontWeight: 600 },
    caption: { fontSize: font.caption },
  },
  shape: { borderRadius: Number.parseFloat(size.radius) },
  components: {
    MuiButton: { defaultProps: { disableElevation: true } },
    MuiButtonBase: { defaultProps: { disableRipple: REDUCED_MOTION } },
    MuiTooltip: {
      // On a touch screen a tooltip opens on a long press only: a tap's emulated hover and the
      // focus it leaves would open one that stays on the screen until the next tap elsewhere.
      defaultProps: TOUCH ? { disableHoverListener: true, disableFocusListener: true } : {},
      styleOverrides: { tooltip: { fontSize: font.caption } },
    },
  },
});
