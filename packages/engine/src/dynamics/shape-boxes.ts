import type { AABB } from '../geometry/aabb.ts';
import type { Geometry } from './shape.ts';

// Every shape's tight and fat boxes, by shape id, so the narrow phase's gates read numbers, not
// each contact's Shape and AABB objects (contact-manager.ts); and each shape's geometry, so the
// full narrow phase reaches it without the Contact and Shape objects. A copy: Shape.aabb and
// Shape.fatAABB stay the boxes the rest of the engine reads, and every write to them writes
// here too (Shape.computeAABB, Shape.fatAABBChanged). Layout per shape id, stride 8 doubles:
//   0 minX, 1 minY, 2 maxX, 3 maxY       tight box at the body's pose (m)
//   4 minX, 5 minY, 6 maxX, 7 maxY       the broad phase's fat box (m)
// The offsets are literals in contact-manager.ts, the one loop that reads them.
export const BOXES_STRIDE = 8;

/** The flat copy of every shape's boxes in a world, by shape id. */
export class ShapeBoxes {
  data: Float64Array = new Float64Array(BOXES_STRIDE * 64);
  /** Each shape's geometry by shape id (null for a free id). */
  readonly geometries: (Geometry | null)[] = [];

  /** Makes room for shape id `id`, keeping what is stored. */
  reserve(id: number): void {
    if ((id + 1) * BOXES_STRIDE <= this.data.length) return;
    let size = this.data.length;
    while (size < (id + 1) * BOXES_STRIDE) size *= 2;
    const grown = new Float64Array(size);
    grown.set(this.data);
    this.data = grown;
  }

  /** Stores shape `id`'s tight box. */
  setTight(id: number, box: AABB): void {
    const d = this.data;
    const p = id * BOXES_STRIDE;
    d[p] = box.minX;
    d[p + 1] = box.minY;
    d[p + 2] = box.maxX;
    d[p + 3] = box.maxY;
  }

  /** Stores shape `id`'s fat box. */
  setFat(id: number, box: AABB): void {
    const d = this.data;
    const p = id * BOXES_STRIDE + 4;
    d[p] = box.minX;
    d[p + 1] = box.minY;
    d[p + 2] = box.maxX;
    d[p + 3] = box.maxY;
  }
}
