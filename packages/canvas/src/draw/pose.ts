/** A body's pose for drawing: origin (m, world, y-down) and rotation (rad, clockwise on screen). */
export interface Pose {
  x: number;
  y: number;
  angle: number;
}
