import type { AABB } from '../geometry/aabb.ts';
import type { Geometry } from './shape.ts';

// What the contact loops need of every shape in a world, by shape id, kept beside the Shape
// objects so those loops read numbers instead of loading each contact's Shape, AABB and geometry
// (contact-manager.ts). Copies: Shape stays what the rest of the engine reads, and every write to
// what is copied writes here too (Shape.computeAABB, Shape.fatAABBChanged, Shape's filter
// setter; all of it when the shape joins the world, Shape.attachTable).
//
// Boxes, stride 8 doubles per shape id:
//   0 minX, 1 minY, 2 maxX, 3 maxY       tight box at the body's pose (m)
//   4 minX, 5 minY, 6 maxX, 7 maxY       the broad phase's fat box (m)
// Filters, stride 4 int32 per shape id:
//   0 category bits, 1 mask bits (as int32: `&` reads them so anyway), 2 group, 3 sensor (1/0)
// The offsets are literals in contact-manager.ts, the one file whose loops read them.
export const SHAPE_STRIDE = 8;
export const FILTER_STRIDE = 4;

/** Every shape's boxes, filter and geometry in a world, by shape id. */
export class ShapeTable {
  data: Float64Array = new Float64Array(SHAPE_STRIDE * 64);
  filters: Int32Array = new Int32Array(FILTER_STRIDE * 64);
  /** Each shape's geometry by shape id (null for a free id). */
  readonly geometries: (Geometry | null)[] = [];

  /** Makes room for shape id `id`, keeping what is stored. */
  reserve(id: number): void {
    while (this.geometries.length <= id) this.geometries.push(null);
    if ((id + 1) * SHAPE_STRIDE <= this.data.length) return;
    let size = this.data.length;
    while (size < (id + 1) * SHAPE_STRIDE) size *= 2;
    const grown = new Float64Array(size);
    grown.set(this.data);
    this.data = grown;
    const filters = new Int32Array((size / SHAPE_STRIDE) * FILTER_STRIDE);
    filters.set(this.filters);
    this.filters = filters;
  }

  /** Stores shape `id`'s tight box. */
  setTight(id: number, box: AABB): void {
    const d = this.data;
    const p = id * SHAPE_STRIDE;
    d[p] = box.minX;
    d[p + 1] = box.minY;
    d[p + 2] = box.maxX;
    d[p + 3] = box.maxY;
  }

  /** Stores shape `id`'s fat box. */
  setFat(id: number, box: AABB): void {
    const d = this.data;
    const p = id * SHAPE_STRIDE + 4;
    d[p] = box.minX;
    d[p + 1] = box.minY;
    d[p + 2] = box.maxX;
    d[p + 3] = box.maxY;
  }

  /** Stores shape `id`'s filter and whether it is a sensor. */
  setFilter(id: number, category: number, mask: number, group: number, sensor: boolean): void {
    const f = this.filters;
    const p = id * FILTER_STRIDE;
    f[p] = category;
    f[p + 1] = mask;
    f[p + 2] = group;
    f[p + 3] = sensor ? 1 : 0;
  }
}
