import { MAX_POLYGON_VERTICES } from '../core/constants.ts';

/**
 * A convex polygon in its body's local frame, vertices in counter-clockwise order in the
 * mathematical sense (positive signed area in x, y; on a y-down screen that looks clockwise).
 * `radius` > 0 rounds it (a rounded box); 0 is a sharp polygon.
 */
export interface Polygon {
  readonly kind: 'polygon';
  /** Number of vertices, 3..MAX_POLYGON_VERTICES. */
  count: number;
  /** x0, y0, x1, y1, ... (m), length 2 * MAX_POLYGON_VERTICES; only the first 2 * count are used. */
  readonly vertices: Float64Array;
  /** Outward unit normal of edge i (from vertex i to vertex i + 1), same layout as vertices. */
  readonly normals: Float64Array;
  /** Centroid of the area (m). */
  centroidX: number;
  centroidY: number;
  /** Rounding radius (m), >= 0. */
  radius: number;
}

export function createEmptyPolygon(): Polygon {
  return {
    kind: 'polygon',
    count: 0,
    vertices: new Float64Array(2 * MAX_POLYGON_VERTICES),
    normals: new Float64Array(2 * MAX_POLYGON_VERTICES),
    centroidX: 0,
    centroidY: 0,
    radius: 0,
  };
}
