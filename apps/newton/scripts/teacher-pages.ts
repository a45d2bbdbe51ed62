// The teacher kit's pages, made at build time from one template (apps/newton/teacher/
// template.html: the markup, with a {{key}} where a language's text goes) and one file of strings
// per language (teacher/en.json, teacher/de.json). A change to the page's structure is made once;
// a translation cannot drift from it. The app's own messages (src/i18n) are not used: the teacher
// pages' prose would weigh on every learner's first load.
import { readFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import type { Plugin } from 'vite';

/** The pages, one per language, at the paths the app links to (`app.teacherPage`). */
export const TEACHER_PAGES = [
  { lang: 'en', file: 'teacher.html' },
  { lang: 'de', file: 'teacher.de.html' },
] as const;

const folder = (name: string): string =>
  fileURLToPath(new URL(`../teacher/${name}`, import.meta.url));

/**
 * The page in `lang`: every `{{key}}` of `template` replaced by its string, and `{{lang}}`,
 * `{{otherLang}}` and `{{otherPage}}` (the other language's page, for `hreflang`). Throws on a
 * key without a string and on a string the template does not use.
 */
export function renderTeacherPage(
  template: string,
  strings: Readonly<Record<string, string>>,
  lang: string,
): string {
  const other = TEACHER_PAGES.find((page) => page.lang !== lang)!;
  const values: Record<string, string> = {
    ...strings,
    lang,
    otherLang: other.lang,
    otherPage: `./${other.file}`,
  };
  const used = new Set<string>();
  const page = template.replace(/\{\{([\w.]+)\}\}/g, (_match, key: string) => {
    const value = values[key];
    if (value === undefined) throw new Error(`teacher page (${lang}): no string for {{${key}}}`);
    used.add(key);
    return value;
  });
  const unused = Object.keys(strings).filter((key) => !used.has(key));
  if (unused.length > 0) {
    throw new Error(`teacher page (${lang}): strings the template does not use: ${unused}`);
  }
  return page;
}

/** Every teacher page, by file name, from the template and strings on disk. */
export function teacherPages(): Map<string, string> {
  const template = readFileSync(folder('template.html'), 'utf8');
  return new Map(
    TEACHER_PAGES.map(({ lang, file }) => {
      const strings = JSON.parse(readFileSync(folder(`${lang}.json`), 'utf8')) as Record<
        string,
        string
      >;
      return [file, renderTeacherPage(template, strings, lang)];
    }),
  );
}

/**
 * Vite: emits the teacher pages into the build (before the precache manifest lists the bundle,
 * so the service worker keeps them offline), and serves them in `vite` dev.
 */
export function teacherPagesPlugin(): Plugin {
  return {
    name: 'newton-teacher-pages',
    generateBundle() {
      for (const [fileName, source] of teacherPages()) {
        this.emitFile({ type: 'asset', fileName, source });
      }
    },
    configureServer(server) {
      server.middlewares.use((request, response, next) => {
        const file = (request.url ?? '').split('?')[0]!.replace(/^.*\//, '');
        const page = teacherPages().get(file);
        if (page === undefined) return next();
        response.setHeader('Content-Type', 'text/html; charset=utf-8');
        response.end(page);
      });
    },
  };
}
