import assert from 'node:assert/strict';
import type { PhysicalUI } from '@physical/dom';
import { test } from '../harness.ts';
import { waitFrames } from '../canvas/page-helpers.ts';

interface Fixture {
  state: { clicks: number; ready: boolean[]; ui: PhysicalUI | null };
  addChip(name: string): void;
  removeChip(name: string): void;
  unmount(): void;
}

const name =
  'react: <PhysicalContainer> under StrictMode makes children physical, follows them, cleans up';
test(name, async ({ open }) => {
  const page = await open('/react/physical-ui.html', { viewport: { width: 400, height: 300 } });
  await waitFrames(page, 3);
  const mounted = await page.evaluate(() => {
    const { state } = window as unknown as Fixture;
    return { count: state.ui!.elements.length, ready: state.ready.at(-1) };
  });
  assert.deepEqual(mounted, { count: 3, ready: true });
  // A click reaches React's handler once.
  await page.click('#counter');
  // Children React adds and removes join and leave the world.
  const followed = await page.evaluate(async () => {
    const fixture = window as unknown as Fixture;
    fixture.addChip('Three');
    await new Promise((resolve) => setTimeout(resolve, 50));
    const added = fixture.state.ui!.elements.map((element) => element.textContent);
    fixture.removeChip('One');
    await new Promise((resolve) => setTimeout(resolve, 50));
    return { added, removed: fixture.state.ui!.elements.map((element) => element.textContent) };
  });
  assert.deepEqual(followed, {
    added: ['Count', 'One', 'Two', 'Three'],
    removed: ['Count', 'Two', 'Three'],
  });
  await page.evaluate(() => (window as unknown as Fixture).state.ui!.release());
  await waitFrames(page, 20);
  const falling = await page.evaluate(() =>
    [...document.querySelectorAll<HTMLElement>('.box button')].map((b) => b.style.transform),
  );
  assert.ok(falling.every((transform) => transform.startsWith('translate(')));
  const ui = await page.evaluateHandle(() => (window as unknown as Fixture).state.ui!);
  await page.evaluate(() => (window as unknown as Fixture).unmount());
  await waitFrames(page, 3);
  const after = await page.evaluate((old) => {
    const { state } = window as unknown as Fixture;
    return {
      clicks: state.clicks,
      ready: state.ready.at(-1),
      bodies: old.world.bodies.length,
      running: old.isRunning,
      container: document.querySelector('.box') === null,
    };
  }, ui);
  assert.deepEqual(after, { clicks: 1, ready: false, bodies: 0, running: false, container: true });
});
