import { MAX_POLYGON_VERTICES } from '../core/constants.ts';
import type { Geometry } from './shape.ts';

// Each shape's geometry as a fixed-stride row of doubles in the world's solver memory (the
// SHAPE_GEOMETRY region, solver-memory.ts; the row is the shape id), which the kernel's narrow
// phase (wasm/update-manifold.ts and the wasm/collide-*.ts it calls) reads in place. Geometry is
// immutable once a shape exists, so the row is written once, when the shape joins a table
// (ShapeTable.copyRow), and is not a copy any later write must remember. This file is the one
// definition of the row's layout: the kernel build writes its mirror into wasm/contact-layout.ts.
//
//   G_KIND        GEOMETRY_CIRCLE, _CAPSULE, _POLYGON or _SEGMENT (the pair-ordering rank)
//   G_RADIUS      rounding radius (m): a circle's or capsule's radius, a polygon's rounding, 0 for
//                 a segment (so a two-sided wall collides as a capsule of radius 0)
//   G_COUNT       a polygon's vertex count; 2 for a capsule or segment, 1 for a circle
//   G_CENTROID_X, G_CENTROID_Y   a polygon's centroid (m)
//   G_ONE_SIDED   1 for a one-sided segment, else 0
//   G_VERTICES    x0, y0, x1, y1, ... (2 MAX_POLYGON_VERTICES doubles): a polygon's vertices, a
//                 circle's centre, a capsule's or segment's two points
//   G_NORMALS     a polygon's edge normals, same layout

export const GEOMETRY_CIRCLE = 0;
export const GEOMETRY_CAPSULE = 1;
export const GEOMETRY_POLYGON = 2;
export const GEOMETRY_SEGMENT = 3;

export const G_KIND = 0;
export const G_RADIUS = 1;
export const G_COUNT = 2;
export const G_CENTROID_X = 3;
export const G_CENTROID_Y = 4;
export const G_ONE_SIDED = 5;
export const G_VERTICES = 6;
export const G_NORMALS: number = G_VERTICES + 2 * MAX_POLYGON_VERTICES;
/** Doubles per row (8-byte rows: any stride keeps doubles aligned). */
export const GEOMETRY_STRIDE: number = G_NORMALS + 2 * MAX_POLYGON_VERTICES;

/** Writes geometry `g` into row `row` of `rows` (GEOMETRY_STRIDE doubles a row). */
export function writeGeometryRow(rows: Float64Array, row: number, g: Geometry): void {
  const p = row * GEOMETRY_STRIDE;
  rows.fill(0, p, p + GEOMETRY_STRIDE);
  const v = p + G_VERTICES;
  switch (g.kind) {
    case 'circle':
      rows[p + G_KIND] = GEOMETRY_CIRCLE;
      rows[p + G_RADIUS] = g.radius;
      rows[p + G_COUNT] = 1;
      rows[v] = g.centerX;
      rows[v + 1] = g.centerY;
      break;
    case 'capsule':
      rows[p + G_KIND] = GEOMETRY_CAPSULE;
      rows[p + G_RADIUS] = g.radius;
      rows[p + G_COUNT] = 2;
      rows[v] = g.x1;
      rows[v + 1] = g.y1;
      rows[v + 2] = g.x2;
      rows[v + 3] = g.y2;
      break;
    case 'segment':
      rows[p + G_KIND] = GEOMETRY_SEGMENT;
      rows[p + G_COUNT] = 2;
      rows[p + G_ONE_SIDED] = g.oneSided ? 1 : 0;
      rows[v] = g.x1;
      rows[v + 1] = g.y1;
      rows[v + 2] = g.x2;
      rows[v + 3] = g.y2;
      break;
    default:
      rows[p + G_KIND] = GEOMETRY_POLYGON;
      rows[p + G_RADIUS] = g.radius;
      rows[p + G_COUNT] = g.count;
      rows[p + G_CENTROID_X] = g.centroidX;
      rows[p + G_CENTROID_Y] = g.centroidY;
      for (let i = 0; i < 2 * g.count; i++) {
        rows[v + i] = g.vertices[i]!;
        rows[p + G_NORMALS + i] = g.normals[i]!;
      }
  }
}
