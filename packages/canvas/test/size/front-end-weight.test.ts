import { describe, expect, it } from 'vitest';
import {
  CANVAS_BUDGET_BYTES,
  WORKER_PAGE_BUDGET_BYTES,
  frontEndLines,
  measureFrontEnd,
} from '../../../../bench/src/size.ts';

// The weight of <physical-canvas> beyond the engine and of a worker world's page, as
// bench/src/size.ts measures and prints them. The budgets (10 KB and 30 KB, issue #33) are not
// met yet: until they are, these ceilings (the figures of 2026-11-27 plus half a kilobyte) stop
// either from growing. The worker page went from 75.9 to 81.2 KB when the page began checking
// every call with the engine's own rules (#31) while it still keeps a whole World as its copy;
// dropping that copy is what makes room. Lower a ceiling whenever a change makes room.
const CANVAS_CEILING_BYTES = 13.9 * 1024;
const WORKER_PAGE_CEILING_BYTES = 81.7 * 1024;

describe('front-end weight', () => {
  it('stays within its ceilings, and reports its budgets', async () => {
    const sizes = await measureFrontEnd();
    const lines = frontEndLines(sizes);
    expect(lines.join('\n')).toContain('budget 10.0 KB');
    expect(lines.join('\n')).toContain('budget 30.0 KB');
    const added = sizes.engineWithCanvas.gzippedBytes - sizes.engine.gzippedBytes;
    expect(added).toBeGreaterThan(0);
    expect(added).toBeLessThanOrEqual(Math.max(CANVAS_BUDGET_BYTES, CANVAS_CEILING_BYTES));
    expect(sizes.workerPage.gzippedBytes).toBeLessThanOrEqual(
      Math.max(WORKER_PAGE_BUDGET_BYTES, WORKER_PAGE_CEILING_BYTES),
    );
  }, 60_000);
});
