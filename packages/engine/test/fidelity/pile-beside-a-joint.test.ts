import { describe, expect, it } from 'vitest';
import { World, box, particle, revoluteJoint, wall, type Body } from '@physical/engine';
import '@physical/engine/javascript-kernel';

// A joint anywhere in a world must not change how a pile apart from it bears its load. With an
// active joint, a relax pass that bounced asks whether it bounced once (a lone bounce is solved
// together with the joints); asking used to open every bounce, so the impact rounds skipped
// them, and a particle under 8 rows of a bouncy pile, far from a hinge, went through the floor
// (at step 179 of 240, 0.09 m below it). Law: every body of the pile rests above the floor
// (its centre at least 0.15 m above it: the particles' radius is 0.2 m, the boxes' half
// height 0.175 m), in both builds of the kernel, with and without the hinges.

/** The pile of e2e/engine/pile.ts (160 boxes and e = 0.3 particles in a bin), 240 steps. */
function pileLowestCentre(kernel: 'auto' | 'javascript', hinges: boolean): number {
  const world = new World({ gravity: { x: 0, y: 9.81 }, kernel });
  world.add(wall({ from: { x: -6, y: 0 }, to: { x: 6, y: 0 } }));
  world.add(wall({ from: { x: -6, y: 0 }, to: { x: -6, y: -30 } }));
  world.add(wall({ from: { x: 6, y: 0 }, to: { x: 6, y: -30 } }));
  const pile: Body[] = [];
  for (let i = 0; i < 160; i++) {
    const position = { x: -5 + (i % 20) * 0.5, y: -1 - Math.floor(i / 20) * 0.6 };
    pile.push(
      world.add(
        i % 4 === 0
          ? particle({ position, radius: 0.2, restitution: 0.3 })
          : box({ position, angle: 0.05 * (i % 7), width: 0.4, height: 0.35, friction: 0.6 }),
      ),
    );
  }
  if (hinges) {
    // A chain of three links on hinges, 4 m right of the bin: it never touches the pile.
    let anchor = world.add(
      box({ type: 'static', position: { x: 10, y: -8 }, width: 0.2, height: 0.2 }),
    );
    for (let k = 0; k < 3; k++) {
      const link = world.add(box({ position: { x: 10.5 + k, y: -8 }, width: 1, height: 0.2 }));
      world.addJoint(revoluteJoint({ bodyA: anchor, bodyB: link, anchor: { x: 10 + k, y: -8 } }));
      anchor = link;
    }
  }
  let lowest = -Infinity;
  for (let step = 0; step < 240; step++) {
    world.step(1 / 60);
    for (const body of pile) lowest = Math.max(lowest, body.position.y);
  }
  return lowest;
}

describe('a pile beside a joint', () => {
  it.each([
    ['WebAssembly', 'auto'],
    ['JavaScript', 'javascript'],
  ] as const)('rests on the floor with hinges elsewhere in the world (%s kernel)', (_, kernel) => {
    // y grows downwards here: the largest centre y is the lowest body.
    expect(pileLowestCentre(kernel, true)).toBeLessThan(-0.15);
    expect(pileLowestCentre(kernel, false)).toBeLessThan(-0.15);
  });
});
