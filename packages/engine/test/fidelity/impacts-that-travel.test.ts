import { describe, expect, it } from 'vitest';
import { reportMeasured } from './measured.ts';
import { World, box, particle } from '@physical/engine';
import {
  DT,
  ballisticPendulumErrors,
  dropOnRestingBalls,
  gasEnergyChange,
  sequentialRebound,
  wedgeEnergyGain,
} from './impact-scenes.ts';

// Laws of impacts that travel (issue #29): an impact that passes through a body already pressed
// (by the ground, by another body) or held (by a joint) keeps momentum, and with e = 1 energy.
// - A ball dropped on a ball resting on the floor, e = 1, rebounds as sequential impacts say
//   (a vertical Newton's cradle): equal masses to the drop height, within 2 %; top:bottom mass
//   ratios 1:2, 1:3, 2:1 and 3:1 to the sequential-impact height, within 2 %; a ball dropped on
//   two equal balls stacked on the floor to the drop height, within 2 %.
// - An elastic gas of unlike masses (e = 1, no friction) under gravity in a closed box keeps its
//   energy within 2 % for 60 s, in each seeded start: 16 balls of 0.1-6 kg in a 10 m box (20
//   starts), 24 balls of 0.1-10 kg in a 6 m box (5 starts), 40 balls of 0.1-6 kg in a 10 m box
//   (3 starts).
// - A light ball wedged between the floor and a heavy one (e = 1): the energy never rises in a step
//   by more than 0.1 %.
// - An elastic ballistic pendulum (a disc hits a rod pinned at one end, e = 1): the rod's angular
//   speed and the disc's speed are the closed form's within 1 %.
// - A resting e = 1 ball on the ground stays put (< 1 cm) and sleeps by 12 s (the resting 20-row
//   pyramid of e = 0.5 boxes is test/fidelity/elastic-by-default.test.ts).

describe('impacts that travel', () => {
  it('a ball dropped on an equal ball resting on the floor (e = 1) rebounds to its drop height', () => {
    const ratio = dropOnRestingBalls(1, 1);
    expect(sequentialRebound(1, 1)).toBeCloseTo(1, 12);
    const error = Math.abs(ratio - 1);
    reportMeasured('ball on a resting equal ball, e = 1: rebound / drop height - 1', error, 0.02);
    expect(error).toBeLessThan(0.02);
  });

  it.each([
    [1, 2],
    [1, 3],
    [2, 1],
    [3, 1],
  ])(
    'a %s kg ball dropped on a %s kg ball resting on the floor rebounds to the sequential-impact height',
    (m1, m2) => {
      // Against the ball's own rebound off the floor (restitution.test.ts's law): the
      // semi-implicit Euler flight loses u h / 2 of height at launch speed u, 2 % of a rebound to
      // a quarter of the drop height, which is the integrator's, not the impact's.
      const expected = sequentialRebound(m1, m2) * dropOnRestingBalls(m1);
      const error = Math.abs(dropOnRestingBalls(m1, m2) - expected) / expected;
      reportMeasured(
        `ball on a resting ball, ${m1}:${m2} kg, e = 1: rebound height, relative error`,
        error,
        0.02,
      );
      expect(error).toBeLessThan(0.02);
    },
  );

  it('a ball dropped on two equal balls stacked on the floor (e = 1) rebounds to its drop height', () => {
    expect(sequentialRebound(1, 1, 1)).toBeCloseTo(1, 12);
    const error = Math.abs(dropOnRestingBalls(1, 1, 1) - 1);
    reportMeasured(
      'ball on two stacked equal balls, e = 1: rebound / drop height - 1',
      error,
      0.02,
    );
    expect(error).toBeLessThan(0.02);
  });

  it.each([
    // balls, box side (m), lightest and heaviest mass (kg), seeds
    [16, 10, 0.1, 6, 20],
    [24, 6, 0.1, 10, 5],
    [40, 10, 0.1, 6, 3],
  ])(
    'an e = 1 gas of %s balls in a %s m box, %s-%s kg, under gravity keeps its energy within 2 % for 60 s, every one of %s starts',
    (count, size, lightest, heaviest, seeds) => {
      const changes: number[] = [];
      for (let seed = 1; seed <= seeds; seed++) {
        changes.push(Math.abs(gasEnergyChange({ seed, balls: count, size, lightest, heaviest })));
      }
      const worst = Math.max(...changes);
      reportMeasured(
        `e = 1 gas, ${count} balls of ${lightest}-${heaviest} kg in a ${size} m box under gravity, worst of ${seeds} starts, energy change in 60 s`,
        worst,
        0.02,
      );
      expect(changes).toHaveLength(seeds);
      expect(worst).toBeLessThan(0.02);
    },
    120_000,
  );

  it('a light ball wedged between the floor and a heavy one (e = 1) never gains more than 0.1 % of the energy in a step', () => {
    // Two wedges: a light ball sliding along the floor into a heavy one that touches the floor (the
    // heavy ball's slope presses it into the floor), and a heavy ball coming down on a light one
    // lying on the floor. Without gravity, so that the energy is all kinetic: under gravity the
    // semi-implicit Euler flight and a bounce's catch-up change the energy between step ends by up
    // to 2 % for a single ball bouncing on the floor, which would hide what the wedge does.
    // The light ball slides in at 17 m/s; the heavy one comes down at 16 / 4 = 4 m/s.
    const worst = Math.max(
      wedgeEnergyGain(0.15, 5.9, 17, 'sliding'),
      wedgeEnergyGain(0.15, 5.9, 16, 'coming down'),
    );
    reportMeasured(
      'light ball wedged under a heavy one, e = 1: largest energy gain in a step',
      worst,
      0.001,
    );
    expect(worst).toBeLessThan(0.001);
  });

  it('an elastic ballistic pendulum (a disc hits a rod pinned at one end) leaves at the closed-form speeds', () => {
    // A 2 m, 2 kg rod hit 1 m below its pin by a 1 kg disc at 3 m/s.
    const [omegaError, discError] = ballisticPendulumErrors({ L: 2, d: 1, M: 2, m: 1, u: 3 });
    reportMeasured(
      'elastic ballistic pendulum: rod angular speed, relative error',
      omegaError,
      0.01,
    );
    reportMeasured('elastic ballistic pendulum: disc speed, relative error', discError, 0.01);
    expect(omegaError).toBeLessThan(0.01);
    expect(discError).toBeLessThan(0.01);
  });

  it('a resting e = 1 ball on the ground stays put and sleeps by 12 s', () => {
    const world = new World();
    world.add(
      box({ type: 'static', position: { x: 0, y: 0.5 }, width: 20, height: 1, restitution: 1 }),
    );
    const ball = world.add(
      particle({ position: { x: 0, y: -0.25 }, radius: 0.25, restitution: 1 }),
    );
    let move = 0;
    let asleepAt = Infinity;
    for (let i = 1; i <= 12 / DT; i++) {
      world.step(DT);
      move = Math.max(move, Math.hypot(ball.position.x, ball.position.y + 0.25));
      if (!ball.isAwake && asleepAt === Infinity) asleepAt = i * DT;
    }
    reportMeasured('resting e = 1 ball: largest move (m)', move, 0.01);
    reportMeasured('resting e = 1 ball: asleep after (s)', asleepAt, 12);
    expect(move).toBeLessThan(0.01);
    expect(asleepAt).toBeLessThanOrEqual(12);
  });
});
