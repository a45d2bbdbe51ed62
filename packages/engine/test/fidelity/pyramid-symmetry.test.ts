import { describe, expect, it } from 'vitest';
import { Body, World, box } from '@physical/engine';
import { reportMeasured } from './measured.ts';

// A tall pyramid compresses under its own weight (soft contacts), but it must not lean: the
// solver's sweep order once pushed every row the same way and a 40-row pyramid's flank slid
// 4.6 cm in 200 steps (a 100-row one, 0.57 m). Without sleep, so the solver works every step.

const TOLERANCE = 0.03; // m: three hundredths of a box

describe('pyramid symmetry', () => {
  it('a 40-row pyramid compresses without leaning: no box moves sideways more than 3 cm', () => {
    const world = new World({ gravity: { x: 0, y: 10 }, enableSleep: false });
    world.add(
      new Body({
        type: 'static',
        position: { x: 0, y: 1 },
        shapes: [{ type: 'box', width: 80, height: 2 }],
      }),
    );
    const boxes: { body: Body; x: number }[] = [];
    for (let row = 0; row < 40; row++) {
      const n = 40 - row;
      for (let i = 0; i < n; i++) {
        const x = i - (n - 1) / 2;
        boxes.push({
          body: world.add(box({ position: { x, y: -0.5 - row }, width: 1, height: 1 })),
          x,
        });
      }
    }
    let worst = 0;
    for (let step = 0; step < 200; step++) {
      world.step(1 / 60);
      for (const { body, x } of boxes) worst = Math.max(worst, Math.abs(body.position.x - x));
    }
    reportMeasured('11 40-row pyramid, largest sideways movement (m)', worst, TOLERANCE);
    expect(worst).toBeLessThan(TOLERANCE);
  }, 30_000);
});
