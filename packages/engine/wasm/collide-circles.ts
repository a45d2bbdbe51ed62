// Ported from src/collision/collide-circles.ts (issue #30): the one source of this narrow phase.
import { B_C, B_S, B_X, B_Y, G_RADIUS, G_VERTICES } from './contact-layout';
import { ld } from './load-store';
import {
  makeFeatureId,
  setPointCount,
  speculativeDistanceOf,
  writeWorldNormal,
  writeWorldPoint,
} from './manifold';

/**
 * Contact between two circles (geometry rows `a`, `b` at transforms `xfA`, `xfB`): at most one
 * point, on the line of centres, midway between the surfaces, with separation
 * |cB - cA| - rA - rB (m). Coincident centres use the fixed normal (1, 0) so the result is never
 * NaN. Writes the manifold at `m`; the normal points from A to B (world frame).
 */
export function collideCircles(a: usize, xfA: usize, b: usize, xfB: usize, m: usize): void {
  const speculativeDistance = speculativeDistanceOf(m);
  const cA = ld(xfA, B_C);
  const sA = ld(xfA, B_S);
  const cB = ld(xfB, B_C);
  const sB = ld(xfB, B_S);
  const aX = ld(a, G_VERTICES);
  const aY = ld(a, G_VERTICES + 1);
  const bX = ld(b, G_VERTICES);
  const bY = ld(b, G_VERTICES + 1);
  const rA = ld(a, G_RADIUS);
  const rB = ld(b, G_RADIUS);
  // Centres relative to A's origin, world orientation.
  const ax = cA * aX - sA * aY;
  const ay = sA * aX + cA * aY;
  const bx = cB * bX - sB * bY + ld(xfB, B_X) - ld(xfA, B_X);
  const by = sB * bX + cB * bY + ld(xfB, B_Y) - ld(xfA, B_Y);
  const dx = bx - ax;
  const dy = by - ay;
  const distance = Math.sqrt(dx * dx + dy * dy);
  const separation = distance - rA - rB;
  if (separation >= speculativeDistance) {
    setPointCount(m, 0);
    return;
  }
  let nx: f64 = 1;
  let ny: f64 = 0;
  if (distance > 0) {
    nx = dx / distance;
    ny = dy / distance;
  }
  // Midway between A's surface point a + rA n and B's surface point b - rB n.
  const along = 0.5 * (rA - rB + distance);
  const pointX = ax + along * nx;
  const pointY = ay + along * ny;
  writeWorldNormal(m, nx, ny);
  setPointCount(m, 1);
  writeWorldPoint(
    m,
    0,
    pointX + ld(xfA, B_X),
    pointY + ld(xfA, B_Y),
    separation,
    makeFeatureId(0, 0),
  );
}
