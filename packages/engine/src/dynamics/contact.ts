import { CONTACT_STRIDE, FRICTION, RESTITUTION } from './contact-data.ts';
import {
  PAIR_CAPSULE_CIRCLE,
  PAIR_CAPSULES,
  PAIR_CIRCLES,
  PAIR_POLYGON_CAPSULE,
  PAIR_POLYGON_CIRCLE,
  PAIR_POLYGONS,
  PAIR_SEGMENT_CAPSULE,
  PAIR_SEGMENT_CIRCLE,
  PAIR_SEGMENT_POLYGON,
} from './pair-kinds.ts';
import type { Shape } from './shape.ts';
import { MATERIAL_FRICTION, MATERIAL_RESTITUTION, MATERIAL_STRIDE } from './shape-table.ts';

// A contact's pair: which shape is A (the higher-ranked kind: segment > polygon > capsule >
// circle) and which narrow phase applies (pair-kinds.ts). The narrow phase itself, the manifold
// of a pair from the shapes' geometry rows, is the kernel's updateManifold
// (wasm/update-manifold.ts), which the contact manager calls (contact-manager.ts).

const KIND_RANK = { circle: 0, capsule: 1, polygon: 2, segment: 3 } as const;

/** True if two shapes can ever collide (segments never collide with segments). */
export function canCollide(a: Shape, b: Shape): boolean {
  return !(a.geometry.kind === 'segment' && b.geometry.kind === 'segment');
}

/** Orders a pair so that shape A has the higher-ranked kind; returns true if the pair must be swapped. */
export function shouldSwap(a: Shape, b: Shape): boolean {
  return KIND_RANK[a.geometry.kind] < KIND_RANK[b.geometry.kind];
}

/**
 * Sets up contact slot `slot` of `data` for a new pair (a and b already ordered, see shouldSwap),
 * whose numbers the caller has cleared: mixes the materials. Returns the pair kind (which collide
 * function applies). A contact is its slot: its shapes, bodies and kind are in the contact data's
 * flat arrays (contact-data.ts) and its place in each body's contact list in the contact edges
 * (contact-edges.ts); no object stands for it.
 */
export function initContactSlot(slot: number, a: Shape, b: Shape, data: Float64Array): number {
  const base = slot * CONTACT_STRIDE;
  // From the shapes' material rows, not their getters: a getter V8 does not inline returns its
  // double boxed (~1 KB of garbage a step in a tumbling drum of 400 boxes, from the new contacts).
  const ma = a.table.materials;
  const mb = b.table.materials;
  const ra = a.row * MATERIAL_STRIDE;
  const rb = b.row * MATERIAL_STRIDE;
  data[base + FRICTION] = Math.sqrt(ma[ra + MATERIAL_FRICTION]! * mb[rb + MATERIAL_FRICTION]!);
  data[base + RESTITUTION] = Math.max(
    ma[ra + MATERIAL_RESTITUTION]!,
    mb[rb + MATERIAL_RESTITUTION]!,
  );
  const kindA = a.geometry.kind;
  const kindB = b.geometry.kind;
  if (kindA === 'circle') return PAIR_CIRCLES;
  if (kindA === 'capsule') return kindB === 'circle' ? PAIR_CAPSULE_CIRCLE : PAIR_CAPSULES;
  if (kindA === 'polygon') {
    return kindB === 'circle'
      ? PAIR_POLYGON_CIRCLE
      : kindB === 'capsule'
        ? PAIR_POLYGON_CAPSULE
        : PAIR_POLYGONS;
  }
  return kindB === 'circle'
    ? PAIR_SEGMENT_CIRCLE
    : kindB === 'capsule'
      ? PAIR_SEGMENT_CAPSULE
      : PAIR_SEGMENT_POLYGON;
}
