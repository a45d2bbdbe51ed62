import { requireBoolean, requireRange } from '../../core/validate.ts';
import type { Vec2Like } from '../../math/vec2.ts';
import { Joint, jointMax, requireOrdered, type JointStep } from './joint.ts';
import {
  DELTA_CENTER_X,
  DELTA_CENTER_Y,
  JOINT_ANGLE_0,
  LOCAL_ANCHOR_AX,
  LOCAL_ANCHOR_AY,
  LOCAL_ANCHOR_BX,
  LOCAL_ANCHOR_BY,
  R_AX,
  R_AY,
  R_BX,
  R_BY,
  REFERENCE_ANGLE,
} from './joint-record.ts';

/**
 * The base of the joints between two bodies (revolute, prismatic, distance, weld): what they share
 * and a mouse joint does not (anchors set from world points, the frame prepared each step, the
 * setters of switches and limits). Apart from {@link Joint} so that an app whose only joint is a
 * canvas's drag (a mouse joint) bundles none of it.
 */
export abstract class TwoBodyJoint<UserData = unknown> extends Joint<UserData> {
  /** @internal Sets the local anchors of the world points `anchorA` and `anchorB` now. */
  protected setAnchors(anchorA: Vec2Like, anchorB: Vec2Like): void {
    const localA = this.bodyA.getLocalPoint(anchorA);
    const localB = this.bodyB.getLocalPoint(anchorB);
    const d = this.store.data;
    const o = this.base;
    d[o + LOCAL_ANCHOR_AX] = localA.x;
    d[o + LOCAL_ANCHOR_AY] = localA.y;
    d[o + LOCAL_ANCHOR_BX] = localB.x;
    d[o + LOCAL_ANCHOR_BY] = localB.y;
  }

  /**
   * @internal The setter of a switch named `field`: a change clears the accumulated impulses of
   * its rows (`count` numbers from `cleared`) and wakes the bodies.
   */
  protected setSwitch(
    field: string,
    offset: number,
    value: boolean,
    cleared: number,
    count: number,
  ): void {
    requireBoolean(field, value);
    if (value === this.flag(offset)) return;
    const d = this.store.data;
    d[this.base + offset] = value ? 1 : 0;
    for (let i = 0; i < count; i++) d[this.base + cleared + i] = 0;
    this.wakeBodies();
  }

  /**
   * @internal Sets a limit's two ends (at `offset` and the next), named `lowerField` and
   * `upperField`; an error names the end the user `changed`.
   */
  protected setRange(
    lowerField: string,
    upperField: string,
    offset: number,
    lower: number,
    upper: number,
    changed: 'lower' | 'upper',
  ): void {
    requireRange(lowerField, lower, -jointMax(lowerField), jointMax(lowerField));
    requireRange(upperField, upper, -jointMax(upperField), jointMax(upperField));
    requireOrdered(lowerField, lower, upperField, upper, changed);
    this.write(offset, lower);
    this.write(offset + 1, upper);
    this.wakeBodies();
  }

  /**
   * @internal The frame every two-body kind prepares alike: the bodies (see prepareBodies), the
   * levers from the centres of mass to the anchors in world orientation at the step's start (the
   * sub-steps turn them by each body's rotation since, state Q_C and Q_S), the centres' offset and
   * the joint angle.
   */
  prepareFrame(step: JointStep): void {
    this.prepareBodies(step);
    const d = this.store.data;
    const o = this.base;
    const a = this.bodyA;
    const b = this.bodyB;
    const ta = a.transform;
    const tb = b.transform;
    const lAx = d[o + LOCAL_ANCHOR_AX]! - a.localCenterX;
    const lAy = d[o + LOCAL_ANCHOR_AY]! - a.localCenterY;
    const lBx = d[o + LOCAL_ANCHOR_BX]! - b.localCenterX;
    const lBy = d[o + LOCAL_ANCHOR_BY]! - b.localCenterY;
    d[o + R_AX] = ta.c * lAx - ta.s * lAy;
    d[o + R_AY] = ta.s * lAx + ta.c * lAy;
    d[o + R_BX] = tb.c * lBx - tb.s * lBy;
    d[o + R_BY] = tb.s * lBx + tb.c * lBy;
    d[o + DELTA_CENTER_X] = b.centerX - a.centerX;
    d[o + DELTA_CENTER_Y] = b.centerY - a.centerY;
    d[o + JOINT_ANGLE_0] = b.angleValue - a.angleValue - d[o + REFERENCE_ANGLE]!;
  }
}
