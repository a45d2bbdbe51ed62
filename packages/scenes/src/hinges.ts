import { type Body, type Vec2Like, type World, revoluteJoint } from '@physical/engine';

/** A hinge's anchor as each body saw it when joined: they should stay one point. */
export interface HingeRecord {
  readonly a: Body;
  readonly b: Body;
  readonly localA: Vec2Like;
  readonly localB: Vec2Like;
}

/** Adds a revolute joint at `anchor` and records the anchor in both bodies' frames. */
export function hinge(
  world: World,
  hinges: HingeRecord[],
  a: Body,
  b: Body,
  anchor: Vec2Like,
  options: Omit<Parameters<typeof revoluteJoint>[0], 'bodyA' | 'bodyB' | 'anchor'> = {},
): void {
  world.addJoint(revoluteJoint({ ...options, bodyA: a, bodyB: b, anchor }));
  hinges.push({ a, b, localA: a.getLocalPoint(anchor), localB: b.getLocalPoint(anchor) });
}

/** The largest distance (m) between the two sides of any recorded hinge. */
export function largestHingeGap(hinges: readonly HingeRecord[]): number {
  let gap = 0;
  for (const { a, b, localA, localB } of hinges) {
    const pa = a.getWorldPoint(localA);
    const pb = b.getWorldPoint(localB);
    gap = Math.max(gap, Math.hypot(pa.x - pb.x, pa.y - pb.y));
  }
  return gap;
}
