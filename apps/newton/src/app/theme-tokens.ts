/**
 * Newton's design tokens, the one place for each colour and size of Material Design's dark theme
 * as the thesis chose it. Two things are made from them: the MUI theme of the screens and
 * dialogs that load later (`mui-theme.ts`), and the CSS custom properties the first screen's
 * plain stylesheets read (`tokenCss`, put into index.html at build time by vite.config.ts), so
 * that a colour changed here changes both. No MUI here: the first screen imports this file.
 */
export const TOKENS = {
  color: {
    primary: '#82b1ff',
    /** Text on a contained primary button (MUI's contrast text for a light primary). */
    onPrimary: 'rgba(0, 0, 0, 0.87)',
    primaryHover: '#5b7cb2',
    secondary: '#ffb74d',
    onSecondary: 'rgba(0, 0, 0, 0.87)',
    secondaryHover: '#b28035',
    background: '#121212',
    paper: '#1e1e1e',
    text: '#ffffff',
    textSecondary: 'rgba(255, 255, 255, 0.7)',
    textDisabled: 'rgba(255, 255, 255, 0.5)',
    divider: 'rgba(255, 255, 255, 0.12)',
    /** The thin lines between the bars, the panel and the canvas. */
    rule: 'rgba(255, 255, 255, 0.08)',
    hover: 'rgba(255, 255, 255, 0.08)',
    selected: 'rgba(255, 255, 255, 0.16)',
    primaryTint: 'rgba(130, 177, 255, 0.08)',
    primarySelected: 'rgba(130, 177, 255, 0.16)',
    primaryBorder: 'rgba(130, 177, 255, 0.5)',
    /** The hint's light bulb. */
    hint: '#ffd54f',
    /** The ruler's body, and its ticks and numbers. */
    ruler: 'rgba(255, 224, 130, 0.85)',
    rulerInk: '#000000',
    switchThumb: '#e0e0e0',
    switchTrack: 'rgba(255, 255, 255, 0.3)',
  },
  font: {
    family: 'Roboto, system-ui, -apple-system, "Segoe UI", "Helvetica Neue", Arial, sans-serif',
    /** Labels at 13 px or more: 12 px captions are hard to read on a phone held at arm's length. */
    caption: '0.8125rem',
    body2: '0.875rem',
    body1: '1rem',
    title: '1.15rem',
    titleNarrow: '1.05rem',
  },
  shadow: {
    /** Material's elevation 1, under a switch's thumb. */
    thumb:
      '0 2px 1px -1px rgba(0, 0, 0, 0.2), 0 1px 1px 0 rgba(0, 0, 0, 0.14), 0 1px 3px 0 rgba(0, 0, 0, 0.12)',
  },
  size: {
    /** Material's grid unit (MUI's `spacing(1)`). */
    unit: '8px',
    radius: '12px',
    /** The smallest touch target. */
    target: '48px',
    bar: '52px',
    bottomBar: '60px',
    rail: '80px',
  },
} as const;

/** A token's CSS custom property: `color.primary` is `--color-primary`. */
export function tokenVariable(group: keyof typeof TOKENS, name: string): string {
  return `--${group}-${name.replace(/[A-Z]/g, (letter) => `-${letter.toLowerCase()}`)}`;
}

/** Every token as a CSS custom property on `:root`, the stylesheets' one source of values. */
export function tokenCss(): string {
  const lines: string[] = [];
  for (const [group, values] of Object.entries(TOKENS)) {
    for (const [name, value] of Object.entries(values)) {
      lines.push(`${tokenVariable(group as keyof typeof TOKENS, name)}:${value};`);
    }
  }
  return `:root{${lines.join('')}}`;
}
