import assert from 'node:assert/strict';
import type { Page } from 'playwright-core';
import { test } from '../harness.ts';
import {
  LANDSCAPE,
  PHONE,
  assertQuiet,
  closeApp,
  numberIn,
  openApp,
  readout,
  screenshot,
} from './phone.ts';
import { fitProblems } from './fit.ts';

const sleep = (ms: number): Promise<void> => new Promise((resolve) => setTimeout(resolve, ms));

type Box = { x: number; y: number; width: number; height: number };
const overlaps = (a: Box, b: Box): boolean =>
  a.x < b.x + b.width && b.x < a.x + a.width && a.y < b.y + b.height && b.y < a.y + a.height;

async function helper(page: Page): Promise<string> {
  return ((await page.locator('[data-helper="square-mass"]').textContent()) ?? '').replace(
    /\u00a0/g,
    ' ',
  );
}

for (const [orientation, options] of [
  ['portrait', PHONE],
  ['landscape', LANDSCAPE],
] as const) {
  test(`newton: forces (${orientation}), typed values are validated, the clock starts at Start, the run ends at the stop, readouts never overlap`, async ({
    browser,
  }) => {
    const app = await openApp(browser, '#forces', options);
    const { page } = app;
    try {
      // Before Start nothing moves and the clock stands at zero.
      await sleep(600);
      assert.equal(await readout(page, 'time', '#forces'), 't = 0.00 s');

      // Typed input: rejected with the reason and the range shown, OK disabled until valid.
      await page.locator('[data-action="edit-A"]').click();
      const dialog = page.getByRole('dialog');
      await dialog.waitFor();
      const ok = dialog.getByRole('button', { name: 'OK' });
      const mass = page.locator('#square-mass');
      for (const [typed, reason] of [
        ['0', /between 0\.5 and 5 kg/],
        // A negative mass is a number out of the range, not "not a number".
        ['-3', /between 0\.5 and 5 kg/],
        ['abc', /Not a number/],
        ['0x10', /Not a number/],
        ['1e9', /Not a number/],
        ['9', /between 0\.5 and 5 kg/],
      ] as const) {
        await mass.fill(typed);
        assert.match(await helper(page), reason, `"${typed}" is refused`);
        assert.equal(await mass.getAttribute('aria-invalid'), 'true');
        assert.equal(await ok.isDisabled(), true, `OK disabled for "${typed}"`);
      }
      await mass.fill('1,5');
      assert.match(await helper(page), /0\.5 to 5 kg/);
      assert.equal(await ok.isDisabled(), false);
      // Stepped entry: + adds 0.1 kg.
      await page.locator('[data-action="square-mass-plus"]').click();
      assert.equal(await mass.inputValue(), '1.6');
      // The force is the learner's to set: 3.2 N on 1.6 kg.
      await page.locator('#square-force').fill('-1');
      assert.match(
        ((await page.locator('[data-helper="square-force"]').textContent()) ?? '').replace(
          /\u00a0/g,
          ' ',
        ),
        /between 0 and 10 N/,
      );
      await page.locator('#square-force').fill('3.2');
      await ok.click();
      await dialog.waitFor({ state: 'detached' });
      assert.equal(await readout(page, 'force-A'), '3.2 N');

      await page.locator('#forces [data-action="start"]').click();
      // A (3.2 N on 1.6 kg, a = 2) reaches the stop after t = sqrt(2 d / a) = sqrt(10.8) = 3.29 s,
      // B (2 N on 2 kg, a = 1) after sqrt(21.6) = 4.65 s.
      await page.waitForFunction(
        () => document.querySelector('#forces [data-action="start"]')!.textContent === 'Run over',
        undefined,
        { timeout: 20_000, polling: 100 },
      );
      const end = numberIn(await readout(page, 'time', '#forces'));
      assert.ok(Math.abs(end - 4.65) < 0.1, `clock timed from Start: ${end} s`);
      await sleep(500);
      assert.equal(numberIn(await readout(page, 'time', '#forces')), end, 'clock stops at the end');
      for (const [name, expected] of [
        ['A', 2],
        ['B', 1],
      ] as const) {
        const a = numberIn(await readout(page, `a-${name}`));
        assert.ok(Math.abs(a - expected) < 1e-3, `measured acceleration of ${name}: ${a}`);
        const chip = (await page.locator(`[data-action="edit-${name}"]`).boundingBox())!;
        const motion = (await page.locator(`[data-readout="motion-${name}"]`).boundingBox())!;
        assert.ok(!overlaps(chip, motion), `${name}: the label chip and the readout overlap`);
      }
      assert.match(
        (await page.locator('[data-announcer="forces"]').textContent())!,
        /reached the stop/,
      );
      // The page does not scroll, and every control can be tapped (graphs scroll in the panel,
      // under nothing).
      assert.deepEqual(await fitProblems(page), []);
      for (const name of ['A', 'B']) {
        const track = (await page
          .locator(`#forces [data-track="${name}"] physical-canvas`)
          .boundingBox())!;
        assert.ok(track.height >= 56, `track ${name} canvas is ${track.height} px tall`);
      }
      await screenshot(page, `forces-finished-${orientation}`);
      assertQuiet(app);
    } finally {
      await closeApp(app);
    }
  });
}

