import type { MassData } from './mass-data.ts';
import type { Polygon } from './polygon.ts';
import { hypot } from '../math/hypot.ts';
import { atan2 } from '../math/trigonometry.ts';

/**
 * Mass properties of the polygon at `density` (kg/m^2): mass (kg), centre of mass (body-local, m)
 * and rotational inertia about the centre of mass (kg m^2). Writes and returns `out`.
 *
 * Sharp core: a fan of triangles from a reference point inside the polygon (its first vertex),
 * each contributing area |e1 x e2| / 2, first moment area (e1 + e2) / 3 and polar second moment
 * (|e1 x e2| / 12)(e1.e1 + e1.e2 + e2.e2); working relative to a vertex keeps precision for shapes
 * far from the body origin (the formula Box2D's b2ComputePolygonMass uses).
 *
 * Rounded (radius r > 0), exact rather than Box2D's pushed-out-edges approximation: the shape is
 * the Minkowski sum of the core with a disc, which splits without overlap into the core, one
 * r-thick rectangle on each edge and one circular sector at each vertex (their angles sum to 2 pi),
 * so area = A + P r + pi r^2. For the sector at vertex v between edge normals n0 and n1 (angles
 * alpha, beta), with q measured from v:
 *   area = (beta - alpha) r^2 / 2,   integral of q = (r^3 / 3)(n1.y - n0.y, n0.x - n1.x),
 *   integral of |q|^2 = (beta - alpha) r^4 / 4,
 * and moving to another origin o uses integral |v - o + q|^2 = J_v + 2 (v - o).Q_v + area |v - o|^2.
 * An edge rectangle of length L has area L r, centroid at the edge midpoint + (r/2) n and polar
 * moment about its centroid L r (L^2 + r^2) / 12.
 */
export function computePolygonMass(polygon: Polygon, density: number, out: MassData): MassData {
  const count = polygon.count;
  const vertices = polygon.vertices;
  const normals = polygon.normals;
  const r = polygon.radius;
  // All moments relative to vertex 0 (ox, oy).
  const ox = vertices[0]!;
  const oy = vertices[1]!;
  let area = 0;
  let firstX = 0;
  let firstY = 0;
  let second = 0;
  for (let i = 1; i < count - 1; i++) {
    const e1x = vertices[2 * i]! - ox;
    const e1y = vertices[2 * i + 1]! - oy;
    const e2x = vertices[2 * i + 2]! - ox;
    const e2y = vertices[2 * i + 3]! - oy;
    const cross = e1x * e2y - e1y * e2x;
    const triangleArea = 0.5 * cross;
    area += triangleArea;
    firstX += (triangleArea * (e1x + e2x)) / 3;
    firstY += (triangleArea * (e1y + e2y)) / 3;
    second +=
      (cross / 12) * (e1x * e1x + e1x * e2x + e2x * e2x + e1y * e1y + e1y * e2y + e2y * e2y);
  }
  if (r > 0) {
    for (let i = 0; i < count; i++) {
      const next = i === count - 1 ? 0 : i + 1;
      const previous = i === 0 ? count - 1 : i - 1;
      const vx = vertices[2 * i]! - ox;
      const vy = vertices[2 * i + 1]! - oy;
      const wx = vertices[2 * next]! - ox;
      const wy = vertices[2 * next + 1]! - oy;
      const nx = normals[2 * i]!;
      const ny = normals[2 * i + 1]!;
      // Edge rectangle.
      const length = hypot(wx - vx, wy - vy);
      const rectangleArea = length * r;
      const rectangleX = 0.5 * (vx + wx) + 0.5 * r * nx;
      const rectangleY = 0.5 * (vy + wy) + 0.5 * r * ny;
      area += rectangleArea;
      firstX += rectangleArea * rectangleX;
      firstY += rectangleArea * rectangleY;
      second +=
        (rectangleArea * (length * length + r * r)) / 12 +
        rectangleArea * (rectangleX * rectangleX + rectangleY * rectangleY);
      // Vertex sector between the previous edge's normal and this edge's normal.
      const n0x = normals[2 * previous]!;
      const n0y = normals[2 * previous + 1]!;
      const sweep = atan2(n0x * ny - n0y * nx, n0x * nx + n0y * ny);
      const sectorArea = 0.5 * sweep * r * r;
      const sectorFirstX = ((r * r * r) / 3) * (ny - n0y);
      const sectorFirstY = ((r * r * r) / 3) * (n0x - nx);
      area += sectorArea;
      firstX += sectorFirstX + sectorArea * vx;
      firstY += sectorFirstY + sectorArea * vy;
      second +=
        0.25 * sweep * r * r * r * r +
        2 * (vx * sectorFirstX + vy * sectorFirstY) +
        sectorArea * (vx * vx + vy * vy);
    }
  }
  const mass = density * area;
  const cx = firstX / area;
  const cy = firstY / area;
  out.mass = mass;
  out.centerX = ox + cx;
  out.centerY = oy + cy;
  // Parallel axis theorem, from the reference vertex to the centre of mass.
  out.rotationalInertia = density * (second - area * (cx * cx + cy * cy));
  return out;
}
