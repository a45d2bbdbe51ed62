import assert from 'node:assert/strict';
import { test } from '../harness.ts';
import {
  SMALL_LANDSCAPE,
  SMALL_PHONE,
  assertClosedForm,
  labValue,
  openTab,
  results,
  runUntilCollided,
  setElasticity,
  typeLab,
} from './lab.ts';
import { assertQuiet, closeApp, numberIn, openApp, readout, screenshot } from './phone.ts';

for (const [kind, e, key] of [
  ['elastic', 1, 'End'],
  ['perfectly inelastic', 0, 'Home'],
] as const) {
  test(`newton: collision lab at 375x667, a ${kind} collision: the before and after totals match the closed form to 1e-3`, async ({
    browser,
  }) => {
    const app = await openApp(browser, '#reactions', SMALL_PHONE);
    const { page } = app;
    try {
      // Set up two particles and type their masses and velocities, as a student would.
      await openTab(page, 'setup');
      await page.locator('#reactions [data-action="lab-setup"]').click();
      await typeLab(page, 'A-mass', '1');
      await typeLab(page, 'A-vx', '2');
      await typeLab(page, 'B-mass', '2');
      await typeLab(page, 'B-vx', '-0.5');
      assert.equal(await labValue(page, 'B-vx'), -0.5);
      // Walls and the tilt off: nothing but the collision changes the momentum.
      await openTab(page, 'options');
      await page.locator('#reactions [data-control="walls"]').uncheck();
      await page.locator('#reactions [data-control="tilt"]').uncheck();
      await setElasticity(page, key);
      assert.match(
        (await page.locator('#reactions-elasticity-label').textContent())!,
        e === 1 ? /100 %/ : /: 0 %/,
      );
      await runUntilCollided(page);
      const shown = await results(page);
      assertClosedForm(shown, 1, 2, 2, -0.5, e);
      // The tray's summary says the same: total momentum before → after.
      await openTab(page, 'tray');
      const [before, after] = (await readout(page, 'momentum')).split('→').map(numberIn);
      assert.ok(Math.abs(before! - 1) <= 0.005 && Math.abs(after! - 1) <= 0.005);
      await openTab(page, 'results');
      await screenshot(page, `lab-${e === 1 ? 'elastic' : 'inelastic'}-375x667`);
      assertQuiet(app);
    } finally {
      await closeApp(app);
    }
  });
}

test('newton: collision lab in landscape, a wall bounce before the collision stays out of its record', async ({
  browser,
}) => {
  // Walls on: A runs left into the wall, comes back at 3 m/s and hits B at rest. The wall's
  // impulse (6 N s) is not the collision's: before is A at +3 m/s, not -3 m/s.
  const app = await openApp(
    browser,
    '#reactions?mA=1&mB=1&vA=-3&vB=0&e=1&walls=1&tilt=0',
    SMALL_LANDSCAPE,
  );
  const { page } = app;
  try {
    await runUntilCollided(page, 0);
    // Equal masses, elastic: A stops, B takes its velocity. On a busy machine the next
    // collision may come first (B back from the right wall into A at rest): the same law.
    const shown = await results(page);
    if (Math.abs(shown['px-before-A']!) < 1e-3) assertClosedForm(shown, 1, 1, 0, -3, 1);
    else assertClosedForm(shown, 1, 1, 3, 0, 1);
    await screenshot(page, 'lab-walls-667x375');
    assertQuiet(app);
  } finally {
    await closeApp(app);
  }
});

