import { ThemeProvider } from '@mui/material';
import type { ReactNode } from 'react';
import { muiTheme } from './mui-theme.ts';

/**
 * The MUI theme around a part drawn with MUI. The first screen has none (plain elements and a
 * static stylesheet: no Emotion on a slow phone's first seconds); the parts that load later wrap
 * themselves in this, each bringing MUI with its own chunk.
 */
export function MuiTheme({ children }: { children: ReactNode }) {
  return <ThemeProvider theme={muiTheme}>{children}</ThemeProvider>;
}
