import { describe, expect, it } from 'vitest';
import { reportMeasured } from './measured.ts';
import { World, particle, polygon, regularPolygon } from '@physical/engine';
import type { Body } from '@physical/engine';

// Law 6: 100 circles and polygons collide in zero gravity with no walls for 10 s. Contact impulses
// are equal and opposite at a common point, so total linear momentum is conserved within 1e-9
// relative and angular momentum about the origin, sum of m (r x v) + I w, within 1e-6 relative.

const DT = 1 / 60;
const LINEAR_TOLERANCE = 1e-9;
const ANGULAR_TOLERANCE = 1e-6;

/** Mulberry32: a small seeded PRNG, so the scene is the same on every run. */
function random(seed: number): () => number {
  let a = seed >>> 0;
  return () => {
    a = (a + 0x6d2b79f5) >>> 0;
    let t = a;
    t = Math.imul(t ^ (t >>> 15), t | 1);
    t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
}

function momentum(bodies: readonly Body[]): { px: number; py: number; l: number } {
  let px = 0;
  let py = 0;
  let l = 0;
  for (const body of bodies) {
    const m = body.mass;
    const c = body.centerOfMass;
    const v = body.linearVelocity;
    px += m * v.x;
    py += m * v.y;
    l += m * (c.x * v.y - c.y * v.x) + body.inertia * body.angularVelocity;
  }
  return { px, py, l };
}

describe('momentum conservation', () => {
  it('100 mixed bodies colliding without gravity or walls conserve linear and angular momentum', () => {
    const world = new World({ gravity: { x: 0, y: 0 }, enableSleep: false });
    const rand = random(2024);
    const bodies: Body[] = [];
    // A 10 x 10 grid around (20, 10), everyone heading for the centre, plus a common drift and
    // a swirl so that both momenta are far from zero.
    const centre = { x: 20, y: 10 };
    const drift = { x: 1.5, y: -0.5 };
    for (let i = 0; i < 100; i++) {
      const x = centre.x + 1.6 * ((i % 10) - 4.5);
      const y = centre.y + 1.6 * (Math.floor(i / 10) - 4.5);
      const dx = centre.x - x;
      const dy = centre.y - y;
      const distance = Math.hypot(dx, dy);
      const speed = 2 + 3 * rand();
      const linearVelocity = {
        x: (speed * dx) / distance + drift.x - 0.3 * dy,
        y: (speed * dy) / distance + drift.y + 0.3 * dx,
      };
      const size = 0.25 + 0.3 * rand();
      const material = {
        position: { x, y },
        linearVelocity,
        angularVelocity: 4 * (rand() - 0.5),
        density: 0.5 + 2 * rand(),
        friction: 0.5 * rand(),
        restitution: 0.8 * rand(),
      };
      const kind = i % 3;
      if (kind === 0) bodies.push(world.add(particle({ ...material, radius: size })));
      else if (kind === 1) {
        bodies.push(world.add(regularPolygon({ ...material, sides: 3 + (i % 6), radius: size })));
      } else {
        // A convex polygon from random points on a circle.
        const angles = Array.from({ length: 5 }, () => 2 * Math.PI * rand()).sort((p, q) => p - q);
        const vertices = angles.map((a) => ({ x: size * Math.cos(a), y: size * Math.sin(a) }));
        let body: Body;
        try {
          body = polygon({ ...material, vertices });
        } catch {
          body = regularPolygon({ ...material, sides: 5, radius: size });
        }
        bodies.push(world.add(body));
      }
    }
    let collisions = 0;
    world.on('collision', () => collisions++);
    const start = momentum(bodies);
    const linearScale = Math.hypot(start.px, start.py);
    let worstLinear = 0;
    let worstAngular = 0;
    for (let i = 0; i < 600; i++) {
      world.step(DT);
      const now = momentum(bodies);
      worstLinear = Math.max(
        worstLinear,
        Math.hypot(now.px - start.px, now.py - start.py) / linearScale,
      );
      worstAngular = Math.max(worstAngular, Math.abs(now.l - start.l) / Math.abs(start.l));
    }
    // They really collided: many collision events.
    expect(collisions).toBeGreaterThan(300);
    reportMeasured('6 linear momentum, worst relative error', worstLinear, LINEAR_TOLERANCE);
    reportMeasured('6 angular momentum, worst relative error', worstAngular, ANGULAR_TOLERANCE);
    expect(worstLinear).toBeLessThanOrEqual(LINEAR_TOLERANCE);
    expect(worstAngular).toBeLessThanOrEqual(ANGULAR_TOLERANCE);
  });
});
