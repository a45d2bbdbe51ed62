import { describe, expect, it } from 'vitest';
import type { CollisionEvent } from '@physical/engine';
import { CollisionArrows, ARROW_LIFETIME } from '../src/screens/reactions/collision-arrows.ts';
import {
  MAX_FILL,
  PUSH_FORCE,
  clearParticles,
  filledArea,
  freeSpot,
  isFull,
  createReactionsScene,
  pushFor,
  setElasticity,
  setTilt,
  spawnParticle,
  totalMomentum,
} from '../src/screens/reactions/reactions-scene.ts';
import { tiltFromOrientation } from '../src/sensors/device-tilt.ts';

describe('Reactions scene', () => {
  it('spawns a particle where tapped; size shows mass', () => {
    const scene = createReactionsScene(6, 9);
    const small = spawnParticle(scene, { x: 2, y: 3 }, () => 0);
    const big = spawnParticle(scene, { x: 4, y: 6 }, () => 1);
    expect(small.position).toMatchObject({ x: 2, y: 3 });
    expect(big.mass).toBeGreaterThan(small.mass);
    expect(scene.particles.size).toBe(2);
    clearParticles(scene);
    expect(scene.particles.size).toBe(0);
  });

  it('pushes every particle with the same force: the lighter one accelerates more', () => {
    const scene = createReactionsScene(6, 9);
    const small = spawnParticle(scene, { x: 3, y: 1.5 }, () => 0);
    const big = spawnParticle(scene, { x: 3, y: 7.5 }, () => 1);
    setTilt(scene, { x: 1, y: 0 });
    scene.world.step(1 / 60);
    const impulseSmall = small.mass * small.linearVelocity.x;
    const impulseBig = big.mass * big.linearVelocity.x;
    expect(impulseSmall).toBeCloseTo(PUSH_FORCE / 60, 9);
    expect(impulseBig).toBeCloseTo(PUSH_FORCE / 60, 9);
    expect(small.linearVelocity.x).toBeGreaterThan(big.linearVelocity.x);
  });

  it('records equal and opposite arrows at each collision, fading out', () => {
    const scene = createReactionsScene(6, 9);
    const arrows = new CollisionArrows();
    let time = 0;
    scene.world.on('collision', (event: CollisionEvent) => arrows.record(event, 1 / 60, time));
    const a = spawnParticle(scene, { x: 2, y: 8 }, () => 0.5);
    spawnParticle(scene, { x: 4, y: 8 }, () => 0.5);
    a.linearVelocity = { x: 3, y: 0 };
    for (let i = 0; i < 60 && arrows.visible(time).length === 0; i++) {
      scene.world.step(1 / 60);
      time += 1 / 60;
    }
    const [first] = arrows.visible(time);
    expect(first).toBeDefined();
    expect(first!.arrow.force).toBeGreaterThan(0);
    expect(Math.hypot(first!.arrow.nx, first!.arrow.ny)).toBeCloseTo(1, 9);
    expect(arrows.visible(time + ARROW_LIFETIME + 0.01)).toEqual([]);
  });
});

describe('device tilt', () => {
  it('leaning right pushes right, leaning the top up pushes down the screen', () => {
    expect(tiltFromOrientation(0, 90)).toEqual({ x: 1, y: 0 });
    expect(tiltFromOrientation(90, 0)).toEqual({ x: 0, y: 1 });
    expect(tiltFromOrientation(0, -30)).toEqual({ x: -0.5, y: 0 });
  });

  it('follows the screen rotation in landscape', () => {
    const tilt = tiltFromOrientation(0, 90, 90);
    expect(tilt.x).toBeCloseTo(0, 9);
    expect(tilt.y).toBeCloseTo(-1, 9);
  });
});

describe('Reactions push, elasticity and momentum', () => {
  it('caps the push at 1 N in any direction: a diagonal full tilt is 1 N, not 1.41 N', () => {
    const diagonal = pushFor({ x: 1, y: 1 });
    expect(Math.hypot(diagonal.x, diagonal.y)).toBeCloseTo(1, 12);
    expect(diagonal.x).toBeCloseTo(Math.SQRT1_2, 12);
    expect(pushFor({ x: 0.5, y: 0 })).toEqual({ x: 0.5, y: 0 });
  });

  it('gives new particles the chosen elasticity and sums their momentum', () => {
    const scene = createReactionsScene(6, 9, 0.3);
    const a = spawnParticle(scene, { x: 2, y: 2 }, () => 0.5);
    expect(a.shapes[0]!.restitution).toBe(0.3);
    setElasticity(scene, 1);
    expect(a.shapes[0]!.restitution).toBe(1);
    a.linearVelocity = { x: 2, y: 0 };
    const b = spawnParticle(scene, { x: 4, y: 4 }, () => 0);
    b.linearVelocity = { x: 0, y: -1 };
    const p = totalMomentum(scene);
    expect(p.x).toBeCloseTo(2 * a.mass, 12);
    expect(p.y).toBeCloseTo(-b.mass, 12);
  });
});

describe('Reactions scene: a full box', () => {
  it('is full before the particles could no longer lie apart, and a full box stays a box', () => {
    const scene = createReactionsScene(4, 7.5, 1);
    let seed = 7;
    const random = (): number => (seed = (seed * 16807) % 2147483647) / 2147483647;
    // Add as the Add button does, until the box says it is full.
    let added = 0;
    while (!isFull(scene) && added < 1000) {
      spawnParticle(scene, freeSpot(scene, random), random);
      added++;
    }
    expect(isFull(scene)).toBe(true);
    expect(added).toBeGreaterThan(20);
    expect(filledArea(scene)).toBeLessThanOrEqual(MAX_FILL * 4 * 7.5);
    // Pushed hard into a corner for 20 s: every particle stays inside, none runs away.
    setTilt(scene, { x: 1, y: 1 });
    for (let i = 0; i < 1200; i++) scene.world.step(1 / 60);
    for (const body of scene.particles.keys()) {
      expect(body.position.x).toBeGreaterThan(0);
      expect(body.position.x).toBeLessThan(4);
      expect(body.position.y).toBeGreaterThan(0);
      expect(body.position.y).toBeLessThan(7.5);
      expect(Math.hypot(body.linearVelocity.x, body.linearVelocity.y)).toBeLessThan(5);
    }
  });

  it('finds a free spot for a new particle while there is one', () => {
    const scene = createReactionsScene(6, 9);
    spawnParticle(scene, { x: 3, y: 4.5 }, () => 1);
    const spot = freeSpot(scene, () => 0.5);
    // 0.5 lands on the particle at the centre every try: the last try is returned anyway.
    expect(spot).toEqual({ x: 3, y: 4.5 });
    let k = 0;
    const tries = [0.5, 0.5, 0, 0];
    const free = freeSpot(scene, () => tries[k++ % tries.length]!);
    expect(scene.world.overlapShape({ type: 'circle', radius: 0.45 }, { position: free })).toEqual(
      [],
    );
  });
});
