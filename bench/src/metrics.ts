import type { SceneDesc, World } from './types.ts';

/** What the worker measures at the end of the run, for the quality column. */
export interface Metrics {
  /** Bodies whose pose is not finite. */
  nan: number;
  /** Pyramids: largest sideways displacement of any box (m), and the limit (a quarter width). */
  maxLateral?: number;
  lateralLimit?: number;
  /** Pyramids: largest sink of a top box (m, positive = down). */
  topSink?: number;
  /** Tumbler: boxes whose centre is outside the container's inner square. */
  outside?: number;
  /** Tumbler: container angle at the end vs the motor's 25 deg/s (deg). */
  containerAngleDeg?: number;
}

export function initialPoses(scene: SceneDesc): { x: number; y: number }[] {
  return scene.bodies.map((b) => ({ x: b.x, y: b.y }));
}

export function measure(scene: SceneDesc, world: World): Metrics {
  let nan = 0;
  for (let i = 0; i < scene.bodies.length; i++) {
    if (scene.bodies[i]!.type === 'static') continue;
    const p = world.pose(i);
    if (!Number.isFinite(p.x) || !Number.isFinite(p.y) || !Number.isFinite(p.angle)) nan++;
  }
  // Bodies the scene created while running (rain's ragdolls).
  for (const p of world.groupPoses?.() ?? []) {
    if (!Number.isFinite(p.x) || !Number.isFinite(p.y) || !Number.isFinite(p.angle)) nan++;
  }
  const metrics: Metrics = { nan };
  const q = scene.quality;
  if (q.kind === 'pyramid') {
    let maxLateral = 0;
    for (const i of q.boxes) {
      const dx = Math.abs(world.pose(i).x - scene.bodies[i]!.x);
      maxLateral = Math.max(maxLateral, Number.isNaN(dx) ? Infinity : dx);
    }
    let topSink = -Infinity;
    for (const i of q.tops) {
      const sink = scene.bodies[i]!.y - world.pose(i).y;
      topSink = Math.max(topSink, Number.isNaN(sink) ? Infinity : sink);
    }
    metrics.maxLateral = maxLateral;
    metrics.lateralLimit = 0.25 * q.boxWidth;
    metrics.topSink = topSink;
  } else if (q.kind === 'tumbler') {
    const c = world.pose(q.container);
    const cos = Math.cos(c.angle);
    const sin = Math.sin(c.angle);
    let outside = 0;
    for (const i of q.boxes) {
      const p = world.pose(i);
      const dx = p.x - c.x;
      const dy = p.y - c.y;
      const lx = cos * dx + sin * dy;
      const ly = -sin * dx + cos * dy;
      if (!(Math.abs(lx) <= q.innerHalf && Math.abs(ly) <= q.innerHalf)) outside++;
    }
    metrics.outside = outside;
    metrics.containerAngleDeg = (c.angle * 180) / Math.PI;
  }
  return metrics;
}
