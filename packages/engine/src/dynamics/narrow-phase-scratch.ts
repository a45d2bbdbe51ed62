import { MAX_POLYGON_VERTICES } from '../core/constants.ts';
import { GEOMETRY_STRIDE } from './shape-geometry.ts';

// The kernel's narrow phase (wasm/update-manifold.ts, wasm/collide-*.ts) works in a small fixed
// region of the solver memory (NARROW_PHASE_SCRATCH, solver-memory.ts): the manifold a collide
// function writes before updateManifold moves it into the contact's slot, and the scratch the
// polygon functions transform vertices into. This file is the one definition of its layout; the
// kernel build writes its mirror into wasm/contact-layout.ts.

/** The manifold's unit normal (world frame, from A to B). */
export const M_NORMAL_X = 0;
export const M_NORMAL_Y = 1;
/** Points written, 0 to 2. */
export const M_COUNT = 2;
/** Input: keep points closer than this (m). */
export const M_SPECULATIVE_DISTANCE = 3;
/** The points, M_POINT_STRIDE doubles each: world x, y (m), separation (m), feature id. */
export const M_POINTS = 4;
export const M_POINT_STRIDE = 4;
export const MP_X = 0;
export const MP_Y = 1;
export const MP_SEPARATION = 2;
export const MP_ID = 3;
/** Polygon A's vertices in the polygon kernel's frame (2 MAX_POLYGON_VERTICES doubles). */
export const S_VERTICES_A = 16;
/** Polygon B's vertices and normals in that frame. */
export const S_VERTICES_B: number = S_VERTICES_A + 2 * MAX_POLYGON_VERTICES;
export const S_NORMALS_B: number = S_VERTICES_B + 2 * MAX_POLYGON_VERTICES;
/** A capsule or two-sided wall as a two-vertex polygon: a geometry row (shape-geometry.ts). */
export const S_POLYGON: number = S_NORMALS_B + 2 * MAX_POLYGON_VERTICES;
/** The closest-segment fractions f1 and f2 (closest-segment-fractions.ts). */
export const S_FRACTIONS: number = S_POLYGON + GEOMETRY_STRIDE;
/** A transform (x, y, cos, sin) the tests' collidePair reads, and a second one. */
export const S_TRANSFORM_A: number = S_FRACTIONS + 2;
export const S_TRANSFORM_B: number = S_TRANSFORM_A + 4;
/** Why the kernel's collideContacts stopped at a slot (GATE_DESTROY, ... in contact-gates.ts). */
export const GATE_ACTION: number = S_TRANSFORM_B + 4;
/** Doubles of the region. */
export const NARROW_PHASE_SCRATCH_DOUBLES: number = GATE_ACTION + 1;
