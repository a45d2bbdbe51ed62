// The broad-phase boxes, the one source of the speculative box: per awake body of a step's finalize
// that is not due a sweep (shapeBounds), and per body outside it (bodyBounds: a teleport, a swept
// body's new pose, a shape joining), each shape's tight box at the body's pose (from its geometry
// row, shape-geometry.ts), written into the shape's row of SHAPE_BOXES, then grown by the
// speculative distance and the body's motion in the next step (Box2D v3 computes the same box
// while finalizing bodies, "b2FinalizeBodiesTask"). The shapes whose grown box left their fat box
// (SHAPE_BOXES' fat box, which the broad phase's tree holds too) are listed with that box
// (ESCAPED_SHAPES, solver-memory.ts) for the TypeScript (src/dynamics/body-bounds.ts), which moves
// their proxies in the JavaScript trees. Built to WebAssembly and by wasm2js to JavaScript
// (scripts/contact-kernel-build.ts). The tight boxes are the geometry files' compute*AABB (the
// queries' and sensors' boxes) operation for operation, so bit-identical: `Math.min`/`max` are
// f64.min/max, which order -0 as JavaScript does.
import {
  AABB_MARGIN,
  A_BOUNDS_DT,
  BODY_STRIDE,
  B_C,
  B_MAX_EXTENT,
  B_S,
  B_SHAPE_HEAD,
  B_VX,
  B_VY,
  B_W,
  B_X,
  B_Y,
  ESCAPE_STRIDE,
  GEOMETRY_CIRCLE,
  GEOMETRY_CAPSULE,
  GEOMETRY_POLYGON,
  GEOMETRY_STRIDE,
  G_COUNT,
  G_KIND,
  G_RADIUS,
  G_VERTICES,
  SHAPE_STRIDE,
  SPECULATIVE_DISTANCE,
} from './contact-layout';
import { ld, st } from './load-store';

/**
 * The shapes of the body whose numbers are at `b` (its chain, or shape `only` alone), listed from
 * entry `escapes` of `escaped` when their grown box left the fat box (or always, with `every` 1);
 * returns the new number of entries. The one source of the speculative box; a function of its own
 * (not inlined), so the module holds it once for both entries.
 */
function bodyBoxes(
  b: usize,
  only: i32,
  boxes: usize,
  geometry: usize,
  next: usize,
  dt: f64,
  escaped: usize,
  escapes: i32,
  every: i32,
): i32 {
  // The motion: the speculative distance, the spin swept over the body's extent when it passes
  // the fat margin, and the velocity when the body moves farther than the margin in a step (so
  // the pair exists, and its speculative contact can stop the motion, before it reaches what it
  // will hit; stretching slower bodies would only make idle pairs).
  const spin = Math.abs(ld(b, B_W)) * ld(b, B_MAX_EXTENT) * dt;
  let grow = SPECULATIVE_DISTANCE;
  if (spin > AABB_MARGIN) grow += spin;
  let dx = ld(b, B_VX) * dt;
  let dy = ld(b, B_VY) * dt;
  if (dx * dx + dy * dy <= AABB_MARGIN * AABB_MARGIN) {
    dx = 0;
    dy = 0;
  }
  const backX = Math.min(dx, 0);
  const backY = Math.min(dy, 0);
  const aheadX = Math.max(dx, 0);
  const aheadY = Math.max(dy, 0);
  const x = ld(b, B_X);
  const y = ld(b, B_Y);
  const c = ld(b, B_C);
  const s = ld(b, B_S);
  let shape = only >= 0 ? only : <i32>ld(b, B_SHAPE_HEAD) - 1;
  while (shape >= 0) {
    const g = geometry + ((<usize>shape * GEOMETRY_STRIDE) << 3);
    const kind = <i32>ld(g, G_KIND);
    const r = ld(g, G_RADIUS);
    let minX: f64, minY: f64, maxX: f64, maxY: f64;
    if (kind == GEOMETRY_CIRCLE) {
      // computeCircleAABB
      const lx = ld(g, G_VERTICES);
      const ly = ld(g, G_VERTICES + 1);
      const px = c * lx - s * ly + x;
      const py = s * lx + c * ly + y;
      minX = px - r;
      minY = py - r;
      maxX = px + r;
      maxY = py + r;
    } else if (kind == GEOMETRY_POLYGON) {
      // computePolygonAABB
      minX = Infinity;
      minY = Infinity;
      maxX = -Infinity;
      maxY = -Infinity;
      const n = <i32>ld(g, G_COUNT);
      for (let k = 0; k < n; k++) {
        const lx = ld(g, G_VERTICES + 2 * k);
        const ly = ld(g, G_VERTICES + 2 * k + 1);
        const px = c * lx - s * ly + x;
        const py = s * lx + c * ly + y;
        if (px < minX) minX = px;
        if (py < minY) minY = py;
        if (px > maxX) maxX = px;
        if (py > maxY) maxY = py;
      }
      minX = minX - r;
      minY = minY - r;
      maxX = maxX + r;
      maxY = maxY + r;
    } else {
      // computeCapsuleAABB; computeSegmentAABB without the radius (adding a 0 would turn a
      // -0 into +0)
      const x1 = ld(g, G_VERTICES);
      const y1 = ld(g, G_VERTICES + 1);
      const x2 = ld(g, G_VERTICES + 2);
      const y2 = ld(g, G_VERTICES + 3);
      const ax = c * x1 - s * y1 + x;
      const ay = s * x1 + c * y1 + y;
      const bx = c * x2 - s * y2 + x;
      const by = s * x2 + c * y2 + y;
      minX = Math.min(ax, bx);
      minY = Math.min(ay, by);
      maxX = Math.max(ax, bx);
      maxY = Math.max(ay, by);
      if (kind == GEOMETRY_CAPSULE) {
        minX = minX - r;
        minY = minY - r;
        maxX = maxX + r;
        maxY = maxY + r;
      }
    }
    const box = boxes + ((<usize>shape * SHAPE_STRIDE) << 3);
    st(box, 0, minX);
    st(box, 1, minY);
    st(box, 2, maxX);
    st(box, 3, maxY);
    // BodyBounds.place, then BroadPhase.moveProxy's test against the fat box.
    const placedMinX = minX - grow + backX;
    const placedMinY = minY - grow + backY;
    const placedMaxX = maxX + grow + aheadX;
    const placedMaxY = maxY + grow + aheadY;
    if (
      every != 0 ||
      !(
        ld(box, 4) <= placedMinX &&
        ld(box, 5) <= placedMinY &&
        placedMaxX <= ld(box, 6) &&
        placedMaxY <= ld(box, 7)
      )
    ) {
      const e = escaped + ((<usize>escapes * ESCAPE_STRIDE) << 3);
      st(e, 0, <f64>shape);
      st(e, 1, placedMinX);
      st(e, 2, placedMinY);
      st(e, 3, placedMaxX);
      st(e, 4, placedMaxY);
      escapes++;
    }
    shape = only >= 0 ? -1 : load<i32>(next + ((<usize>shape) << 2)) - 1;
  }
  return escapes;
}

