import type { Body } from '@physical/engine';
import type { Pose } from '../draw/pose.ts';

/**
 * The pose of every body before the last step, so a frame can draw the blend between the last
 * two steps (interpolation) using only the public API: the element snapshots the poses right
 * before it calls `world.step`, and reads the current ones from the bodies.
 *
 * Poses are stored by the body's index in `world.bodies` at snapshot time; a body that moved in
 * the list since (added or removed during the step) is drawn at its current pose.
 */
export class PoseHistory {
  private bodies: Body[] = [];
  private poses = new Float64Array(0);
  private count = 0;

  /** Records the current pose of every body (call before each step). */
  snapshot(bodies: readonly Body[]): void {
    const count = bodies.length;
    if (this.poses.length < 3 * count) {
      this.poses = new Float64Array(Math.max(3 * count, 2 * this.poses.length));
    }
    const poses = this.poses;
    const snapshotBodies = this.bodies;
    for (let i = 0; i < count; i++) {
      const body = bodies[i]!;
      const position = body.position;
      poses[3 * i] = position.x;
      poses[3 * i + 1] = position.y;
      poses[3 * i + 2] = body.angle;
      snapshotBodies[i] = body;
    }
    snapshotBodies.length = count;
    this.count = count;
  }

  /** Forgets every snapshot (a new world, or a teleport that must not be blended). */
  clear(): void {
    this.bodies.length = 0;
    this.count = 0;
  }

  /**
   * The pose to draw body `bodies[index]` at: `alpha` of the way from its snapshot to its current
   * pose (1 = current). Writes and returns `out`.
   */
  interpolate(body: Body, index: number, alpha: number, out: Pose): Pose {
    const position = body.position;
    const angle = body.angle;
    if (alpha >= 1 || index >= this.count || this.bodies[index] !== body || !body.isAwake) {
      out.x = position.x;
      out.y = position.y;
      out.angle = angle;
      return out;
    }
    const poses = this.poses;
    const beta = 1 - alpha;
    out.x = beta * poses[3 * index]! + alpha * position.x;
    out.y = beta * poses[3 * index + 1]! + alpha * position.y;
    out.angle = beta * poses[3 * index + 2]! + alpha * angle;
    return out;
  }
}
