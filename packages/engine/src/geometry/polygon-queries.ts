import type { Transform } from '../math/transform.ts';
import type { AABB } from './aabb.ts';
import type { Polygon } from './polygon.ts';
import type { RayHit, RayInput } from './ray.ts';

/** World-frame bounding box (m) of the polygon placed by `xf`, including its radius. */
export function computePolygonAABB(polygon: Polygon, xf: Transform, out: AABB): AABB {
  const vertices = polygon.vertices;
  const c = xf.c;
  const s = xf.s;
  let minX = Infinity;
  let minY = Infinity;
  let maxX = -Infinity;
  let maxY = -Infinity;
  for (let i = 0; i < polygon.count; i++) {
    const lx = vertices[2 * i]!;
    const ly = vertices[2 * i + 1]!;
    const x = c * lx - s * ly + xf.x;
    const y = s * lx + c * ly + xf.y;
    if (x < minX) minX = x;
    if (y < minY) minY = y;
    if (x > maxX) maxX = x;
    if (y > maxY) maxY = y;
  }
  const r = polygon.radius;
  out.minX = minX - r;
  out.minY = minY - r;
  out.maxX = maxX + r;
  out.maxY = maxY + r;
  return out;
}

/**
 * True when the world point (px, py) (m) lies inside or on the polygon placed by `xf`, rounding
 * included: for radius r > 0 a point outside the core counts when its distance to the core is <= r.
 */
export function polygonContainsPoint(
  polygon: Polygon,
  xf: Transform,
  px: number,
  py: number,
): boolean {
  const dx = px - xf.x;
  const dy = py - xf.y;
  const lx = xf.c * dx + xf.s * dy;
  const ly = -xf.s * dx + xf.c * dy;
  const count = polygon.count;
  const vertices = polygon.vertices;
  const normals = polygon.normals;
  let isInsideCore = true;
  for (let i = 0; i < count; i++) {
    const separation =
      normals[2 * i]! * (lx - vertices[2 * i]!) + normals[2 * i + 1]! * (ly - vertices[2 * i + 1]!);
    if (separation > 0) {
      isInsideCore = false;
      break;
    }
  }
  if (isInsideCore) {
    return true;
  }
  const r = polygon.radius;
  if (r === 0) {
    return false;
  }
  // Outside a convex core, the distance to it is the distance to the nearest edge.
  let best = Infinity;
  for (let i = 0; i < count; i++) {
    const next = i === count - 1 ? 0 : i + 1;
    const d = pointSegmentDistanceSquared(
      lx,
      ly,
      vertices[2 * i]!,
      vertices[2 * i + 1]!,
      vertices[2 * next]!,
      vertices[2 * next + 1]!,
    );
    if (d < best) best = d;
  }
  return best <= r * r;
}

/**
 * Casts a world-frame ray against the polygon placed by `xf`. Returns false on a miss and when
 * the ray starts inside; on a hit writes the fraction, world point (m) and outward unit normal.
 *
 * Sharp polygons: Cyrus-Beck clipping of the ray against the edge half-planes in the polygon's
 * frame (Ericson, Real-Time Collision Detection, 5.3.8). Rounded polygons (radius r > 0), exact:
 * the boundary of core + disc lies on the union of the edges pushed out by r n and the circles of
 * radius r around the vertices, all of which lie inside the shape, so the first entry into the
 * shape is the earliest entering hit among those pieces.
 */