/**
 * Boxes of the `count` awake bodies (world indices at `awake`, body numbers at `bodies`), skipping
 * the `fastCount` awake indices listed at `fast` (ascending: the sweeps move those bodies' boxes),
 * for a next step of `dt` seconds (A_BOUNDS_DT of the arguments at `args`, kernel-arguments.ts).
 * Shapes are found through each body's chain (`B_SHAPE_HEAD`, and
 * the next shape id plus one per shape at `next`). Writes each tight box at `boxes` (SHAPE_BOXES),
 * reads shape geometry at `geometry`, and appends each escaped shape's id and grown box at
 * `escaped`; returns how many escaped.
 */
export function shapeBounds(
  bodies: usize,
  awake: usize,
  count: i32,
  fast: usize,
  fastCount: i32,
  boxes: usize,
  geometry: usize,
  next: usize,
  args: usize,
  escaped: usize,
): i32 {
  const dt = ld(args, A_BOUNDS_DT);
  let escapes = 0;
  let listed = 0;
  let nextFast = fastCount > 0 ? load<i32>(fast) : -1;
  for (let i = 0; i < count; i++) {
    if (i == nextFast) {
      listed++;
      nextFast = listed < fastCount ? load<i32>(fast + ((<usize>listed) << 2)) : -1;
      continue;
    }
    const b = bodies + ((<usize>load<i32>(awake + ((<usize>i) << 2)) * BODY_STRIDE) << 3);
    escapes = bodyBoxes(b, -1, boxes, geometry, next, dt, escaped, escapes, 0);
  }
  return escapes;
}

/**
 * The same boxes for one body outside a step's finalize (World: a teleport, a type change, a swept
 * body's new pose; WorldMembership: a shape joining): the body whose numbers are at double `base`
 * of `bodies`, its whole chain, or only shape `only` when it is not -1 (a shape joining before
 * the chain holds it). With `every` 1 every shape visited is listed, escaped or not (a static
 * body's forced pair search moves or marks each; a joining shape has no fat box yet). Returns how
 * many were listed at `escaped`. The look-ahead `dt` is A_BOUNDS_DT of the arguments at `args`.
 */
export function bodyBounds(
  bodies: usize,
  base: i32,
  only: i32,
  boxes: usize,
  geometry: usize,
  next: usize,
  args: usize,
  escaped: usize,
  every: i32,
): i32 {
  return bodyBoxes(
    bodies + ((<usize>base) << 3),
    only,
    boxes,
    geometry,
    next,
    ld(args, A_BOUNDS_DT),
    escaped,
    0,
    every,
  );
}
