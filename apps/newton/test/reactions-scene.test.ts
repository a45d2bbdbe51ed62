import { describe, expect, it } from 'vitest';
import {
  type Body,
  type CollisionEvent,
  World,
  particle,
  restoreSnapshot,
  takeSnapshot,
} from '@physical/engine';
import { DYNAMIC_PALETTE } from '@physical/canvas';
import {
  CollisionArrows,
  ARROW_LIFETIME,
  averageForce,
} from '../src/screens/reactions/collision-arrows.ts';
import {
  CollisionRecorder,
  totalKineticEnergyOf,
  totalMomentumOf,
} from '../src/screens/reactions/collision-lab.ts';
import { observeSteps } from '../src/lab/step-hook.ts';
import {
  GRAVITY,
  MAX_FILL,
  adoptWorld,
  clearParticles,
  labelsByIndex,
  particleColor,
  particleLabel,
  radiusForMass,
  setParticleMass,
  setTiltOn,
  setUpLab,
  setWallsOn,
  trayAcceleration,
  filledArea,
  freeSpot,
  isFull,
  createReactionsScene,
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

  it('tilts like a tray: m g sin θ on each particle, the same acceleration for every mass', () => {
    const scene = createReactionsScene(6, 9);
    const small = spawnParticle(scene, { x: 3, y: 1.5 }, () => 0);
    const big = spawnParticle(scene, { x: 3, y: 7.5 }, () => 1);
    // sin θ = 0.5: leaning 30°.
    setTilt(scene, { x: 0.5, y: 0 });
    scene.world.step(1 / 60);
    expect(small.linearVelocity.x).toBeCloseTo((GRAVITY * 0.5) / 60, 9);
    expect(big.linearVelocity.x).toBeCloseTo((GRAVITY * 0.5) / 60, 9);
    // The force m g sin θ grows with the mass.
    expect(big.mass * big.linearVelocity.x).toBeGreaterThan(small.mass * small.linearVelocity.x);
    // Switched off, the tilt pushes nothing.
    setTiltOn(scene, false);
    const v = big.linearVelocity.x;
    scene.world.step(1 / 60);
    expect(big.linearVelocity.x).toBe(v);
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
    // An elastic head-on hit of equal masses at 3 m/s: J = m u (e = 0.8: J = (1 + e) m u / 2).
    const mass = a.mass;
    expect(first!.arrow.impulse).toBeCloseTo((1.8 * mass * 3) / 2, 3);
    expect(averageForce(first!.arrow.impulse, 0.01)).toBeCloseTo(first!.arrow.impulse * 100, 9);
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
  it('caps the tray acceleration at g in any direction: a diagonal full tilt is g, not 1.41 g', () => {
    const diagonal = trayAcceleration({ x: 1, y: 1 });
    expect(Math.hypot(diagonal.x, diagonal.y)).toBeCloseTo(GRAVITY, 12);
    expect(diagonal.x).toBeCloseTo(GRAVITY * Math.SQRT1_2, 12);
    expect(trayAcceleration({ x: 0.5, y: 0 })).toEqual({ x: GRAVITY / 2, y: 0 });
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
    // 1,200 steps of a full box: 3.7 s on a quiet machine, over 7 s on a loaded one.
  }, 30_000);

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

/** The closed form of a 1-D collision with restitution e: velocities after. */
function closedForm(m1: number, m2: number, u1: number, u2: number, e: number): [number, number] {
  const p = m1 * u1 + m2 * u2;
  return [(p - m2 * e * (u1 - u2)) / (m1 + m2), (p + m1 * e * (u1 - u2)) / (m1 + m2)];
}

describe('Reactions collision lab', () => {
  for (const e of [1, 0, 0.5]) {
    it(`records before and after a 1-D collision with e = ${e} as the closed form says`, () => {
      const scene = createReactionsScene(6, 9, e);
      setTiltOn(scene, false);
      const [a, b] = setUpLab(scene, [
        { mass: 1, vx: 2 },
        { mass: 2, vx: -0.5 },
      ]) as [Body, Body];
      expect(a.mass).toBeCloseTo(1, 12);
      expect(b.mass).toBeCloseTo(2, 12);
      const recorder = new CollisionRecorder();
      recorder.setPair([a, b, 'A', 'B']);
      scene.world.on('collision', (event) => recorder.collided(event));
      observeSteps(scene.world, {
        before: () => recorder.beforeStep(),
        after: () => recorder.afterStep(scene.world.steps / 60),
      });
      for (let i = 0; i < 90; i++) scene.world.step(1 / 60);
      const record = recorder.record!;
      expect(record).not.toBeNull();
      const [v1, v2] = closedForm(1, 2, 2, -0.5, e);
      expect(record.before.map((s) => s.vx)).toEqual([2, -0.5]);
      expect(record.after[0]!.vx).toBeCloseTo(v1, 6);
      expect(record.after[1]!.vx).toBeCloseTo(v2, 6);
      expect(totalMomentumOf(record.after).x).toBeCloseTo(totalMomentumOf(record.before).x, 9);
      const lost = totalKineticEnergyOf(record.before) - totalKineticEnergyOf(record.after);
      // KE lost: (1 - e^2) m1 m2 (u1 - u2)^2 / (2 (m1 + m2)).
      expect(lost).toBeCloseTo(((1 - e * e) * 1 * 2 * 2.5 ** 2) / (2 * 3), 6);
    });
  }

  it('walls off: particles pass through them with their momentum', () => {
    const scene = createReactionsScene(6, 9, 1);
    setTiltOn(scene, false);
    setWallsOn(scene, false);
    const [a] = setUpLab(scene, [{ mass: 1, vx: 5 }]) as [Body];
    for (let i = 0; i < 120; i++) scene.world.step(1 / 60);
    expect(a.position.x).toBeGreaterThan(6);
    expect(a.linearVelocity.x).toBeCloseTo(5, 12);
    setWallsOn(scene, true);
    const [c] = setUpLab(scene, [{ mass: 1, vx: 5 }]) as [Body];
    for (let i = 0; i < 120; i++) scene.world.step(1 / 60);
    expect(c.position.x).toBeLessThan(6);
  });

  it('shows a mass by the size of its disc, and sets it exactly', () => {
    const scene = createReactionsScene(6, 9, 1);
    const body = spawnParticle(scene, { x: 3, y: 3 }, () => 0.5);
    setParticleMass(body, 2);
    expect(body.mass).toBeCloseTo(2, 12);
    expect(body.shapes).toHaveLength(1);
    const shape = body.shapes[0]!;
    expect(shape.geometry.kind === 'circle' && shape.geometry.radius).toBe(radiusForMass(2));
    expect(radiusForMass(1)).toBeLessThan(radiusForMass(2));
    expect(particleLabel(0)).toBe('A');
    expect(particleLabel(27)).toBe('B2');
  });

  it('gives each next particle the next palette colour, the same again for its name after a rewind', () => {
    const colors = Array.from({ length: 60 }, (_, index) => particleColor(particleLabel(index)));
    expect(colors).toEqual(
      Array.from({ length: 60 }, (_, index) => index % DYNAMIC_PALETTE.length),
    );
    const scene = createReactionsScene(6, 9, 1);
    const [a, b] = setUpLab(scene, [
      { mass: 1, vx: 1 },
      { mass: 2, vx: 0 },
    ]);
    expect([scene.particles.get(a!)!.color, scene.particles.get(b!)!.color]).toEqual([0, 1]);
    const again = adoptWorld(
      scene,
      restoreSnapshot(takeSnapshot(scene.world)),
      labelsByIndex(scene),
      2,
    );
    expect([...again.particles.values()].map((info) => [info.label, info.color])).toEqual([
      ['A', 0],
      ['B', 1],
    ]);
  });

  it('names the particles of a restored world again by their index', () => {
    const scene = createReactionsScene(6, 9, 1);
    setUpLab(scene, [
      { mass: 1, vx: 1 },
      { mass: 2, vx: 0 },
    ]);
    const labels = labelsByIndex(scene);
    const copy = new World({ gravity: { x: 0, y: 0 } });
    for (const body of scene.world.bodies)
      copy.add(particle({ position: body.position, radius: 0.2 }));
    const adopted = adoptWorld(scene, copy, labels, scene.added);
    expect([...adopted.particles.values()].map((info) => info.label)).toEqual(['A', 'B']);
    expect(adopted.particles.has(copy.bodies[labels.indexOf('B')]!)).toBe(true);
  });
});
