import { describe, expect, it } from 'vitest';
import { restoreSnapshot, takeSnapshot } from '@physical/engine';
import {
  POLYGON_MASS,
  adoptWorld,
  applyConstantForce,
  createInertiaScene,
  forceVector,
  labMotion,
  sceneSizeFor,
  updateFloorFriction,
  screenAngle,
} from '../src/screens/inertia/inertia-scene.ts';

/** A deterministic stand-in for Math.random. */
function sequence(...values: number[]): () => number {
  let index = 0;
  return () => values[index++ % values.length]!;
}

describe('Inertia scene', () => {
  it('puts a 5- or 6-sided polygon at rest in the centre, asleep, with elastic walls on ice by default', () => {
    const scene = createInertiaScene(6, 8, {}, sequence(0.7));
    expect(scene.sides).toBe(6);
    expect(scene.elasticity).toBe(1);
    expect(scene.surface).toBe('ice');
    expect(scene.body.position.x).toBeCloseTo(3, 12);
    expect(scene.body.position.y).toBeCloseTo(4, 12);
    expect(scene.body.mass).toBeCloseTo(POLYGON_MASS, 9);
    expect(scene.body.isAwake).toBe(false);
    expect(createInertiaScene(6, 8, {}, sequence(0.2)).sides).toBe(5);
    expect(scene.world.gravity).toEqual({ x: 0, y: 0 });
    for (let i = 0; i < 120; i++) scene.world.step(1 / 60);
    expect(scene.body.linearVelocity.x).toBe(0);
    expect(scene.body.linearVelocity.y).toBe(0);
  });

  it('keeps the speed through wall bounces by default (perfectly elastic, frictionless walls)', () => {
    const scene = createInertiaScene(6, 8, { sides: 6 });
    scene.body.linearVelocity = { x: 2, y: 0.7 };
    const speed = Math.hypot(2, 0.7);
    let hits = 0;
    scene.world.on('collision', () => hits++);
    for (let i = 0; i < 240; i++) scene.world.step(1 / 60);
    const v = scene.body.linearVelocity;
    expect(hits).toBeGreaterThanOrEqual(2);
    expect(Math.hypot(v.x, v.y)).toBeCloseTo(speed, 2);
  });

  it('with bounciness 0 the body stops at the wall; on wood friction mu m g slows and stops it', () => {
    const dead = createInertiaScene(6, 8, { sides: 6, elasticity: 0 });
    dead.body.linearVelocity = { x: 2, y: 0 };
    for (let i = 0; i < 120; i++) dead.world.step(1 / 60);
    expect(Math.abs(dead.body.linearVelocity.x)).toBeLessThan(0.05);
    const wood = createInertiaScene(60, 60, { sides: 6, surface: 'wood' });
    wood.body.linearVelocity = { x: 1, y: 0 };
    updateFloorFriction(wood);
    for (let i = 0; i < 60; i++) wood.world.step(1 / 60);
    // a = mu g = 0.05 * 9.81 m/s^2 for 1 s.
    expect(wood.body.linearVelocity.x).toBeCloseTo(1 - 0.05 * 9.81, 2);
    for (let i = 0; i < 180; i++) wood.world.step(1 / 60);
    expect(wood.body.linearVelocity.x).toBe(0);
    expect(wood.body.isAwake).toBe(false);
  });

  it('points 0 degrees right and 90 degrees up on screen (the world is y-down)', () => {
    expect(forceVector(0, 2)).toEqual({ x: 2, y: 0 });
    expect(forceVector(90, 2)).toEqual({ x: 0, y: -2 });
    expect(screenAngle({ x: 0, y: -1 })).toBe(90);
    expect(screenAngle({ x: 0, y: 1 })).toBe(270);
  });

  it('accelerates while the force acts and keeps a constant velocity after it stops', () => {
    const scene = createInertiaScene(6, 8, {}, sequence(0.7));
    const force = applyConstantForce(scene, 0, 1);
    for (let i = 0; i < 30; i++) scene.world.step(1 / 60);
    force.remove();
    const speed = scene.body.linearVelocity.x;
    expect(speed).toBeCloseTo(0.5, 9); // 1 N on 1 kg for 0.5 s
    for (let i = 0; i < 60; i++) scene.world.step(1 / 60);
    expect(scene.body.linearVelocity.x).toBeCloseTo(speed, 12);
    expect(scene.body.linearVelocity.y).toBe(0);
    expect(scene.body.position.x).toBeGreaterThan(3.5);
  });

  it('sizes the box to the canvas: short side 6 m', () => {
    expect(sceneSizeFor(400, 800)).toEqual({ width: 6, height: 12 });
    expect(sceneSizeFor(800, 400)).toEqual({ width: 12, height: 6 });
    expect(sceneSizeFor(0, 0)).toEqual({ width: 6, height: 7.5 });
  });

  it('a scene stepped back to goes on as the original did: the floor slows it the same (its friction is the restored first force)', () => {
    const scene = createInertiaScene(6, 8, { surface: 'wood', elasticity: 0.5 }, sequence(0.2));
    const push = applyConstantForce(scene, 30, 2);
    for (let i = 0; i < 20; i++) scene.world.step(1 / 60);
    push.remove();
    const saved = takeSnapshot(scene.world);
    const back = adoptWorld(scene, restoreSnapshot(saved));
    expect(back.body).toBe(back.world.bodies[4]);
    expect(back.walls).toEqual(back.world.bodies.slice(0, 4));
    expect(back.friction).toBe(back.body.forces[0]);
    expect([back.width, back.height, back.sides, back.surface]).toEqual([6, 8, 5, 'wood']);
    for (let i = 0; i < 40; i++) {
      scene.world.step(1 / 60);
      back.world.step(1 / 60);
    }
    expect(labMotion(back)).toEqual(labMotion(scene));
    expect(back.friction.x).toBe(scene.friction.x);
    expect(back.friction.x).not.toBe(0);
  });

  it("reports position and velocity from the floor's left end, y up as the screen's angles count", () => {
    const scene = createInertiaScene(6, 8, {}, sequence(0.7));
    scene.body.position = { x: 1, y: 2 };
    scene.body.linearVelocity = { x: 0.5, y: -1.5 };
    expect(labMotion(scene)).toEqual({ x: 1, y: 6, vx: 0.5, vy: 1.5 });
    expect(screenAngle({ x: 0, y: -1 })).toBe(90);
  });
});
