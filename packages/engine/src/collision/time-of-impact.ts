import { LINEAR_SLOP } from '../core/constants.ts';
import { Transform } from '../math/transform.ts';
import type { DistanceProxy } from './distance.ts';
import { coreResult, gjkCores } from './distance.ts';

// Time of impact by conservative advancement (Brian Mirtich, "Impulse-based Dynamic Simulation
// of Rigid Body Systems", PhD thesis, 1996, section 2.3; Erin Catto, "Continuous Collision",
// GDC 2013).
//
// Over the step each body's centre of mass moves linearly and its angle changes linearly in the
// fraction t. At time t GJK gives the core distance d and the unit direction n from A's closest
// point to B's. For any later time the separation of the two cores along the fixed axis n is a
// lower bound on their distance, and it shrinks no faster than
//   rate = (vA - vB) . n + |wA| rA + |wB| rB
// where v is a centre's displacement over the step (m), w the angle change (rad) and r the
// largest distance from the centre of mass to a core vertex (m): a point at r from the centre
// moves at most |w| r. So the cores cannot reach the target distance before
//   t + (d - target) / rate,
// and advancing to that time never passes the first contact. Iterating converges on the time
// at which d = target; if the rate is not positive the shapes separate along n for the rest
// of the step.
//
// The target is the core distance at which the swollen shapes overlap by LINEAR_SLOP (but the
// cores stay at least LINEAR_SLOP apart): the solver then holds the contact without the shapes
// ever interpenetrating deeply, and GJK never works on touching cores.

/** Iteration cap. Each iteration is one GJK call; typical hits converge in 2 to 6. */
const MAX_ITERATIONS = 50;

/**
 * A body's motion over one step, as the time-of-impact query sees it: the centre of mass
 * moves in a straight line and the angle changes uniformly with the fraction t in [0, 1].
 */
export class Sweep {
  /** Centre of mass in the body frame (m). */
  localCenterX = -0;
  localCenterY = -0;
  /** World centre of mass at t = 0 (m). */
  c1X = -0;
  c1Y = -0;
  /** World centre of mass at t = 1 (m). */
  c2X = -0;
  c2Y = -0;
  /** Body angle at t = 0 (rad). */
  a1 = -0;
  /** Body angle at t = 1 (rad). */
  a2 = -0;
}

/** State of a time-of-impact result. */
export type TimeOfImpactState = 'unknown' | 'failed' | 'overlapped' | 'hit' | 'separated';

/** Result of timeOfImpact. */
export class TimeOfImpactOutput {
  /**
   * 'hit': the shapes reach the target separation at `fraction`; 'separated': they stay apart
   * up to maxFraction; 'overlapped': their cores already overlap at `fraction` (continuous
   * collision cannot help); 'failed': the iteration cap was reached, `fraction` is the last
   * time known to be safe.
   */
  state: TimeOfImpactState = 'unknown';
  /** Fraction of the step (dimensionless, 0..maxFraction) at which the state holds. */
  fraction = -0;
}

/**
 * Writes the body's transform at fraction `t` of the sweep into `out` (world frame, m and rad):
 * the centre and angle interpolated linearly, and origin = centre - R(angle) localCenter.
 * Returns `out`.
 */
export function getSweepTransform(sweep: Sweep, t: number, out: Transform): Transform {
  const s = 1 - t;
  const cx = s * sweep.c1X + t * sweep.c2X;
  const cy = s * sweep.c1Y + t * sweep.c2Y;
  const angle = s * sweep.a1 + t * sweep.a2;
  return out.setFromCenter(cx, cy, angle, sweep.localCenterX, sweep.localCenterY);
}

/** Largest distance from the sweep's centre of mass to a core vertex of the proxy (m). */
function maxCoreRadius(proxy: DistanceProxy, sweep: Sweep): number {
  const v = proxy.vertices;
  let maxSquared = 0;
  for (let i = 0; i < proxy.count; i++) {
    const dx = v[2 * i]! - sweep.localCenterX;
    const dy = v[2 * i + 1]! - sweep.localCenterY;
    const squared = dx * dx + dy * dy;
    if (squared > maxSquared) {
      maxSquared = squared;
    }
  }
  return Math.sqrt(maxSquared);
}

const xfA = new Transform();
const xfB = new Transform();

/**
 * Finds the first fraction t in [0, maxFraction] of the step at which the shapes of proxies A
 * and B, moving along their sweeps, come within the target separation: the surfaces overlap by
 * LINEAR_SLOP, or for sharp shapes the cores are LINEAR_SLOP apart (within LINEAR_SLOP / 4).
 * Writes the state and fraction to `out`. Allocates nothing.
 */
export function timeOfImpact(
  proxyA: DistanceProxy,
  sweepA: Sweep,
  proxyB: DistanceProxy,
  sweepB: Sweep,
  maxFraction: number,
  out: TimeOfImpactOutput,
): void {
  const totalRadius = proxyA.radius + proxyB.radius;
  const target = Math.max(LINEAR_SLOP, totalRadius - LINEAR_SLOP);
  const tolerance = 0.25 * LINEAR_SLOP;

  // v: relative displacement of B's centre with respect to A's over the whole step (m);
  // the angular bound |w| r per body (m).
  const vx = sweepB.c2X - sweepB.c1X - (sweepA.c2X - sweepA.c1X);
  const vy = sweepB.c2Y - sweepB.c1Y - (sweepA.c2Y - sweepA.c1Y);
  const angularBound =
    Math.abs(sweepA.a2 - sweepA.a1) * maxCoreRadius(proxyA, sweepA) +
    Math.abs(sweepB.a2 - sweepB.a1) * maxCoreRadius(proxyB, sweepB);

  let t = 0;
  for (let iteration = 0; iteration < MAX_ITERATIONS; iteration++) {
    getSweepTransform(sweepA, t, xfA);
    getSweepTransform(sweepB, t, xfB);
    const distance = gjkCores(proxyA, xfA, proxyB, xfB);

    if (distance <= 0) {
      out.state = 'overlapped';
      out.fraction = t;
      return;
    }
    if (distance < target + tolerance) {
      out.state = 'hit';
      out.fraction = t;
      return;
    }

    const nx = (coreResult.pointBX - coreResult.pointAX) / distance;
    const ny = (coreResult.pointBY - coreResult.pointAY) / distance;
    const rate = -(vx * nx + vy * ny) + angularBound;
    if (rate <= 0) {
      out.state = 'separated';
      out.fraction = maxFraction;
      return;
    }
    t += (distance - target) / rate;
    if (t >= maxFraction) {
      out.state = 'separated';
      out.fraction = maxFraction;
      return;
    }
  }
  out.state = 'failed';
  out.fraction = t;
}
