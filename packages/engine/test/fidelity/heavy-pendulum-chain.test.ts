import { describe, expect, it } from 'vitest';
import { reportMeasured } from './measured.ts';
import {
  World,
  box,
  particle,
  restoreSnapshot,
  revoluteJoint,
  takeSnapshot,
} from '@physical/engine';
import type { Body, RevoluteJoint } from '@physical/engine';

// Law: a heavy bob on a chain of light hinged links holds. Four 1 kg links of 0.5 m hang from a
// fixed hinge with a bob at the end, default world, 60 Hz. Hanging at rest, the chain does not
// stretch and each hinge carries the weight below it (the exact chain solve,
// dynamics/joints/pin-chains.ts; on sequential impulses alone a 1000 kg bob stretched it 1.3 m).
// Released from the horizontal, the bob never moves faster than a free fall from its height
// (no energy is made) and the chain keeps its length, up to 10,000:1.

const DT = 1 / 60;
const LINKS = 4;
const LENGTH = 0.5;

function chain(
  ratio: number,
  horizontal: boolean,
  links = LINKS,
  length = LENGTH,
): { world: World; bob: Body; hinges: RevoluteJoint[] } {
  const world = new World({ enableSleep: false });
  const ceiling = world.add(
    box({ type: 'static', position: { x: 0, y: -0.1 }, width: 0.2, height: 0.2 }),
  );
  const hinges: RevoluteJoint[] = [];
  let previous: Body = ceiling;
  const along = (d: number): { x: number; y: number } =>
    horizontal ? { x: d, y: 0 } : { x: 0, y: d };
  for (let k = 0; k < links; k++) {
    const link = world.add(
      box({
        position: along((k + 0.5) * length),
        width: horizontal ? length : 0.05,
        height: horizontal ? 0.05 : length,
        density: 1 / (length * 0.05),
      }),
    );
    hinges.push(
      world.addJoint(revoluteJoint({ bodyA: previous, bodyB: link, anchor: along(k * length) })),
    );
    previous = link;
  }
  const radius = 0.1;
  const bob = world.add(
    particle({
      position: along(links * length),
      radius,
      density: ratio / (Math.PI * radius * radius),
    }),
  );
  hinges.push(
    world.addJoint(revoluteJoint({ bodyA: previous, bodyB: bob, anchor: along(links * length) })),
  );
  return { world, bob, hinges };
}

const stretchOf = (bob: Body, links = LINKS, length = LENGTH): number =>
  Math.hypot(bob.position.x, bob.position.y) - links * length;

describe('a heavy bob on light links', () => {
  it('hanging at 1000:1, the chain keeps its length and every hinge carries the weight below it (1 %)', () => {
    const { world, bob, hinges } = chain(1000, false);
    let stretch = 0;
    for (let i = 0; i < 600; i++) {
      world.step(DT);
      stretch = Math.max(stretch, Math.abs(stretchOf(bob)));
    }
    const g = world.gravity.y;
    let worst = 0;
    hinges.forEach((hinge, k) => {
      // Hinge k carries the bob and the links below it: LINKS - k links.
      const expected = (bob.mass + (LINKS - k)) * g;
      const force = Math.hypot(hinge.reactionForce.x, hinge.reactionForce.y);
      worst = Math.max(worst, Math.abs(force / expected - 1));
    });
    reportMeasured('1000:1 hanging chain, stretch (m)', stretch, 1e-3);
    reportMeasured('1000:1 hanging chain, worst hinge force error', worst, 0.01);
    expect(stretch).toBeLessThan(1e-3);
    expect(worst).toBeLessThan(0.01);
  });

  // Whipping light links are stiff: each turns against the tension of its two pins. Without the
  // chain's geometric stiffness, the 1000:1 chain below stretched 1.58 m and the eight-link one
  // and the 10,000:1 one exploded.
  for (const [ratio, links, length] of [
    [100, LINKS, LENGTH],
    [1000, LINKS, LENGTH],
    [1000, 8, 0.25],
    [10000, LINKS, LENGTH],
  ] as const) {
    it(`released from the horizontal at ${ratio}:1 on ${links} links, the bob never beats a free fall and the chain stretches at most 1 cm`, () => {
      const { world, bob } = chain(ratio, true, links, length);
      const bound = Math.sqrt(2 * world.gravity.y * links * length);
      let speed = 0;
      let stretch = 0;
      for (let i = 0; i < 600; i++) {
        world.step(DT);
        speed = Math.max(speed, Math.hypot(bob.linearVelocity.x, bob.linearVelocity.y));
        stretch = Math.max(stretch, stretchOf(bob, links, length));
      }
      const label = `${ratio}:1 swinging chain of ${links}`;
      reportMeasured(`${label}, top speed over free-fall speed`, speed / bound, 1.01);
      reportMeasured(`${label}, stretch (m)`, stretch, 0.01);
      expect(speed / bound).toBeLessThan(1.01);
      expect(stretch).toBeLessThan(0.01);
    });
  }

  it('a restored 1000:1 chain steps exactly as the original (the chain solve comes back with it)', () => {
    const { world, bob } = chain(1000, true);
    for (let i = 0; i < 30; i++) world.step(DT);
    const copy = restoreSnapshot(JSON.parse(JSON.stringify(takeSnapshot(world))));
    const copyBob = copy.bodies[copy.bodies.length - 1]!;
    for (let i = 0; i < 120; i++) {
      world.step(DT);
      copy.step(DT);
    }
    expect(copyBob.mass).toBe(bob.mass);
    expect({ ...copyBob.position }).toEqual({ ...bob.position });
  });
});
