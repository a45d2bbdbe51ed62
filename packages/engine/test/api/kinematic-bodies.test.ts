import { describe, expect, it } from 'vitest';
import { Body, World, box } from '@physical/engine';

describe('kinematic bodies', () => {
  it('move exactly with the velocity they are given, ignoring gravity and contacts', () => {
    const world = new World({ gravity: { x: 0, y: 10 } });
    const platform = world.add(
      new Body({
        type: 'kinematic',
        position: { x: 0, y: 0 },
        linearVelocity: { x: 2, y: 0 },
        angularVelocity: 0.5,
        shapes: [{ type: 'box', width: 4, height: 0.5 }],
      }),
    );
    world.add(box({ position: { x: 1, y: -1 }, width: 0.5, height: 0.5 }));
    for (let i = 0; i < 60; i++) world.step(1 / 60);
    expect(platform.position.x).toBeCloseTo(2, 12);
    expect(platform.position.y).toBe(0);
    expect(platform.angle).toBeCloseTo(0.5, 12);
    expect(platform.linearVelocity.x).toBe(2);
    expect(platform.mass).toBe(0);
  });

  it('push dynamic bodies out of their way', () => {
    const world = new World({ gravity: { x: 0, y: 10 } });
    world.add(box({ type: 'static', position: { x: 0, y: 1 }, width: 40, height: 1 }));
    const crate = world.add(box({ position: { x: 2, y: 0 }, width: 1, height: 1, friction: 0.2 }));
    world.add(
      new Body({
        type: 'kinematic',
        position: { x: -2, y: 0 },
        linearVelocity: { x: 3, y: 0 },
        shapes: [{ type: 'box', width: 1, height: 1 }],
      }),
    );
    for (let i = 0; i < 120; i++) world.step(1 / 60);
    // The pusher's front is at -2 + 3 * 2 + 0.5 = 4.5: the crate is ahead of it, never inside.
    expect(crate.position.x).toBeGreaterThan(4.5 + 0.5 - 0.02);
  });

  it('keep a body resting on them awake while they move', () => {
    const world = new World({ gravity: { x: 0, y: 10 } });
    const lift = world.add(
      new Body({
        type: 'kinematic',
        position: { x: 0, y: 5 },
        linearVelocity: { x: 0, y: -0.5 },
        shapes: [{ type: 'box', width: 4, height: 0.5 }],
      }),
    );
    const crate = world.add(box({ position: { x: 0, y: 4.25 }, width: 1, height: 1 }));
    for (let i = 0; i < 180; i++) world.step(1 / 60);
    expect(crate.isAwake).toBe(true);
    // Carried up with the lift: its bottom stays on the lift's top.
    expect(crate.position.y - (lift.position.y - 0.25 - 0.5)).toBeCloseTo(0, 1);
  });
});
