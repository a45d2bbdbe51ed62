// Helpers of the collision lab's browser tests: the Reactions panel's tabs, fields and results
// as a student reaches them.
import assert from 'node:assert/strict';
import type { BrowserContextOptions, Page } from 'playwright-core';
import { PHONE, numberIn, readout } from './phone.ts';

const sleep = (ms: number): Promise<void> => new Promise((resolve) => setTimeout(resolve, ms));

/** A small phone (iPhone SE, 8): 375 x 667, portrait. */
export const SMALL_PHONE: BrowserContextOptions = {
  ...PHONE,
  viewport: { width: 375, height: 667 },
  deviceScaleFactor: 2,
};

/** The same small phone turned sideways. */
export const SMALL_LANDSCAPE: BrowserContextOptions = {
  ...SMALL_PHONE,
  viewport: { width: 667, height: 375 },
};

/** Opens a tab of the Reactions panel (Tray, Lab, Results, Options, Data). */
export async function openTab(
  page: Page,
  tab: 'tray' | 'setup' | 'results' | 'options' | 'data',
): Promise<void> {
  await page.locator(`#reactions [data-tab="${tab}"]`).click();
  await page.locator(`#reactions [data-tab="${tab}"][aria-selected="true"]`).waitFor();
}

/** Types `value` into a field of the Lab table (e.g. `A-vx`) and presses Enter. */
export async function typeLab(page: Page, field: string, value: string): Promise<void> {
  const input = page.locator(`#reactions [data-lab-input="${field}"]`);
  await input.fill(value);
  await input.press('Enter');
}

/** The value a Lab table field shows. */
export async function labValue(page: Page, field: string): Promise<number> {
  return numberIn(await page.locator(`#reactions [data-lab-input="${field}"]`).inputValue());
}

/** Sets the elasticity slider (Options tab open) to 0 % (Home) or 100 % (End) by keyboard. */
export async function setElasticity(page: Page, key: 'Home' | 'End'): Promise<void> {
  const thumb = page.locator('#reactions [data-control="elasticity"] input');
  await thumb.focus();
  await page.keyboard.press(key);
}

/** Presses Play and waits until the Results tab shows the pair's collision, then pauses. */
export async function runUntilCollided(page: Page, settle = 500): Promise<void> {
  await openTab(page, 'results');
  await page.locator('#reactions [data-action="play"]').click();
  await page.locator('#reactions [data-readout="lab-px-after-total"]').waitFor({ timeout: 15_000 });
  // An inelastic pair pushes over a few steps: let the collision finish.
  await sleep(settle);
  await page.locator('#reactions [data-action="play"]').click();
}

/** The Results table: each cell's shown number, by row and column (`px-after`, `total`). */
export async function results(page: Page): Promise<Record<string, number>> {
  const values: Record<string, number> = {};
  for (const row of ['px-before', 'px-after', 'ke-before', 'ke-after']) {
    for (const column of ['A', 'B', 'total']) {
      values[`${row}-${column}`] = numberIn(await readout(page, `lab-${row}-${column}`));
    }
  }
  return values;
}

/** The closed form of a 1-D collision with restitution e: velocities after. */
export function closedForm(
  m1: number,
  m2: number,
  u1: number,
  u2: number,
  e: number,
): { v1: number; v2: number } {
  const p = m1 * u1 + m2 * u2;
  return {
    v1: (p - m2 * e * (u1 - u2)) / (m1 + m2),
    v2: (p + m1 * e * (u1 - u2)) / (m1 + m2),
  };
}

/**
 * Checks the Results table against the closed form of a head-on collision of m1 at u1 with
 * m2 at u2 (restitution e) to 1e-3: each momentum and energy before and after, and the totals.
 */
export function assertClosedForm(
  shown: Record<string, number>,
  m1: number,
  m2: number,
  u1: number,
  u2: number,
  e: number,
): void {
  const { v1, v2 } = closedForm(m1, m2, u1, u2, e);
  const expected: Record<string, number> = {
    'px-before-A': m1 * u1,
    'px-before-B': m2 * u2,
    'px-before-total': m1 * u1 + m2 * u2,
    'px-after-A': m1 * v1,
    'px-after-B': m2 * v2,
    'px-after-total': m1 * v1 + m2 * v2,
    'ke-before-A': 0.5 * m1 * u1 * u1,
    'ke-before-B': 0.5 * m2 * u2 * u2,
    'ke-before-total': 0.5 * m1 * u1 * u1 + 0.5 * m2 * u2 * u2,
    'ke-after-A': 0.5 * m1 * v1 * v1,
    'ke-after-B': 0.5 * m2 * v2 * v2,
    'ke-after-total': 0.5 * m1 * v1 * v1 + 0.5 * m2 * v2 * v2,
  };
  for (const [name, value] of Object.entries(expected)) {
    assert.ok(
      Math.abs(shown[name]! - value) <= 1e-3,
      `${name}: shown ${shown[name]}, closed form ${value.toFixed(4)}`,
    );
  }
  // Momentum kept; kinetic energy kept for e = 1 only.
  assert.ok(Math.abs(shown['px-after-total']! - shown['px-before-total']!) <= 1e-3);
  if (e === 1) assert.ok(Math.abs(shown['ke-after-total']! - shown['ke-before-total']!) <= 1e-3);
  else assert.ok(shown['ke-after-total']! < shown['ke-before-total']! - 0.01);
}
