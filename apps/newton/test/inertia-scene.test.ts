import { describe, expect, it } from 'vitest';
import {
  POLYGON_MASS,
  applyConstantForce,
  createInertiaScene,
  forceVector,
  sceneSizeFor,
  screenAngle,
} from '../src/screens/inertia/inertia-scene.ts';

/** A deterministic stand-in for Math.random. */
function sequence(...values: number[]): () => number {
  let index = 0;
  return () => values[index++ % values.length]!;
}

describe('Inertia scene', () => {
  it('puts a 5- or 6-sided polygon at rest in the centre, with random restitution and friction', () => {
    const scene = createInertiaScene(6, 8, sequence(0.7, 0.25, 0.9));
    expect(scene.sides).toBe(6);
    expect(scene.restitution).toBe(0.25);
    expect(scene.friction).toBe(0.9);
    expect(scene.body.position.x).toBeCloseTo(3, 12);
    expect(scene.body.position.y).toBeCloseTo(4, 12);
    expect(scene.body.mass).toBeCloseTo(POLYGON_MASS, 9);
    expect(createInertiaScene(6, 8, sequence(0.2, 0.5, 0.5)).sides).toBe(5);
    expect(scene.world.gravity).toEqual({ x: 0, y: 0 });
    for (let i = 0; i < 120; i++) scene.world.step(1 / 60);
    expect(scene.body.linearVelocity.x).toBe(0);
    expect(scene.body.linearVelocity.y).toBe(0);
  });

  it('points 0 degrees right and 90 degrees up on screen (the world is y-down)', () => {
    expect(forceVector(0, 2)).toEqual({ x: 2, y: 0 });
    expect(forceVector(90, 2)).toEqual({ x: 0, y: -2 });
    expect(screenAngle({ x: 0, y: -1 })).toBe(90);
    expect(screenAngle({ x: 0, y: 1 })).toBe(270);
  });

  it('accelerates while the force acts and keeps a constant velocity after it stops', () => {
    const scene = createInertiaScene(6, 8, sequence(0.7, 0.5, 0.5));
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
});
