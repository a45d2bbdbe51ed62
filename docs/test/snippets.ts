import { readFileSync, readdirSync } from 'node:fs';

/** A fenced code block of a guide. */
export interface Snippet {
  /** Guide file name, e.g. `01-getting-started.md`. */
  readonly guide: string;
  /** 1-based line of the opening fence. */
  readonly line: number;
  readonly language: 'ts' | 'tsx';
  /** Tagged `browser` (```ts browser): type-checked only, never run in Node. */
  readonly browser: boolean;
  readonly code: string;
}

export const GUIDES = new URL('../guides/', import.meta.url);

/** Every ```ts and ```tsx block of every guide, in order. */
export function guideSnippets(): Snippet[] {
  const snippets: Snippet[] = [];
  for (const guide of readdirSync(GUIDES)
    .filter((name) => name.endsWith('.md'))
    .sort()) {
    const lines = readFileSync(new URL(guide, GUIDES), 'utf8').split('\n');
    for (let i = 0; i < lines.length; i++) {
      const fence = /^```(ts|tsx)( browser)?\s*$/.exec(lines[i]!);
      if (fence === null) continue;
      const start = i;
      const body: string[] = [];
      for (i++; i < lines.length && lines[i] !== '```'; i++) body.push(lines[i]!);
      snippets.push({
        guide,
        line: start + 1,
        language: fence[1] as 'ts' | 'tsx',
        browser: fence[2] !== undefined,
        code: body.join('\n'),
      });
    }
  }
  return snippets;
}
