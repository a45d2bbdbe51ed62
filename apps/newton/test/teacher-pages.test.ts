import { describe, expect, it } from 'vitest';
import { renderTeacherPage, teacherPages } from '../scripts/teacher-pages.ts';

/** The page's tags in order, with the attributes that name a language or a page left out. */
function tags(page: string): string[] {
  return (page.match(/<[^>]+>/g) ?? []).map((tag) =>
    tag.replace(/\s(lang|hreflang|href|data-language)="[^"]*"/g, ''),
  );
}

describe('teacher pages', () => {
  it('makes the English and German pages from one template: the same markup, each in its language, each linking the other', () => {
    const pages = teacherPages();
    const en = pages.get('teacher.html')!;
    const de = pages.get('teacher.de.html')!;
    expect(tags(de)).toEqual(tags(en));
    expect(en).toMatch(/^<!doctype html>\n<html lang="en">/);
    expect(de).toMatch(/^<!doctype html>\n<html lang="de">/);
    expect(en).toContain('<link rel="alternate" hreflang="de" href="./teacher.de.html" />');
    expect(de).toContain('<link rel="alternate" hreflang="en" href="./teacher.html" />');
    expect(en).toContain('<title>Newton · For teachers</title>');
    expect(de).toContain('<title>Newton · Für Lehrkräfte</title>');
    expect(en).not.toContain('{{');
    expect(de).not.toContain('{{');
  });

  it('refuses a placeholder without a string, and a string the template does not use', () => {
    const template = '<html lang="{{lang}}"><p>{{a}}</p></html>';
    expect(renderTeacherPage(template, { a: 'x' }, 'en')).toBe('<html lang="en"><p>x</p></html>');
    expect(() => renderTeacherPage(template, {}, 'en')).toThrow(/no string for \{\{a\}\}/);
    expect(() => renderTeacherPage(template, { a: 'x', b: 'y' }, 'de')).toThrow(/does not use: b/);
  });
});
