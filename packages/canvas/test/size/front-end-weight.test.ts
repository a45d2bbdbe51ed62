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
// either from growing. The worker page fell from 81.2 to 41.2 KB when it stopped keeping a whole
// World as its copy (it checks input with the engine's `check*` functions instead); what is left
// over the budget is the engine's Body and joint classes its copies are built from (their solver
// methods included); the Body handle over the body memory (issue #30) made it 42.3 KB. Lower a
// ceiling whenever a change makes room.
const CANVAS_CEILING_BYTES = 13.9 * 1024;
const WORKER_PAGE_CEILING_BYTES = 42.8 * 1024;

/** Modules of the step a worker world's page must not ship: the worker runs them. */
const SOLVER_MODULES = [
  'engine/src/world/world.ts',
  'engine/src/dynamics/solver.ts',
  'engine/src/dynamics/contact-manager.ts',
  'engine/src/dynamics/contact-kernel-binary.ts',
  'engine/src/dynamics/contact-kernel-javascript.ts',
  'engine/src/collision/broad-phase.ts',
];

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

  it("ships no World, solver, contacts or broad phase in a worker world's page", async () => {
    const { engine, workerPage } = await measureFrontEnd();
    // The engine's own app bundles every one of them: the list names real modules.
    for (const module of SOLVER_MODULES) expect(engine.modules).toContain(module);
    for (const module of SOLVER_MODULES) expect(workerPage.modules).not.toContain(module);
  }, 60_000);
});
