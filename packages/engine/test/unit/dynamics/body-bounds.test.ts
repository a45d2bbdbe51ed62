import { describe, expect, it } from 'vitest';
import { World, box, type Body } from '@physical/engine';

// The broad phase is what queries and new contacts see: after every step each awake body's boxes
// must be where the body is, whichever path moved them (finalize for slow bodies, after the sweep
// for fast ones and bullets, finalize for everything when continuous collision is off).

function around(body: Body, half: number) {
  const p = body.position;
  return { minX: p.x - half, minY: p.y - half, maxX: p.x + half, maxY: p.y + half };
}

const cases = [
  { name: 'a slow body', speed: 0.5, bullet: false, continuous: true, type: 'dynamic' },
  { name: 'a fast body (swept)', speed: 300, bullet: false, continuous: true, type: 'dynamic' },
  { name: 'a fast bullet', speed: 300, bullet: true, continuous: true, type: 'dynamic' },
  {
    name: 'a fast body, continuous off',
    speed: 300,
    bullet: false,
    continuous: false,
    type: 'dynamic',
  },
  { name: 'a kinematic body', speed: 300, bullet: false, continuous: true, type: 'kinematic' },
] as const;

describe('broad-phase boxes follow the bodies', () => {
  for (const c of cases) {
    it(`${c.name}: found where it is after each step, not where it was`, () => {
      const world = new World({ gravity: { x: 0, y: 0 }, enableContinuous: c.continuous });
      const mover = world.add(
        box({ type: c.type, position: { x: 0, y: 0 }, width: 0.2, height: 0.2, bullet: c.bullet }),
      );
      // Something else in the dynamic tree, so the query is not trivially the only proxy.
      world.add(box({ position: { x: -50, y: 30 }, width: 1, height: 1 }));
      mover.linearVelocity = { x: c.speed, y: 0 };
      for (let step = 0; step < 5; step++) {
        const before = around(mover, 0.05);
        world.step(1 / 60);
        expect(mover.position.x).toBeGreaterThan(before.minX + 0.05 + (c.speed / 60) * 0.99);
        expect(world.bodiesInAABB(around(mover, 0.05))).toContain(mover);
        // Moved farther than the fat margin (0.1 m) plus its size: its old place is empty.
        if (c.speed / 60 > 0.5) expect(world.bodiesInAABB(before)).not.toContain(mover);
      }
    });
  }
});
