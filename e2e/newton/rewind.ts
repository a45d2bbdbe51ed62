// Helpers of the step-back, scrub and CSV browser tests on Inertia and Forces: readouts read
// together, the rewind slider moved by keyboard, the CSV downloaded and parsed.
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import type { Page } from 'playwright-core';
import { numberIn } from './phone.ts';

/** Readouts of a screen read in one go (one render shows them all), as their texts. */
export async function readouts(
  page: Page,
  screen: string,
  names: readonly string[],
): Promise<Record<string, string>> {
  const texts = await page.evaluate(
    ([scope, list]) =>
      list.map((name) =>
        (document.querySelector(`#${scope} [data-readout="${name}"]`)?.textContent ?? '')
          .replace(/\u00a0/g, ' ')
          .trim(),
      ),
    [screen, names] as const,
  );
  return Object.fromEntries(names.map((name, index) => [name, texts[index]!]));
}

/** The simulated time a readout set shows (s). */
export function timeOf(shown: Record<string, string>): number {
  return numberIn(shown['time']!);
}

/**
 * Scrubs with the keyboard, as a learner without a mouse does: focus the rewind slider, Home to
 * the oldest saved moment, then PageUp (10 steps) and ArrowRight (1 step) up to `steps` steps
 * after it.
 */
export async function scrubTo(page: Page, screen: string, steps: number): Promise<void> {
  const thumb = page.locator(`#${screen} [data-control="rewind"] input`);
  await thumb.focus();
  await page.keyboard.press('Home');
  for (let i = 0; i < Math.floor(steps / 10); i++) await page.keyboard.press('PageUp');
  for (let i = 0; i < steps % 10; i++) await page.keyboard.press('ArrowRight');
}

/** A CSV as a student's script reads it: the header's names and the rows' numbers. */
export interface Csv {
  readonly text: string;
  readonly columns: readonly string[];
  readonly rows: readonly (readonly number[])[];
  /** The value in `row` of the column named `name` (NaN for an empty cell). */
  at(row: readonly number[], name: string): number;
}

export function parseCsv(text: string): Csv {
  assert.ok(text.endsWith('\r\n'), 'CSV lines end in CR LF');
  const [header, ...lines] = text.trim().split('\r\n');
  const columns = header!.split(',');
  const rows = lines.map((line) => line.split(',').map((cell) => (cell === '' ? NaN : +cell)));
  return {
    text,
    columns,
    rows,
    at: (row, name) => {
      const index = columns.indexOf(name);
      assert.ok(index >= 0, `column "${name}" in ${header}`);
      return row[index]!;
    },
  };
}

/** Downloads the screen's CSV with its button and parses it; checks the file's name. */
export async function downloadCsv(page: Page, screen: string): Promise<Csv> {
  const [download] = await Promise.all([
    page.waitForEvent('download'),
    page.locator(`#${screen} [data-action="download-csv"]`).tap(),
  ]);
  assert.equal(download.suggestedFilename(), `newton-${screen}.csv`);
  return parseCsv(readFileSync((await download.path())!, 'utf8'));
}

/**
 * The rows are one history: times from 0 in steps of 1/60 s, none missing or repeated (a
 * stepped-back future is gone), up to `until` (s) as the time readout shows it.
 */
export function assertOneHistory(csv: Csv, until: number): void {
  csv.rows.forEach((row, index) => {
    assert.ok(
      Math.abs(row[0]! - index / 60) < 1e-6,
      `row ${index} is at t = ${index}/60 s, not ${row[0]} s`,
    );
  });
  const last = csv.rows[csv.rows.length - 1]![0]!;
  assert.ok(
    Math.abs(last - until) <= 0.005,
    `the last row (${last} s) is the time shown (${until})`,
  );
}

/** The CSV row at the time a readout shows (to its 2 decimals: one step is 0.0167 s). */
export function rowAt(csv: Csv, time: number): readonly number[] {
  const row = csv.rows.find((item) => Math.abs(item[0]! - time) <= 0.005);
  assert.ok(row !== undefined, `a row at t = ${time} s`);
  return row;
}
