import { describe, expect, it } from 'vitest';
import { reportMeasured } from './measured.ts';
import { World, particle, wall } from '@physical/engine';

// Law 8: Newton's law of restitution. A ball dropped from 1 m onto a wall leaves it at e times the
// impact speed (within 1 %; for e = 0, under 1 % of the impact speed), and so rises to e^2 h
// (within 5 %).
//
// Speeds are taken at the floor's level, by energy, so they do not depend on where in its step the
// ball happened to touch: a ball at height d above its resting height moving at v reaches the floor
// at sqrt(v^2 + 2 g d) (falling) and left it at sqrt(v^2 + 2 g d) (rising). The velocity a body
// reports is its last sub-step's average (semi-implicit Euler moves it by h v); at the step's end
// it moves at that plus g h / 2, and that is the v above.

const DT = 1 / 60;
const G = 9.81;
const DROP = 1;
const RADIUS = 0.1;
const RATIO_TOLERANCE = 0.01;
const APEX_TOLERANCE = 0.05;

interface Bounce {
  impactSpeed: number;
  reboundSpeed: number;
  apexHeight: number;
}

function drop(restitution: number): Bounce {
  const world = new World({ gravity: { x: 0, y: G }, restitutionThreshold: 0 });
  const floorY = 0;
  world.add(wall({ from: { x: -5, y: floorY }, to: { x: 5, y: floorY }, restitution }));
  const restY = floorY - RADIUS; // the ball's centre when it touches the floor
  const ball = world.add(
    particle({ position: { x: 0, y: restY - DROP }, radius: RADIUS, restitution }),
  );
  const speedAtFloor = (): number => {
    const v = ball.linearVelocity.y + (G * DT) / (2 * world.subSteps);
    const height = restY - ball.position.y;
    return Math.sqrt(v * v + 2 * G * Math.max(height, 0));
  };
  let impactSpeed = 0;
  let reboundSpeed = 0;
  let previousSpeedAtFloor = 0;
  let previous = 0;
  let apexY = Infinity;
  for (let i = 0; i < 240; i++) {
    world.step(DT);
    const vy = ball.linearVelocity.y;
    if (impactSpeed === 0 && previous > 0 && vy <= 0) {
      // The step of the bounce: before it the ball was falling, after it it rises (or rests).
      impactSpeed = previousSpeedAtFloor;
      reboundSpeed = vy < 0 ? speedAtFloor() : 0;
    }
    if (impactSpeed > 0) {
      if (vy > 0 && previous <= 0) break; // past the next apex
      apexY = Math.min(apexY, ball.position.y);
    }
    previous = vy;
    previousSpeedAtFloor = speedAtFloor();
  }
  return { impactSpeed, reboundSpeed, apexHeight: restY - apexY };
}

describe('restitution', () => {
  it.each([0.5, 0.8, 1])(
    'rebounds at e times the impact speed and rises to e^2 h (e = %f)',
    (e) => {
      const { impactSpeed, reboundSpeed, apexHeight } = drop(e);
      // Falling 1 m: sqrt(2 g h), up to the integrator's error.
      expect(Math.abs(impactSpeed / Math.sqrt(2 * G * DROP) - 1)).toBeLessThan(RATIO_TOLERANCE);
      const ratioError = Math.abs(reboundSpeed / impactSpeed - e) / e;
      const apexError = Math.abs(apexHeight - e * e * DROP) / (e * e * DROP);
      reportMeasured(
        `8 restitution e = ${e}, rebound/impact relative error`,
        ratioError,
        RATIO_TOLERANCE,
      );
      reportMeasured(`8 restitution e = ${e}, apex relative error`, apexError, APEX_TOLERANCE);
      expect(ratioError).toBeLessThanOrEqual(RATIO_TOLERANCE);
      expect(apexError).toBeLessThanOrEqual(APEX_TOLERANCE);
    },
  );

  it('does not bounce with e = 0', () => {
    const { impactSpeed, reboundSpeed } = drop(0);
    expect(Math.abs(impactSpeed / Math.sqrt(2 * G * DROP) - 1)).toBeLessThan(RATIO_TOLERANCE);
    expect(Math.abs(reboundSpeed)).toBeLessThan(RATIO_TOLERANCE * impactSpeed);
  });
});
