import assert from 'node:assert/strict';
import { test } from '../harness.ts';
import { COUNT_LAYOUT_READS } from './layout-reads.ts';

test('dom: 200 falling elements: no layout read inside a frame, and no layout at all', async ({
  open,
}) => {
  const page = await open(
    '/dom/fixture.html',
    { viewport: { width: 800, height: 600 } },
    COUNT_LAYOUT_READS,
  );
  await page.evaluate(() => {
    const { PhysicalUI, fill } = window.dom;
    const box = fill(200);
    const ui = new PhysicalUI(box, { released: true });
    Object.assign(window, { ui });
  });
  const session = await page.context().newCDPSession(page);
  await session.send('Performance.enable');
  const metrics = async () => {
    const { metrics } = await session.send('Performance.getMetrics');
    const value = (name: string) => metrics.find((entry) => entry.name === name)!.value;
    return { layouts: value('LayoutCount'), styles: value('RecalcStyleCount') };
  };
  // Let start-up (measuring, the first ResizeObserver round) pass, then watch 60 frames.
  const frames = () =>
    page.evaluate(() => (window as unknown as { frameCallbacks: number }).frameCallbacks);
  await page.waitForFunction(
    () => (window as unknown as { frameCallbacks: number }).frameCallbacks > 5,
  );
  const start = await metrics();
  const frames0 = await frames();
  await page.waitForFunction(
    (first) => (window as unknown as { frameCallbacks: number }).frameCallbacks >= first + 60,
    frames0,
    { timeout: 20_000 },
  );
  const end = await metrics();
  const result = await page.evaluate(() => {
    const counts = window as unknown as {
      layoutReads: number;
      layoutReadNames: string[];
      frameCallbacks: number;
    };
    return {
      reads: counts.layoutReads,
      names: [...new Set(counts.layoutReadNames)],
      frames: counts.frameCallbacks,
      running: (window as unknown as { ui: { isRunning: boolean } }).ui.isRunning,
      moved: [...document.querySelectorAll<HTMLElement>('#box > *')].filter(
        (e) => e.style.transform !== '',
      ).length,
    };
  });
  assert.equal(result.moved, 200);
  assert.deepEqual([result.reads, result.names], [0, []]);
  // Transforms alone never lay out: the frames restyled but did not lay out once.
  assert.ok(end.styles > start.styles, 'the frames restyled');
  assert.equal(end.layouts - start.layouts, 0);
});