export function rayCastPolygon(
  polygon: Polygon,
  xf: Transform,
  input: RayInput,
  out: RayHit,
): boolean {
  const c = xf.c;
  const s = xf.s;
  // Ray in the polygon's frame: p + t d, t in [0, maxFraction].
  const ox = input.originX - xf.x;
  const oy = input.originY - xf.y;
  const px = c * ox + s * oy;
  const py = -s * ox + c * oy;
  const dx = c * input.translationX + s * input.translationY;
  const dy = -s * input.translationX + c * input.translationY;
  const count = polygon.count;
  const vertices = polygon.vertices;
  const normals = polygon.normals;
  const r = polygon.radius;
  let hitFraction: number;
  let nx = 0;
  let ny = 0;

  if (r === 0) {
    let lower = 0;
    let upper = input.maxFraction;
    let index = -1;
    for (let i = 0; i < count; i++) {
      const ex = normals[2 * i]!;
      const ey = normals[2 * i + 1]!;
      // Inside half-plane i: e.(p + t d - v) <= 0, i.e. t * denominator <= numerator.
      const numerator = ex * (vertices[2 * i]! - px) + ey * (vertices[2 * i + 1]! - py);
      const denominator = ex * dx + ey * dy;
      if (denominator === 0) {
        if (numerator < 0) {
          return false;
        }
      } else if (denominator < 0 && numerator < lower * denominator) {
        lower = numerator / denominator;
        index = i;
      } else if (denominator > 0 && numerator < upper * denominator) {
        upper = numerator / denominator;
      }
      if (upper < lower) {
        return false;
      }
    }
    if (index < 0) {
      return false;
    }
    hitFraction = lower;
    nx = normals[2 * index]!;
    ny = normals[2 * index + 1]!;
  } else {
    if (polygonContainsPoint(polygon, xf, input.originX, input.originY)) {
      return false;
    }
    const dd = dx * dx + dy * dy;
    if (dd === 0) {
      return false;
    }
    let best = Infinity;
    for (let i = 0; i < count; i++) {
      const next = i === count - 1 ? 0 : i + 1;
      const vx = vertices[2 * i]!;
      const vy = vertices[2 * i + 1]!;
      const ex = normals[2 * i]!;
      const ey = normals[2 * i + 1]!;
      // Pushed-out edge, entered only when moving against its normal.
      const denominator = ex * dx + ey * dy;
      if (denominator < 0) {
        const t = (ex * (vx + r * ex - px) + ey * (vy + r * ey - py)) / denominator;
        if (t >= 0 && t < best) {
          const wx = vertices[2 * next]!;
          const wy = vertices[2 * next + 1]!;
          const qx = px + t * dx - vx;
          const qy = py + t * dy - vy;
          const along = qx * (wx - vx) + qy * (wy - vy);
          if (along >= 0 && along <= (wx - vx) * (wx - vx) + (wy - vy) * (wy - vy)) {
            best = t;
            nx = ex;
            ny = ey;
          }
        }
      }
      // Vertex circle: |p - v + t d|^2 = r^2, smaller root.
      const fx = px - vx;
      const fy = py - vy;
      const b = fx * dx + fy * dy;
      const discriminant = b * b - dd * (fx * fx + fy * fy - r * r);
      if (discriminant >= 0 && b < 0) {
        const t = (-b - Math.sqrt(discriminant)) / dd;
        if (t >= 0 && t < best) {
          best = t;
          nx = (fx + t * dx) / r;
          ny = (fy + t * dy) / r;
        }
      }
    }
    if (best > input.maxFraction) {
      return false;
    }
    hitFraction = best;
  }

  const hx = px + hitFraction * dx;
  const hy = py + hitFraction * dy;
  out.fraction = hitFraction;
  out.x = c * hx - s * hy + xf.x;
  out.y = s * hx + c * hy + xf.y;
  out.normalX = c * nx - s * ny;
  out.normalY = s * nx + c * ny;
  return true;
}

function pointSegmentDistanceSquared(
  px: number,
  py: number,
  ax: number,
  ay: number,
  bx: number,
  by: number,
): number {
  const ex = bx - ax;
  const ey = by - ay;
  const lengthSquared = ex * ex + ey * ey;
  let t = ((px - ax) * ex + (py - ay) * ey) / lengthSquared;
  t = t < 0 ? 0 : t > 1 ? 1 : t;
  const dx = px - (ax + t * ex);
  const dy = py - (ay + t * ey);
  return dx * dx + dy * dy;
}
