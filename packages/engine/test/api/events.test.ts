import { describe, expect, it } from 'vitest';
import { World, box, particle, type CollisionEvent } from '@physical/engine';

describe('onCollision', () => {
  it('reports both bodies, a unit normal from A to B and equal and opposite impulses', () => {
    const world = new World({ gravity: { x: 0, y: 0 }, restitutionThreshold: 0 });
    const left = world.add(
      particle({ position: { x: 0, y: 0 }, radius: 0.5, linearVelocity: { x: 2, y: 0 } }),
    );
    const right = world.add(particle({ position: { x: 2, y: 0 }, radius: 0.5, density: 3 }));
    const seen: { normalX: number; normalY: number; impulse: number; a: unknown }[] = [];
    world.on('collision', (event: CollisionEvent) => {
      seen.push({
        normalX: event.normalX,
        normalY: event.normalY,
        impulse: event.normalImpulse,
        a: event.bodyA,
      });
    });
    const momentumBefore = left.mass * left.linearVelocity.x + right.mass * right.linearVelocity.x;
    const leftVelocityBefore = left.linearVelocity.x;
    for (let i = 0; i < 60 && seen.length === 0; i++) world.step();
    expect(seen).toHaveLength(1);
    const hit = seen[0]!;
    expect(Math.hypot(hit.normalX, hit.normalY)).toBeCloseTo(1, 12);
    // The normal points from A to B.
    const sign = hit.a === left ? 1 : -1;
    expect(hit.normalX * sign).toBeCloseTo(1, 9);
    // Newton's third law: A lost exactly what B gained, and that is the reported impulse.
    const impulseOnRight = right.mass * right.linearVelocity.x;
    expect(impulseOnRight).toBeCloseTo(hit.impulse, 9);
    expect(left.mass * (leftVelocityBefore - left.linearVelocity.x)).toBeCloseTo(hit.impulse, 9);
    expect(left.mass * left.linearVelocity.x + right.mass * right.linearVelocity.x).toBeCloseTo(
      momentumBefore,
      12,
    );
  });

  it('fires on the body options (the thesis style) and on the world, and can be removed', () => {
    const world = new World({ gravity: { x: 0, y: 10 } });
    world.add(box({ type: 'static', position: { x: 0, y: 3 }, width: 10, height: 1 }));
    let bodyCalls = 0;
    let worldCalls = 0;
    let moves = 0;
    const ball = world.add(
      particle({
        radius: 0.25,
        onCollision: () => bodyCalls++,
        onMove: () => moves++,
      }),
    );
    const stop = world.on('collision', () => worldCalls++);
    for (let i = 0; i < 60; i++) world.step();
    expect(bodyCalls).toBeGreaterThan(0);
    expect(worldCalls).toBe(bodyCalls);
    expect(moves).toBeGreaterThan(20);
    stop();
    const before = worldCalls;
    ball.applyImpulse({ x: 0, y: 1 });
    for (let i = 0; i < 10; i++) world.step();
    expect(worldCalls).toBe(before);
  });

  it('onMove stops once the body sleeps', () => {
    const world = new World({ gravity: { x: 0, y: 10 } });
    world.add(box({ type: 'static', position: { x: 0, y: 3 }, width: 10, height: 1 }));
    let moves = 0;
    const ball = world.add(particle({ radius: 0.25, onMove: () => moves++ }));
    for (let i = 0; i < 300; i++) world.step();
    expect(ball.isAwake).toBe(false);
    const atRest = moves;
    for (let i = 0; i < 60; i++) world.step();
    expect(moves).toBe(atRest);
  });
});

describe('contact begin and end', () => {
  it('begin when shapes meet, end when they part', () => {
    const world = new World({ gravity: { x: 0, y: 0 }, restitutionThreshold: 0 });
    const a = world.add(
      particle({
        position: { x: 0, y: 0 },
        radius: 0.5,
        linearVelocity: { x: 3, y: 0 },
        restitution: 1,
      }),
    );
    world.add(particle({ position: { x: 3, y: 0 }, radius: 0.5, restitution: 1 }));
    const log: string[] = [];
    world.on('contactBegin', () => log.push('begin'));
    world.on('contactEnd', () => log.push('end'));
    for (let i = 0; i < 120; i++) world.step();
    expect(log).toEqual(['begin', 'end']);
    expect(a.linearVelocity.x).toBeCloseTo(0, 6); // equal masses exchanged velocities
  });

  it('removing a touching body ends its contacts', () => {
    const world = new World({ gravity: { x: 0, y: 10 } });
    const ground = world.add(
      box({ type: 'static', position: { x: 0, y: 3 }, width: 10, height: 1 }),
    );
    const ball = world.add(particle({ radius: 0.25, position: { x: 0, y: 2.2 } }));
    let ended = 0;
    ball.on('contactEnd', (event) => {
      expect([event.bodyA, event.bodyB]).toContain(ground);
      ended++;
    });
    for (let i = 0; i < 30; i++) world.step();
    world.remove(ground);
    expect(ended).toBe(1);
  });
});

describe('world events', () => {
  it('bodyAdded, bodyRemoved and wake', () => {
    const world = new World({ gravity: { x: 0, y: 10 } });
    const log: string[] = [];
    world.on('bodyAdded', () => log.push('added'));
    world.on('bodyRemoved', () => log.push('removed'));
    world.on('wake', () => log.push('wake'));
    world.add(box({ type: 'static', position: { x: 0, y: 3 }, width: 10, height: 1 }));
    const ball = world.add(particle({ radius: 0.25, position: { x: 0, y: 2.2 } }));
    for (let i = 0; i < 120; i++) world.step();
    expect(ball.isAwake).toBe(false);
    ball.applyForce({ x: 1, y: 0 });
    world.remove(ball);
    expect(log).toEqual(['added', 'added', 'wake', 'removed']);
  });
});
