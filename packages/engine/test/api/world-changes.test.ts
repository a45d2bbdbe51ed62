import { describe, expect, it } from 'vitest';
import { World, box, particle, wall, type Body } from '@physical/engine';

// The thesis's canvas took a plain list of bodies the app could change at any time; the world
// must make that just as easy, also from inside callbacks, without corrupting a step.

function fallingPair(): { world: World; ball: Body; ground: Body } {
  const world = new World({ gravity: { x: 0, y: 10 } });
  const ground = world.add(box({ type: 'static', position: { x: 0, y: 5 }, width: 20, height: 1 }));
  const ball = world.add(particle({ position: { x: 0, y: 0 }, radius: 0.5 }));
  return { world, ball, ground };
}

describe('adding and removing bodies', () => {
  it('keeps bodies in the order they were added', () => {
    const world = new World();
    const a = world.add(particle({ radius: 1 }));
    const b = world.add(particle({ radius: 1, position: { x: 3, y: 0 } }));
    const c = world.add(particle({ radius: 1, position: { x: 6, y: 0 } }));
    world.remove(b);
    expect(world.bodies).toEqual([a, c]);
    expect(world.has(b)).toBe(false);
    expect(b.world).toBeNull();
    const d = world.add(b);
    expect(world.bodies).toEqual([a, c, d]);
  });

  it('a body removed from inside a collision listener leaves at the end of the step', () => {
    const { world, ball } = fallingPair();
    let collisions = 0;
    world.on('collision', (event) => {
      collisions++;
      if (event.bodyA === ball || event.bodyB === ball) world.remove(ball);
      // Still listed until the step ends: the step is never corrupted mid-way.
      expect(world.bodies).toContain(ball);
      expect(world.has(ball)).toBe(false);
    });
    for (let i = 0; i < 120 && world.bodies.includes(ball); i++) world.step();
    expect(collisions).toBe(1); // no more events once its removal is queued
    expect(world.bodies).not.toContain(ball);
    expect(ball.world).toBeNull();
    // The world keeps working after the removal.
    for (let i = 0; i < 10; i++) world.step();
  });

  it('a body added from inside a listener joins at the end of the step and simulates', () => {
    const { world, ball } = fallingPair();
    let spawned: Body | null = null;
    ball.on('collision', () => {
      if (spawned === null)
        spawned = world.add(particle({ position: { x: 3, y: 0 }, radius: 0.5 }));
    });
    for (let i = 0; i < 120; i++) world.step();
    expect(spawned).not.toBeNull();
    expect(world.bodies).toContain(spawned);
    // It fell onto the ground (top at y = 4.5) and rests there.
    expect(spawned!.position.y).toBeCloseTo(4, 1);
  });

  it('removing a body that other bodies rest on wakes them, and they fall', () => {
    const world = new World({ gravity: { x: 0, y: 10 } });
    world.add(box({ type: 'static', position: { x: 0, y: 10 }, width: 20, height: 1 }));
    const shelf = world.add(
      box({ type: 'static', position: { x: 0, y: 5 }, width: 4, height: 0.5 }),
    );
    const crate = world.add(box({ position: { x: 0, y: 4.25 }, width: 1, height: 1 }));
    for (let i = 0; i < 120; i++) world.step();
    expect(crate.isAwake).toBe(false);
    world.remove(shelf);
    expect(crate.isAwake).toBe(true);
    for (let i = 0; i < 120; i++) world.step();
    expect(crate.position.y).toBeCloseTo(9, 1);
  });

  it('clear() removes everything', () => {
    const { world } = fallingPair();
    world.clear();
    expect(world.bodies).toHaveLength(0);
    world.step();
  });

  it('shapes can be added to and removed from a body in the world', () => {
    const { world, ball } = fallingPair();
    const mass = ball.mass;
    const extra = ball.addShape({ type: 'box', width: 1, height: 1, offset: { x: 1, y: 0 } });
    expect(ball.mass).toBeCloseTo(mass + 1, 12);
    expect(ball.centerOfMass.x).toBeGreaterThan(0);
    ball.removeShape(extra);
    expect(ball.mass).toBeCloseTo(mass, 12);
    for (let i = 0; i < 120; i++) world.step();
    expect(ball.position.y).toBeCloseTo(4, 1);
  });

  it('teleporting a body wakes it and it falls from its new place', () => {
    const { world, ball } = fallingPair();
    for (let i = 0; i < 120; i++) world.step();
    expect(ball.isAwake).toBe(false);
    ball.position = { x: 2, y: -5 };
    expect(ball.isAwake).toBe(true);
    world.step();
    expect(ball.position.x).toBe(2);
    expect(ball.position.y).toBeGreaterThan(-5);
  });

  it('a wall added between steps stops a falling body', () => {
    const world = new World({ gravity: { x: 0, y: 10 } });
    const ball = world.add(particle({ radius: 0.25 }));
    world.step();
    world.add(wall({ from: { x: -5, y: 2 }, to: { x: 5, y: 2 } }));
    for (let i = 0; i < 120; i++) world.step();
    expect(ball.position.y).toBeCloseTo(1.75, 2);
  });
});
