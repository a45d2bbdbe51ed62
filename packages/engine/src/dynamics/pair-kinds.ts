// The narrow-phase table: which collide function handles a pair of shape kinds, with shape A the
// higher-ranked kind (segment > polygon > capsule > circle). A contact slot stores its pair kind
// (contact-data.ts); the kernel's updateManifold (wasm/update-manifold.ts) switches on it. One
// definition: the kernel build writes the mirror into wasm/contact-layout.ts.
export const PAIR_CIRCLES = 0;
export const PAIR_POLYGON_CIRCLE = 1;
export const PAIR_POLYGONS = 2;
export const PAIR_SEGMENT_CIRCLE = 3;
export const PAIR_SEGMENT_POLYGON = 4;
export const PAIR_CAPSULE_CIRCLE = 5;
export const PAIR_CAPSULES = 6;
export const PAIR_POLYGON_CAPSULE = 7;
export const PAIR_SEGMENT_CAPSULE = 8;