test('newton: collision lab, dragging a velocity arrow sets the velocity', async ({ browser }) => {
  const app = await openApp(browser, '#reactions?mA=1&mB=2&vA=1&vB=0&tilt=0', SMALL_PHONE);
  const { page } = app;
  try {
    const canvas = page.locator('#reactions physical-canvas');
    const box = (await canvas.boundingBox())!;
    // A's handle: the tip of its velocity arrow, and a point 1 m further right.
    const points = await canvas.evaluate((element) => {
      const host = element as unknown as {
        world: {
          bodies: {
            type: string;
            position: { x: number; y: number };
            linearVelocity: { x: number; y: number };
            shapes: { geometry: { radius: number } }[];
          }[];
        };
        worldToScreen(point: { x: number; y: number }): { x: number; y: number };
      };
      const a = host.world.bodies.find((body) => body.type === 'dynamic')!;
      const radius = a.shapes[0]!.geometry.radius;
      const tip = { x: a.position.x + radius + a.linearVelocity.x * 0.5, y: a.position.y };
      return {
        from: host.worldToScreen(tip),
        to: host.worldToScreen({ x: tip.x + 1, y: tip.y }),
      };
    });
    await page.mouse.move(box.x + points.from.x, box.y + points.from.y);
    await page.mouse.down();
    await page.mouse.move(box.x + points.to.x, box.y + points.to.y, { steps: 8 });
    await page.mouse.up();
    // 1 m more arrow at 0.5 m per m/s: 2 m/s more, set in the Lab table too.
    await openTab(page, 'setup');
    assert.ok(Math.abs((await labValue(page, 'A-vx')) - 3) <= 0.1, 'vx of A after the drag');
    assert.ok(Math.abs(await labValue(page, 'A-vy')) <= 0.1, 'a level drag sets no vy');
    // The drag added no particle (it was not a tap on the background).
    await openTab(page, 'tray');
    assert.equal(await readout(page, 'count'), '2');
    assertQuiet(app);
  } finally {
    await closeApp(app);
  }
});

test('newton: collision lab by keyboard: particles are chosen and given a velocity, the description is live', async ({
  browser,
}) => {
  const app = await openApp(browser, '#reactions', SMALL_PHONE);
  const { page } = app;
  try {
    const description = page.locator('#reactions-description');
    assert.equal(await description.getAttribute('aria-live'), 'polite');
    assert.equal(
      await page.locator('#reactions physical-canvas').getAttribute('aria-describedby'),
      'reactions-description',
    );
    await page.locator('#reactions [data-action="play"]').focus();
    await page.keyboard.press('Enter'); // pause
    const add = page.locator('#reactions [data-action="add"]');
    await add.focus();
    await page.keyboard.press('Enter');
    await page.keyboard.press('Enter');
    // To the Lab tab with the keyboard: arrows move between tabs, Enter opens one.
    await page.locator('#reactions [data-tab="tray"]').focus();
    await page.keyboard.press('ArrowRight');
    await page.keyboard.press('Enter');
    await page.locator('#reactions [data-tab="setup"][aria-selected="true"]').waitFor();
    const choose = page.locator('#reactions [data-action="choose"]');
    await choose.focus();
    await page.keyboard.press('Enter');
    await page.keyboard.press('Enter');
    await page.locator('#reactions [data-lab-input="B-vx"]').waitFor();
    await page.waitForFunction(() =>
      /A: .*B: /.test(document.querySelector('#reactions-description')!.textContent ?? ''),
    );
    // Type A's velocity.
    await page.locator('#reactions [data-lab-input="A-vx"]').focus();
    await page.keyboard.press('ControlOrMeta+a');
    await page.keyboard.type('1.5');
    await page.keyboard.press('Enter');
    await page.waitForFunction(() =>
      /A: .*velocity 1\.5\s*m\/s right/.test(
        document.querySelector('#reactions-description')!.textContent ?? '',
      ),
    );
    // A typo is refused, not applied.
    await page.locator('#reactions [data-lab-input="B-vx"]').fill('abc');
    await page.keyboard.press('Enter');
    assert.equal(
      await page.locator('#reactions [data-lab-input="B-vx"]').getAttribute('aria-invalid'),
      'true',
    );
    await screenshot(page, 'lab-keyboard-375x667');
    assertQuiet(app);
  } finally {
    await closeApp(app);
  }
});
