import { FILTER_ROW } from '../collision/pair-filter.ts';
import type { AABB } from '../geometry/aabb.ts';
import type { Geometry } from './shape.ts';

// Every number of a shape in one place, by row: in a world the row is the shape id, and the
// world's table is what the contact loops read (contact-manager.ts) without loading a Shape.
// `Shape` is a handle: its getters and setters read and write its row here, so there is no second
// copy to keep in step. A shape outside a world keeps a table of its own (one row), copied into
// the world's table when it joins (Shape.attachTable) and out of it when it leaves, as a body's
// store is (body-memory.ts).
//
// Boxes, stride 8 doubles per row:
//   0 minX, 1 minY, 2 maxX, 3 maxY       tight box at the body's pose (m)
//   4 minX, 5 minY, 6 maxX, 7 maxY       the broad phase's fat box (m)
// Filters, stride 4 int32 per row:
//   0 category bits, 1 mask bits (as int32: `&` reads them so anyway; read back with >>> 0),
//   2 group, 3 sensor (1/0)
// Materials, stride 4 doubles per row (not read by the contact loops, so apart from the boxes):
//   0 density, 1 friction, 2 restitution, 3 free
// Geometry, stride GEOMETRY_STRIDE doubles per row (shape-geometry.ts), which the kernel's narrow
// phase reads: written when the shape joins the table (geometry never changes).
//
// A world's table is views of its solver memory's regions (SHAPE_BOXES, SHAPE_FILTERS,
// SHAPE_MATERIALS, SHAPE_GEOMETRY: solver-memory.ts), which the memory replaces when it moves, as
// it does the body store's; a shape outside a world has a table of plain arrays.
// The box and filter offsets are literals in contact-manager.ts, the one file whose loops read
// them, and in shape.ts's accessors.
export const SHAPE_STRIDE = 8;
/** Int32s per filter row (category, mask, group, sensor): the pair filter's row (pair-filter.ts). */
export const FILTER_STRIDE: number = FILTER_ROW;
export const MATERIAL_STRIDE = 4;
/** A material row's density, friction and restitution. */
export const MATERIAL_DENSITY = 0;
export const MATERIAL_FRICTION = 1;
export const MATERIAL_RESTITUTION = 2;

/** Every shape's boxes, filter, material and geometry, by row (in a world, the shape id). */
/**
 * The world's solver memory as a shape table sees it: it makes room for rows (replacing the
 * table's views) and writes a joining shape's geometry row (shape-geometry.ts). Passed in, not
 * imported, so a page that builds shapes without a world (a worker world's page) does not bundle
 * the geometry rows.
 */
export interface ShapeMemory {
  reserveShapes(rows: number): void;
  writeGeometry(row: number, geometry: Geometry): void;
}

export class ShapeTable {
  /** The boxes; replaced when the table grows (read it at each use). */
  data: Float64Array;
  filters: Int32Array;
  materials: Float64Array;
  /**
   * Each row's geometry numbers (shape-geometry.ts), in a world's table only (the kernel's narrow
   * phase reads them; a shape outside a world has its geometry object alone).
   */
  geometry: Float64Array = new Float64Array(0);
  /** Each row's geometry (null for a free id). */
  readonly geometries: (Geometry | null)[] = [];

  /**
   * Room for `rows` rows at first; {@link reserve} grows it: by itself, or through `memory` (a
   * world's solver memory, which makes room for that many rows and replaces the views).
   */
  constructor(
    rows = 64,
    private readonly memory: ShapeMemory | null = null,
  ) {
    this.data = new Float64Array(SHAPE_STRIDE * rows);
    this.filters = new Int32Array(FILTER_STRIDE * rows);
    this.materials = new Float64Array(MATERIAL_STRIDE * rows);
  }

  /** Makes room for row `id`, keeping what is stored. */
  reserve(id: number): void {
    while (this.geometries.length <= id) this.geometries.push(null);
    if ((id + 1) * SHAPE_STRIDE <= this.data.length) return;
    let rows = Math.max(1, this.data.length / SHAPE_STRIDE);
    while (rows < id + 1) rows *= 2;
    if (this.memory !== null) {
      this.memory.reserveShapes(rows);
      return;
    }
    const grown = new Float64Array(rows * SHAPE_STRIDE);
    grown.set(this.data);
    this.data = grown;
    const filters = new Int32Array(rows * FILTER_STRIDE);
    filters.set(this.filters);
    this.filters = filters;
    const materials = new Float64Array(rows * MATERIAL_STRIDE);
    materials.set(this.materials);
    this.materials = materials;
  }

  /** Copies row `from` of `source` into row `to` of this table (made room for first). */
  copyRow(source: ShapeTable, from: number, to: number): void {
    this.reserve(to);
    this.data.set(
      source.data.subarray(from * SHAPE_STRIDE, (from + 1) * SHAPE_STRIDE),
      to * SHAPE_STRIDE,
    );
    this.filters.set(
      source.filters.subarray(from * FILTER_STRIDE, (from + 1) * FILTER_STRIDE),
      to * FILTER_STRIDE,
    );
    this.materials.set(
      source.materials.subarray(from * MATERIAL_STRIDE, (from + 1) * MATERIAL_STRIDE),
      to * MATERIAL_STRIDE,
    );
    const g = source.geometries[from]!;
    this.geometries[to] = g;
    this.memory?.writeGeometry(to, g);
  }

  /** Stores row `id`'s tight box. */
  setTight(id: number, box: AABB): void {
    const d = this.data;
    const p = id * SHAPE_STRIDE;
    d[p] = box.minX;
    d[p + 1] = box.minY;
    d[p + 2] = box.maxX;
    d[p + 3] = box.maxY;
  }

  /** Stores row `id`'s fat box. */
  setFat(id: number, box: AABB): void {
    const d = this.data;
    const p = id * SHAPE_STRIDE + 4;
    d[p] = box.minX;
    d[p + 1] = box.minY;
    d[p + 2] = box.maxX;
    d[p + 3] = box.maxY;
  }
}

/** A table of one row, for a shape outside a world. */
export function createLocalShapeTable(geometry: Geometry): ShapeTable {
  const table = new ShapeTable(1);
  table.reserve(0);
  table.geometries[0] = geometry;
  return table;
}
