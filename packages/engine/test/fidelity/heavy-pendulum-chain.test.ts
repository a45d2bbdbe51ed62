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
// (no energy is made) and, at 100:1, the chain keeps its length.

const DT = 1 / 60;
const LINKS = 4;
const LENGTH = 0.5;

function chain(
  ratio: number,
  horizontal: boolean,
): { world: World; bob: Body; hinges: RevoluteJoint[] } {
  const world = new World({ enableSleep: false });
  const ceiling = world.add(
    box({ type: 'static', position: { x: 0, y: -0.1 }, width: 0.2, height: 0.2 }),
  );
  const hinges: RevoluteJoint[] = [];
  let previous: Body = ceiling;
  const along = (d: number): { x: number; y: number } =>
    horizontal ? { x: d, y: 0 } : { x: 0, y: d };
  for (let k = 0; k < LINKS; k++) {
    const link = world.add(
      box({
        position: along((k + 0.5) * LENGTH),
        width: horizontal ? LENGTH : 0.05,
        height: horizontal ? 0.05 : LENGTH,
        density: 1 / (LENGTH * 0.05),
      }),
    );
    hinges.push(
      world.addJoint(revoluteJoint({ bodyA: previous, bodyB: link, anchor: along(k * LENGTH) })),
    );
    previous = link;
  }
  const radius = 0.1;
  const bob = world.add(
    particle({
      position: along(LINKS * LENGTH),
      radius,
      density: ratio / (Math.PI * radius * radius),
    }),
  );
  hinges.push(
    world.addJoint(revoluteJoint({ bodyA: previous, bodyB: bob, anchor: along(LINKS * LENGTH) })),
  );
  return { world, bob, hinges };
}

const stretchOf = (bob: Body): number =>
  Math.hypot(bob.position.x, bob.position.y) - LINKS * LENGTH;

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

  for (const [ratio, stretchTolerance] of [
    [100, 0.01],
    [1000, 2],
  ] as const) {
    it(`released from the horizontal at ${ratio}:1, the bob never beats a free fall and the chain stretches at most ${stretchTolerance} m`, () => {
      const { world, bob } = chain(ratio, true);
      const bound = Math.sqrt(2 * world.gravity.y * LINKS * LENGTH);
      let speed = 0;
      let stretch = 0;
      for (let i = 0; i < 600; i++) {
        world.step(DT);
        speed = Math.max(speed, Math.hypot(bob.linearVelocity.x, bob.linearVelocity.y));
        stretch = Math.max(stretch, stretchOf(bob));
      }
      reportMeasured(
        `${ratio}:1 swinging chain, top speed over free-fall speed`,
        speed / bound,
        1.01,
      );
      reportMeasured(`${ratio}:1 swinging chain, stretch (m)`, stretch, stretchTolerance);
      expect(speed / bound).toBeLessThan(1.01);
      expect(stretch).toBeLessThan(stretchTolerance);
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
