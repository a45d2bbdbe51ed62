/**
 * A line segment in its body's local frame: the thesis's wall. One-sided walls collide only
 * with shapes on their positive side, the side of the normal (y2 - y1, -(x2 - x1)) / length:
 * on a y-down screen a wall drawn left to right faces up.
 */
export interface Segment {
  readonly kind: 'segment';
  x1: number;
  y1: number;
  x2: number;
  y2: number;
  oneSided: boolean;
}
