import type { Geometry } from '@physical/engine';
import type { Pose } from './pose.ts';

/**
 * Adds the outline of a circle, polygon or capsule, at a body pose, to the context's current path, in
 * world metres. A circle gets a radius line along the body's x axis so its rotation shows.
 * Segments have no area: see {@link appendSegmentPath}. Returns false for a segment.
 *
 * A body-local point p is drawn at pose.xy + R(angle) p, with R the rotation by `angle` (which
 * turns +x towards +y, clockwise on a y-down screen).
 */
export function appendAreaPath(
  context: CanvasRenderingContext2D,
  geometry: Geometry,
  pose: Pose,
  cos: number,
  sin: number,
): boolean {
  if (geometry.kind === 'circle') {
    const x = pose.x + cos * geometry.centerX - sin * geometry.centerY;
    const y = pose.y + sin * geometry.centerX + cos * geometry.centerY;
    const r = geometry.radius;
    context.moveTo(x + r * cos, y + r * sin);
    context.arc(x, y, r, pose.angle, pose.angle + 2 * Math.PI);
    context.lineTo(x, y);
    return true;
  }
  if (geometry.kind === 'polygon') {
    const vertices = geometry.vertices;
    const count = geometry.count;
    const radius = geometry.radius;
    if (radius === 0) {
      for (let i = 0; i < count; i++) {
        const lx = vertices[2 * i]!;
        const ly = vertices[2 * i + 1]!;
        const x = pose.x + cos * lx - sin * ly;
        const y = pose.y + sin * lx + cos * ly;
        if (i === 0) context.moveTo(x, y);
        else context.lineTo(x, y);
      }
      context.closePath();
      return true;
    }
    // Rounded polygon: around each vertex, an arc of the rounding radius from the normal of the
    // edge before it to the normal of the edge after it; the path's implicit lines between arcs
    // are the offset edges. Vertices wind with increasing normal angle, as canvas arcs turn.
    const normals = geometry.normals;
    for (let i = 0; i < count; i++) {
      const previous = i === 0 ? count - 1 : i - 1;
      const lx = vertices[2 * i]!;
      const ly = vertices[2 * i + 1]!;
      const x = pose.x + cos * lx - sin * ly;
      const y = pose.y + sin * lx + cos * ly;
      const from = Math.atan2(normals[2 * previous + 1]!, normals[2 * previous]!) + pose.angle;
      const to = Math.atan2(normals[2 * i + 1]!, normals[2 * i]!) + pose.angle;
      if (i === 0) context.moveTo(x + radius * Math.cos(from), y + radius * Math.sin(from));
      context.arc(x, y, radius, from, to);
    }
    context.closePath();
    return true;
  }
  if (geometry.kind === 'capsule') {
    // Two half circles around the end centres, joined by the sides (the path's implicit lines).
    const x1 = pose.x + cos * geometry.x1 - sin * geometry.y1;
    const y1 = pose.y + sin * geometry.x1 + cos * geometry.y1;
    const x2 = pose.x + cos * geometry.x2 - sin * geometry.y2;
    const y2 = pose.y + sin * geometry.x2 + cos * geometry.y2;
    const r = geometry.radius;
    const axis = Math.atan2(y2 - y1, x2 - x1);
    const side = axis + Math.PI / 2;
    context.moveTo(x2 + r * Math.cos(side - Math.PI), y2 + r * Math.sin(side - Math.PI));
    context.arc(x2, y2, r, side - Math.PI, side);
    context.arc(x1, y1, r, side, side + Math.PI);
    context.closePath();
    return true;
  }
  return false;
}

/** Adds a segment, at a body pose, to the context's current path (world metres). */
export function appendSegmentPath(
  context: CanvasRenderingContext2D,
  geometry: Geometry,
  pose: Pose,
  cos: number,
  sin: number,
): void {
  if (geometry.kind !== 'segment') return;
  context.moveTo(
    pose.x + cos * geometry.x1 - sin * geometry.y1,
    pose.y + sin * geometry.x1 + cos * geometry.y1,
  );
  context.lineTo(
    pose.x + cos * geometry.x2 - sin * geometry.y2,
    pose.y + sin * geometry.x2 + cos * geometry.y2,
  );
}
