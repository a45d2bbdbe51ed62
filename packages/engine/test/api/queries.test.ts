import { describe, expect, it } from 'vitest';
import { World, box, particle, wall } from '@physical/engine';

function scene() {
  const world = new World({ gravity: { x: 0, y: 0 } });
  const ball = world.add(particle({ position: { x: 0, y: 0 }, radius: 1 }));
  const crate = world.add(
    box({ position: { x: 5, y: 0 }, width: 2, height: 2, angle: Math.PI / 4 }),
  );
  const floor = world.add(wall({ from: { x: -10, y: 5 }, to: { x: 10, y: 5 } }));
  const onTop = world.add(particle({ position: { x: 0.5, y: 0 }, radius: 0.3 }));
  return { world, ball, crate, floor, onTop };
}

describe('queries', () => {
  it('bodyAt finds the body under a point, the last added when several overlap', () => {
    const { world, ball, crate, onTop } = scene();
    expect(world.bodyAt({ x: -0.5, y: 0 })).toBe(ball);
    expect(world.bodyAt({ x: 0.5, y: 0 })).toBe(onTop);
    // The rotated crate is a diamond reaching sqrt(2) from its centre along the axes.
    expect(world.bodyAt({ x: 5 + 1.3, y: 0 })).toBe(crate);
    expect(world.bodyAt({ x: 5 + 1.2, y: 1.2 })).toBeNull();
    expect(world.bodyAt({ x: 20, y: 20 })).toBeNull();
  });

  it('bodiesInAABB returns each overlapping body once, in world order', () => {
    const { world, ball, crate, onTop } = scene();
    expect(world.bodiesInAABB({ minX: -2, minY: -2, maxX: 6, maxY: 2 })).toEqual([
      ball,
      crate,
      onTop,
    ]);
    expect(world.bodiesInAABB({ minX: 20, minY: 20, maxX: 21, maxY: 21 })).toEqual([]);
  });

  it('rayCast returns the first hit with its point, normal and fraction', () => {
    const { world, ball, floor } = scene();
    const hit = world.rayCast({ x: -10, y: 0 }, { x: 10, y: 0 });
    expect(hit?.body).toBe(ball);
    expect(hit!.point.x).toBeCloseTo(-1, 9);
    expect(hit!.normal.x).toBeCloseTo(-1, 9);
    expect(hit!.fraction).toBeCloseTo(9 / 20, 9);
    const down = world.rayCast({ x: 8, y: 0 }, { x: 8, y: 10 });
    expect(down?.body).toBe(floor);
    expect(down!.point.y).toBeCloseTo(5, 9);
    expect(world.rayCast({ x: -10, y: -3 }, { x: 10, y: -3 })).toBeNull();
  });
});

describe('sleeping', () => {
  it('a resting body sleeps and wakes on a force, a velocity, a touch or a gravity change', () => {
    const world = new World({ gravity: { x: 0, y: 10 } });
    world.add(box({ type: 'static', position: { x: 0, y: 3 }, width: 20, height: 1 }));
    const crate = world.add(box({ position: { x: 0, y: 2 }, width: 1, height: 1 }));
    const settle = () => {
      for (let i = 0; i < 120; i++) world.step();
      expect(crate.isAwake).toBe(false);
    };
    settle();
    expect(world.awakeBodyCount).toBe(0);
    crate.applyForce({ x: 5, y: 0 });
    expect(crate.isAwake).toBe(true);
    settle();
    crate.linearVelocity = { x: 1, y: 0 };
    expect(crate.isAwake).toBe(true);
    settle();
    world.gravity = { x: 0, y: -10 };
    expect(crate.isAwake).toBe(true);
    world.gravity = { x: 0, y: 10 };
    settle();
    const ball = world.add(particle({ position: { x: 0, y: 0 }, radius: 0.25 }));
    // It falls 1.25 m (0.5 s) onto the sleeping crate, which the touch wakes.
    for (let i = 0; i < 40; i++) world.step();
    expect(crate.isAwake).toBe(true);
    expect(ball.position.y).toBeCloseTo(1.25, 2);
  });
});
