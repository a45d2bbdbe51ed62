// The guides' first screens as pages: each browser snippet of a guide that hands a world to a
// canvas (`.world = world`) or exports a React component becomes a page under
// e2e/guides/generated/ (git-ignored), with the element the guide's text describes
// (`<physical-canvas ...>` in backticks before the snippet). A snippet whose first line names a
// file (`// physics.worker.ts`) is written as that file, for the pages that import it.
import { existsSync, mkdirSync, readFileSync, writeFileSync } from 'node:fs';
import { guideSnippets, GUIDES } from '../../docs/test/snippets.ts';

/** A guide's page: its address on the test server, and where it comes from. */
export interface GuidePage {
  /** For example `01-getting-started.md:21`. */
  readonly name: string;
  /** Path on the test server, for example `/guides/generated/01-getting-started-21.html`. */
  readonly path: string;
}

const generated = new URL('./generated/', import.meta.url);

/** The element markup the guide's text gives before `line` (the last one mentioned). */
function elementBefore(guide: string, line: number): string {
  const text = readFileSync(new URL(guide, GUIDES), 'utf8').split('\n').slice(0, line).join(' ');
  const tags = [...text.matchAll(/`(<physical-canvas[^`]*?>)(?:<\/physical-canvas>)?`/g)];
  const tag = tags.at(-1)?.[1];
  if (tag === undefined) throw new Error(`${guide}:${line}: no <physical-canvas ...> before it`);
  return `${tag}</physical-canvas>`;
}

/** Writes a file unless it already holds `text` (each test worker writes the same pages). */
function write(file: URL, text: string): void {
  if (existsSync(file) && readFileSync(file, 'utf8') === text) return;
  writeFileSync(file, text);
}

/** Writes the pages (and the files they import) and lists them. */
export function writeGuidePages(): GuidePage[] {
  mkdirSync(generated, { recursive: true });
  const pages: GuidePage[] = [];
  for (const snippet of guideSnippets()) {
    if (!snippet.browser) continue;
    const file = /^\/\/ ([\w.-]+\.tsx?)\n/.exec(snippet.code)?.[1];
    if (file !== undefined) {
      write(new URL(file, generated), snippet.code);
      continue;
    }
    const isComponent = /^export function \w+/m.test(snippet.code);
    if (!isComponent && !/\.world = world/.test(snippet.code)) continue;
    const base = `${snippet.guide.replace(/\.md$/, '')}-${snippet.line}`;
    const module = `${base}.${snippet.language}`;
    write(new URL(module, generated), snippet.code);
    let body: string;
    if (isComponent) {
      write(
        new URL(`${base}.main.tsx`, generated),
        [
          `import { createRoot } from 'react-dom/client';`,
          `import * as guide from './${module}';`,
          `const [Component] = Object.values(guide) as (() => React.JSX.Element)[];`,
          `createRoot(document.getElementById('root')!).render(<Component />);`,
        ].join('\n'),
      );
      body = `<div id="root"></div>\n<script type="module" src="./${base}.main.tsx"></script>`;
    } else {
      body = `${elementBefore(snippet.guide, snippet.line)}\n<script type="module" src="./${module}"></script>`;
    }
    write(
      new URL(`${base}.html`, generated),
      [
        '<!doctype html>',
        '<html lang="en">',
        '<meta charset="utf-8" />',
        '<meta name="viewport" content="width=device-width, initial-scale=1" />',
        `<title>${snippet.guide}:${snippet.line}</title>`,
        '<body style="margin: 0">',
        body,
        `<script type="module">document.documentElement.dataset.ready = 'true';</script>`,
        '</body>',
        '</html>',
      ].join('\n'),
    );
    pages.push({
      name: `${snippet.guide}:${snippet.line}`,
      path: `/guides/generated/${base}.html`,
    });
  }
  return pages;
}
