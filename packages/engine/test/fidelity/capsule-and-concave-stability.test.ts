import { describe, expect, it } from 'vitest';
import { reportMeasured } from './measured.ts';
import { World, box, capsule, particle, polygon, wall } from '@physical/engine';
import type { Body } from '@physical/engine';

// Stability of the new shapes in a y-down world with g = 9.81 m/s^2:
// - a concave U bucket (one body, several convex parts) catches a ball and holds it;
// - a pill lying on a 30 degree incline does not roll: with mu = 0.7 > tan 30 it stays, with
//   mu = 0.2 it slides with a = g (sin - mu cos) within 2 %, as a box does (law 10);
// - a pill resting flat on the ground, on a rounded box and on another pill settles without
//   jitter: its speed stays below 1e-3 m/s once settled (sleep off, so it cannot hide jitter).

const DT = 1 / 60;
const G = 9.81;

function maxSpeedAfterSettling(
  world: World,
  bodies: Body[],
  settle: number,
  watch: number,
): number {
  for (let i = 0; i < settle / DT; i++) world.step(DT);
  let worst = 0;
  for (let i = 0; i < watch / DT; i++) {
    world.step(DT);
    for (const body of bodies) {
      worst = Math.max(worst, Math.hypot(body.linearVelocity.x, body.linearVelocity.y));
    }
  }
  return worst;
}

