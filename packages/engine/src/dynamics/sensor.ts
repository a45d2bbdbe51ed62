import { releaseFrom } from '../core/release.ts';
import type { BroadPhase } from '../collision/broad-phase.ts';
import { DistanceOutput, DistanceProxy, shapeDistance } from '../collision/distance.ts';
import { AABB } from '../geometry/aabb.ts';
import { setShapeProxy } from './shape-proxy.ts';
import type { Shape } from './shape.ts';

/**
 * Sensor overlaps. After each step every sensor shape queries the broad phase for shapes whose
 * boxes overlap its own and tests them exactly (GJK distance, radii included: touching counts);
 * the set it finds is compared with last step's to record begin and end events. This is Box2D
 * v3's design (sensor events computed at the end of the step, outside the contact solver), so a
 * sensor never makes a contact: it cannot push, slow or wake anything.
 *
 * Visitors: non-sensor shapes of other bodies of any type (static ones too: a static goal area
 * over a static floor reports the floor once), passing the sensor's filter. Sensors do not detect
 * other sensors, as in Box2D v3.
 *
 * Each sensor's overlap list is in broad-phase order as of its last change.
 */
export class Sensors {
  /** Sensor shapes in the world, in the order they joined. */
  readonly shapes: Shape[] = [];
  /** Per sensor: the shapes overlapping it after the last update. */
  readonly overlaps: Shape[][] = [];
  /** Begin events of the last update: sensor shape, visitor shape; the first `beganCount`. */
  readonly beganSensor: Shape[] = [];
  readonly beganVisitor: Shape[] = [];
  beganCount = 0;
  /** End events (from the last update, or from shapes leaving the world). */
  readonly endedSensor: Shape[] = [];
  readonly endedVisitor: Shape[] = [];
  endedCount = 0;

  private readonly found: Shape[] = [];
  private foundCount = 0;
  private current: Shape | null = null;
  private shapesById: readonly (Shape | null)[] = [];
  private readonly box = new AABB();
  private readonly proxyA = new DistanceProxy();
  private readonly proxyB = new DistanceProxy();
  private readonly output = new DistanceOutput();
  private readonly queryCallback = (_proxyKey: number, shapeId: number): boolean => {
    this.test(shapeId);
    return true;
  };

  /** A sensor shape joined the world. */
  add(shape: Shape): void {
    shape.sensorIndex = this.shapes.length;
    this.shapes.push(shape);
    this.overlaps.push([]);
  }

  /**
   * A shape leaves the world: a sensor drops its list (ending its overlaps), and every sensor
   * the shape was visiting records an end.
   */
  remove(shape: Shape): void {
    if (shape.sensorIndex >= 0) {
      const index = shape.sensorIndex;
      const list = this.overlaps[index]!;
      for (const visitor of list) this.recordEnd(shape, visitor);
      this.shapes.splice(index, 1);
      this.overlaps.splice(index, 1);
      for (let i = index; i < this.shapes.length; i++) this.shapes[i]!.sensorIndex = i;
      shape.sensorIndex = -1;
      return;
    }
    for (let i = 0; i < this.shapes.length; i++) {
      const list = this.overlaps[i]!;
      const at = list.indexOf(shape);
      if (at < 0) continue;
      list.splice(at, 1);
      this.recordEnd(this.shapes[i]!, shape);
    }
  }

  /**
   * Drops the references its per-step lists hold past their counts (a removed body's shapes);
   * the begins and ends not yet reported stay.
   */
  releaseReferences(): void {
    releaseFrom(this.beganSensor, this.beganCount);
    releaseFrom(this.beganVisitor, this.beganCount);
    releaseFrom(this.endedSensor, this.endedCount);
    releaseFrom(this.endedVisitor, this.endedCount);
    releaseFrom(this.found, 0);
    this.foundCount = 0;
  }

  /** Finds every sensor's overlaps now and records what began and ended since last time. */
  update(broadPhase: BroadPhase, shapesById: readonly (Shape | null)[]): void {
    this.beganCount = 0;
    this.shapesById = shapesById;
    for (let i = 0; i < this.shapes.length; i++) {
      const sensor = this.shapes[i]!;
      this.current = sensor;
      this.foundCount = 0;
      setShapeProxy(this.proxyA, sensor);
      const tight = sensor.computeAABB(sensor.body.transform);
      this.box.set(tight.minX, tight.minY, tight.maxX, tight.maxY);
      broadPhase.query(this.box, this.queryCallback);
      const list = this.overlaps[i]!;
      let changed = list.length !== this.foundCount;
      // Ends: in the old list, not found now.
      for (let j = 0; j < list.length; j++) {
        if (this.wasFound(list[j]!)) continue;
        this.recordEnd(sensor, list[j]!);
        changed = true;
      }
      // Begins: found now, not in the old list.
      for (let j = 0; j < this.foundCount; j++) {
        const visitor = this.found[j]!;
        if (list.includes(visitor)) continue;
        const n = this.beganCount++;
        this.beganSensor[n] = sensor;
        this.beganVisitor[n] = visitor;
        changed = true;
      }
      // Rewritten only when the set changed (then in broad-phase order): a sensor whose
      // overlaps stay the same touches nothing, so a steady scene allocates nothing.
      if (changed) {
        list.length = 0;
        for (let j = 0; j < this.foundCount; j++) list.push(this.found[j]!);
      }
    }
    this.current = null;
  }

  private wasFound(shape: Shape): boolean {
    for (let j = 0; j < this.foundCount; j++) if (this.found[j] === shape) return true;
    return false;
  }

  private test(shapeId: number): void {
    const sensor = this.current!;
    const other = this.shapesById[shapeId];
    if (other === null || other === undefined || other.sensor || other.body === sensor.body) return;
    if (!sensor.collidesWith(other)) return;
    const tight = other.computeAABB(other.body.transform);
    const box = this.box;
    if (
      tight.minX > box.maxX ||
      tight.maxX < box.minX ||
      tight.minY > box.maxY ||
      tight.maxY < box.minY
    ) {
      return;
    }
    setShapeProxy(this.proxyB, other);
    shapeDistance(
      this.proxyA,
      sensor.body.transform,
      this.proxyB,
      other.body.transform,
      this.output,
    );
    if (this.output.distance > 0 || this.wasFound(other)) return;
    if (this.foundCount < this.found.length) this.found[this.foundCount] = other;
    else this.found.push(other);
    this.foundCount++;
  }

  private recordEnd(sensor: Shape, visitor: Shape): void {
    const n = this.endedCount++;
    this.endedSensor[n] = sensor;
    this.endedVisitor[n] = visitor;
  }
}
