import { describe, expect, it } from 'vitest';
import {
  arrowLength,
  createForcesTrack,
  displacement,
  drawMysteryMass,
  forceFor,
  isMysteryFound,
  MYSTERY_MAX,
  MYSTERY_MIN,
  opacityFor,
  startTrack,
} from '../src/screens/forces/forces-scene.ts';

describe('Forces scene', () => {
  it('computes F = m a', () => {
    expect(forceFor(1, 2)).toBe(2);
    expect(forceFor(2, 2)).toBe(4);
    expect(forceFor(0.5, 3)).toBe(1.5);
    expect(createForcesTrack({ mass: 2, acceleration: 2 }).force).toBe(4);
  });

  it('gives the square the mass the learner set', () => {
    expect(createForcesTrack({ mass: 2.5, acceleration: 1 }).square.mass).toBeCloseTo(2.5, 12);
  });

  it('draws heavier squares more opaque and bigger forces longer', () => {
    expect(opacityFor(1)).toBeLessThan(opacityFor(2));
    expect(opacityFor(5)).toBe(1);
    expect(arrowLength(4)).toBeCloseTo(2 * arrowLength(2), 12);
  });

  it('moves (1 kg, 2 N) and (2 kg, 4 N) together: same x within 1 mm after 1 s', () => {
    const light = createForcesTrack({ mass: 1, acceleration: 2 });
    const heavy = createForcesTrack({ mass: 2, acceleration: 2 });
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
    const track = createForcesTrack({ mass: 1, acceleration: 2 });
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
});
