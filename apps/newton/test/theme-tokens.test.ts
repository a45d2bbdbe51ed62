import { readFileSync, readdirSync } from 'node:fs';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { describe, expect, it } from 'vitest';
import { muiTheme } from '../src/app/mui-theme.ts';
import { TOKENS, tokenCss, tokenVariable } from '../src/app/theme-tokens.ts';

const SRC = fileURLToPath(new URL('../src/', import.meta.url));

/** Every file under `folder` whose name ends in one of `endings`. */
function files(folder: string, endings: readonly string[]): string[] {
  return readdirSync(folder, { withFileTypes: true }).flatMap((entry) => {
    const path = join(folder, entry.name);
    if (entry.isDirectory()) return files(path, endings);
    return endings.some((ending) => entry.name.endsWith(ending)) ? [path] : [];
  });
}

/** The first screen's static stylesheets, and the page that paints the shell before them. */
const STYLESHEETS = [
  ...files(SRC, ['.css']),
  fileURLToPath(new URL('../index.html', import.meta.url)),
];

describe('theme tokens', () => {
  it('become one custom property each on :root, with the token as its value', () => {
    const css = tokenCss();
    expect(css).toMatch(/^:root\{.*\}$/);
    let count = 0;
    for (const [group, values] of Object.entries(TOKENS)) {
      for (const [name, value] of Object.entries(values)) {
        expect(css).toContain(`${tokenVariable(group as keyof typeof TOKENS, name)}:${value};`);
        count++;
      }
    }
    expect(css.match(/;/g)?.length).toBe(count);
    expect(tokenVariable('color', 'textSecondary')).toBe('--color-text-secondary');
  });

  it('are the only colours of the static stylesheets: each var() they read is a token or set beside it', () => {
    const defined = new Set(tokenCss().match(/--[\w-]+(?=:)/g));
    expect(STYLESHEETS.length).toBeGreaterThanOrEqual(3);
    for (const file of STYLESHEETS) {
      const text = readFileSync(file, 'utf8').replace(/\/\*[\s\S]*?\*\//g, '');
      const own = new Set(text.match(/--[\w-]+(?=\s*:)/g) ?? []);
      for (const [, name] of text.matchAll(/var\((--[\w-]+)/g)) {
        // --fill is the slider's filled share, set on the element by ui/Slider.tsx.
        const known = defined.has(name!) || own.has(name!) || name === '--fill';
        expect(known, `${file} reads ${name}, which no token defines`).toBe(true);
      }
      // A colour written out in a stylesheet would be a second copy of a token.
      const style = file.endsWith('.html')
        ? (text.match(/<style>[\s\S]*?<\/style>/)?.[0] ?? '')
        : text;
      expect(style.match(/#[0-9a-f]{3,8}\b|rgba?\(/gi), file).toBeNull();
    }
  });

  it('make the MUI theme of the parts that load later', () => {
    expect(muiTheme.palette.mode).toBe('dark');
    expect(muiTheme.palette.primary.main).toBe(TOKENS.color.primary);
    expect(muiTheme.palette.secondary.main).toBe(TOKENS.color.secondary);
    expect(muiTheme.palette.background.default).toBe(TOKENS.color.background);
    expect(muiTheme.palette.background.paper).toBe(TOKENS.color.paper);
    expect(muiTheme.typography.fontFamily).toBe(TOKENS.font.family);
    expect(`${muiTheme.shape.borderRadius}px`).toBe(TOKENS.size.radius);
  });
});