for (const [orientation, options] of [
  ['portrait', PHONE],
  ['landscape', LANDSCAPE],
] as const) {
  test(`newton: forces (${orientation}), a mystery mass for B is found from F / a and checked`, async ({
    browser,
  }) => {
    const app = await openApp(browser, '#forces', options);
    const { page } = app;
    const announced = async (pattern: RegExp): Promise<void> => {
      await page.waitForFunction(
        (source) =>
          new RegExp(source).test(
            document.querySelector('[data-announcer="forces"]')!.textContent!,
          ),
        pattern.source,
        { timeout: 4000, polling: 50 },
      );
    };
    try {
      await page.locator('[data-control="mystery"]').check();
      await announced(/mystery mass/);
      // B's mass is hidden, and B gets A's force (the same-force switch is on and locked).
      assert.equal(await readout(page, 'mass-B'), '? kg');
      const same = page.locator('[data-control="same-force"]');
      assert.equal(await same.isChecked(), true);
      assert.equal(await same.isDisabled(), true);
      assert.equal(await readout(page, 'force-B'), await readout(page, 'force-A'));
      // B cannot be edited: it says why instead of opening the dialog.
      await page.locator('[data-action="edit-B"]').click();
      await announced(/mass is the mystery/);
      assert.equal(await page.getByRole('dialog').count(), 0);

      // A wrong guess is refused with the way to find it.
      const guess = page.locator('#mystery-guess');
      const check = page.locator('[data-action="check-mystery"]');
      await guess.fill('abc');
      assert.equal(await check.isDisabled(), true, 'Check disabled for "abc"');
      await guess.fill('5');
      await check.click();
      // Mystery masses lie between 1 and 4 kg: 5 kg is always wrong.
      await announced(/Not 5/);

      // The experiment: run, read B's force and measured acceleration, type m = F / a.
      await page.locator('#forces [data-action="start"]').click();
      await page.waitForFunction(
        () => document.querySelector('#forces [data-action="start"]')!.textContent === 'Run over',
        undefined,
        { timeout: 15_000, polling: 100 },
      );
      const force = numberIn(await readout(page, 'force-B'));
      const acceleration = numberIn(await readout(page, 'a-B'));
      const answer = Math.round((100 * force) / acceleration) / 100;
      await page.locator('#mystery-guess').fill(String(answer));
      await page.locator('[data-action="check-mystery"]').click();
      await announced(/Right: B's mass is/);
      // Found: the mass is shown, and it is the one the measurement gave (within 5 %).
      const revealed = numberIn(await readout(page, 'mystery-result'));
      assert.ok(
        Math.abs(revealed - answer) <= 0.05 * revealed,
        `F / a = ${answer} kg, mass ${revealed} kg`,
      );
      assert.equal(numberIn(await readout(page, 'mass-B')), revealed);
      await screenshot(page, `forces-mystery-${orientation}`);
      assertQuiet(app);
    } finally {
      await closeApp(app);
    }
  });
}
