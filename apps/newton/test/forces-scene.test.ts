import { describe, expect, it } from 'vitest';
import { restoreSnapshot, takeSnapshot } from '@physical/engine';
import {
  accelerationFor,
  adoptTrack,
  arrowLength,
  createForcesTrack,
  displacement,
  drawMysteryMass,
  isMysteryFound,
  measuredAcceleration,
  MYSTERY_MAX,
  MYSTERY_MIN,
  opacityFor,
  startTrack,
  trackState,
} from '../src/screens/forces/forces-scene.ts';

describe('Forces scene', () => {
  it('computes a = F / m, and pushes with the force the learner set', () => {
    expect(accelerationFor(2, 1)).toBe(2);
    expect(accelerationFor(2, 2)).toBe(1);
    expect(accelerationFor(1.5, 0.5)).toBe(3);
    expect(createForcesTrack({ mass: 2, force: 4 }).force).toBe(4);
  });

  it('measures a = F / m to 1e-9 from the first step to the stop (2 x / t^2 read 2.125 at 4 steps)', () => {
    for (const [mass, force] of [
      [1, 2],
      [1.5, 2],
      [5, 2],
    ] as const) {
      const track = createForcesTrack({ mass, force });
      expect(measuredAcceleration(track)).toBeNull();
      let finished = false;
      startTrack(track, () => (finished = true));
      for (let step = 1; step <= 600; step++) {
        track.world.step(1 / 60);
        const a = measuredAcceleration(track)!;
        expect(Math.abs(a - force / mass)).toBeLessThan(1e-9);
        if (step === 4 && mass === 1) {
          // The ruler and clock from rest: the integrator's half sub-step of lead, a (1 + h / t).
          expect((2 * displacement(track)) / (4 / 60) ** 2).toBeCloseTo(2.125, 9);
        }
      }
      expect(finished).toBe(true);
    }
  });

  it('gives the square the mass the learner set', () => {
    expect(createForcesTrack({ mass: 2.5, force: 1 }).square.mass).toBeCloseTo(2.5, 12);
  });

  it('draws heavier squares more opaque and bigger forces longer', () => {
    expect(opacityFor(1)).toBeLessThan(opacityFor(2));
    expect(opacityFor(5)).toBe(1);
    expect(arrowLength(4)).toBeCloseTo(2 * arrowLength(2), 12);
  });

  it('moves (1 kg, 2 N) and (2 kg, 4 N) together: same x within 1 mm after 1 s', () => {
    const light = createForcesTrack({ mass: 1, force: 2 });
    const heavy = createForcesTrack({ mass: 2, force: 4 });
    startTrack(light);
    startTrack(heavy);
    for (let i = 0; i < 60; i++) {
      light.world.step(1 / 60);
      heavy.world.step(1 / 60);
    }
    expect(Math.abs(displacement(light) - displacement(heavy))).toBeLessThan(0.001);
    // x = a t^2 / 2 = 1 m (semi-implicit Euler at 60 Hz: within 2 %).
    expect(displacement(light)).toBeCloseTo(1, 1);
    expect(light.square.linearVelocity.x).toBeCloseTo(2, 6);
  });

  it('without friction or gravity the square stays put until started', () => {
    const track = createForcesTrack({ mass: 1, force: 2 });
    for (let i = 0; i < 60; i++) track.world.step(1 / 60);
    expect(displacement(track)).toBe(0);
  });
});

describe('mystery mass', () => {
  it('is a tenth of a kilogram between 1 and 4 kg, over the whole range of the random source', () => {
    for (const r of [0, 1e-9, 0.25, 0.5, 0.99, 1 - 1e-12]) {
      const mass = drawMysteryMass(() => r);
      expect(mass).toBeGreaterThanOrEqual(MYSTERY_MIN);
      expect(mass).toBeLessThanOrEqual(MYSTERY_MAX);
      expect(Math.abs(mass * 10 - Math.round(mass * 10))).toBeLessThan(1e-9);
    }
    expect(drawMysteryMass(() => 0)).toBe(1);
    expect(drawMysteryMass(() => 1 - 1e-12)).toBe(4);
  });

  it('is found by a guess within 5 % of it, and not by one farther off', () => {
    expect(isMysteryFound(2.09, 2.0)).toBe(true);
    expect(isMysteryFound(1.91, 2.0)).toBe(true);
    expect(isMysteryFound(2.11, 2.0)).toBe(false);
    expect(isMysteryFound(5, 4)).toBe(false);
  });

  it('a track stepped back to mid-run goes on as the run did: the same a, the same stop at the same time', () => {
    const original = createForcesTrack({ mass: 2, force: 3 });
    let finishes = 0;
    startTrack(original, () => finishes++);
    for (let i = 0; i < 30; i++) original.world.step(1 / 60);
    const saved = { snapshot: takeSnapshot(original.world), state: trackState(original) };
    while (original.finishedAt === null) original.world.step(1 / 60);
    expect(finishes).toBe(1);

    let again = 0;
    const back = adoptTrack(original, restoreSnapshot(saved.snapshot), saved.state, () => again++);
    expect(back.world.steps).toBe(30);
    expect(back.square.forces).toHaveLength(1);
    expect(back.finishedAt).toBeNull();
    while (back.finishedAt === null && back.world.steps < 600) {
      back.world.step(1 / 60);
      if (back.finishedAt === null) expect(measuredAcceleration(back)).toBeCloseTo(1.5, 9);
    }
    expect(again).toBe(1);
    expect(back.finishedAt).toBe(original.finishedAt);
    expect(displacement(back)).toBe(displacement(original));
    expect(back.square.forces).toHaveLength(0);
  });

  it('a track stepped back to after its stop stays over: no force, its finish time kept', () => {
    const track = createForcesTrack({ mass: 1, force: 10 });
    startTrack(track);
    while (track.finishedAt === null) track.world.step(1 / 60);
    track.world.step(1 / 60);
    const back = adoptTrack(track, restoreSnapshot(takeSnapshot(track.world)), trackState(track));
    expect(back.finishedAt).toBe(track.finishedAt);
    expect(back.square.forces).toHaveLength(0);
    back.world.step(1 / 60);
    expect(back.square.linearVelocity.x).toBe(0);
  });
});