describe('concave and capsule stability', () => {
  it('a concave U bucket holds a ball dropped into it', () => {
    const world = new World({ gravity: { x: 0, y: G }, enableSleep: false });
    world.add(wall({ from: { x: -10, y: 0 }, to: { x: 10, y: 0 } }));
    // A U 2 m wide and 1 m tall with 0.1 m walls, opening upwards (towards -y).
    const bucket = world.add(
      polygon({
        position: { x: 0, y: -0.5 },
        vertices: [
          { x: -1, y: -0.5 },
          { x: -0.9, y: -0.5 },
          { x: -0.9, y: 0.4 },
          { x: 0.9, y: 0.4 },
          { x: 0.9, y: -0.5 },
          { x: 1, y: -0.5 },
          { x: 1, y: 0.5 },
          { x: -1, y: 0.5 },
        ],
      }),
    );
    expect(bucket.shapes.length).toBeGreaterThan(1);
    const ball = world.add(
      particle({ position: { x: 0.3, y: -3 }, radius: 0.2, restitution: 0.3, density: 0.5 }),
    );
    // The ball may keep rolling slowly on the flat floor (nothing stops a rolling ball), so only
    // the bucket's calm is asserted.
    const worst = maxSpeedAfterSettling(world, [bucket], 4, 2);
    const local = bucket.getLocalPoint(ball.position);
    // Inside: between the walls, on the floor (its top at y = 0.4 - 0.2 m radius).
    const outside = Math.max(Math.abs(local.x) + 0.2 - 0.9, Math.abs(local.y - 0.2));
    reportMeasured(
      'U bucket holds a ball: distance outside its resting place (m)',
      Math.max(0, outside),
      0.01,
    );
    expect(outside).toBeLessThan(0.01);
    expect(Math.abs(bucket.angle)).toBeLessThan(1e-3);
    expect(worst).toBeLessThan(1e-3);
  });

  function incline(mu: number): {
    world: World;
    pill: Body;
    along: () => number;
    speed: () => number;
  } {
    const angle = Math.PI / 6;
    const c = Math.cos(angle);
    const s = Math.sin(angle);
    const world = new World({ gravity: { x: 0, y: G }, enableSleep: false });
    world.add(
      wall({ from: { x: -40 * c, y: -40 * s }, to: { x: 40 * c, y: 40 * s }, friction: mu }),
    );
    const r = 0.2;
    const pill = world.add(
      capsule({
        position: { x: -2 * c + r * s, y: -2 * s - r * c },
        angle,
        length: 0.8,
        radius: r,
        friction: mu,
      }),
    );
    const origin = { x: pill.position.x, y: pill.position.y };
    return {
      world,
      pill,
      along: () => (pill.position.x - origin.x) * c + (pill.position.y - origin.y) * s,
      speed: () => pill.linearVelocity.x * c + pill.linearVelocity.y * s,
    };
  }

  it('a pill with mu = 0.7 stays on a 30 degree incline, lying flat', () => {
    const { world, pill, along } = incline(0.7);
    for (let i = 0; i < 5 / DT; i++) world.step(DT);
    reportMeasured('pill on incline mu = 0.7, drift in 5 s (m)', Math.abs(along()), 1e-3);
    expect(Math.abs(along())).toBeLessThan(1e-3);
    expect(Math.abs(pill.angle - Math.PI / 6)).toBeLessThan(1e-3);
  });

  it('a pill with mu = 0.2 slides, not rolls, with a = g (sin - mu cos)', () => {
    const mu = 0.2;
    const { world, pill, along, speed } = incline(mu);
    const angle = Math.PI / 6;
    const expected = G * (Math.sin(angle) - mu * Math.cos(angle));
    for (let i = 0; i < 30; i++) world.step(DT);
    const v0 = speed();
    const x0 = along();
    const steps = 120;
    let spin = 0;
    for (let i = 0; i < steps; i++) {
      world.step(DT);
      spin = Math.max(spin, Math.abs(pill.angularVelocity));
    }
    const t = steps * DT;
    const fromDistance = (2 * (along() - x0 - v0 * t)) / (t * t);
    const error = Math.abs(fromDistance - expected) / expected;
    reportMeasured('pill on incline mu = 0.2, acceleration relative error', error, 0.02);
    expect(error).toBeLessThanOrEqual(0.02);
    // A rolling disc would gain a spin of 2 a t / (3 r); the pill keeps its flat side down.
    expect(spin).toBeLessThan(1e-2);
  });

  it('pills resting flat on the ground, a rounded box and each other do not jitter', () => {
    const world = new World({ gravity: { x: 0, y: G }, enableSleep: false });
    world.add(wall({ from: { x: -10, y: 0 }, to: { x: 10, y: 0 } }));
    world.add(
      box({ type: 'static', position: { x: 4, y: -0.25 }, width: 2, height: 0.3, radius: 0.1 }),
    );
    const onGround = world.add(capsule({ position: { x: -3, y: -0.3 }, length: 1, radius: 0.25 }));
    const onBox = world.add(capsule({ position: { x: 4, y: -0.85 }, length: 1, radius: 0.25 }));
    const bottom = world.add(capsule({ position: { x: 0, y: -0.3 }, length: 1.2, radius: 0.25 }));
    const top = world.add(capsule({ position: { x: 0.2, y: -0.85 }, length: 0.8, radius: 0.25 }));
    const pills = [onGround, onBox, bottom, top];
    const worst = maxSpeedAfterSettling(world, pills, 3, 3);
    reportMeasured('resting pills: max speed after settling (m/s)', worst, 1e-3);
    expect(worst).toBeLessThan(1e-3);
    // They rest flat where they were put down.
    for (const pill of pills) expect(Math.abs(pill.angle)).toBeLessThan(1e-3);
    expect(top.position.y).toBeCloseTo(bottom.position.y - 0.5, 2);
  });

  it('a pill thrown at 100 m/s does not tunnel through a 5 cm static plate', () => {
    const world = new World({ gravity: { x: 0, y: 0 } });
    world.add(box({ type: 'static', position: { x: 0, y: 0 }, width: 0.05, height: 4 }));
    // 100 m/s covers 1.67 m per step, over thirty times the plate's thickness.
    const pill = world.add(
      capsule({
        position: { x: -3, y: 0 },
        length: 0.4,
        radius: 0.1,
        linearVelocity: { x: 100, y: 0 },
        angle: 0.3,
      }),
    );
    for (let i = 0; i < 30; i++) world.step(DT);
    const passed = pill.position.x > 0 ? pill.position.x : 0;
    reportMeasured('pill at 100 m/s against a 5 cm plate, distance passed through (m)', passed, 0);
    expect(pill.position.x).toBeLessThan(0);
  });
});
