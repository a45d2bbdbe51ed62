// Engine-agnostic scene descriptions, in Box2D's frame (y up, gravity (0, -10)). Each engine adapter
// turns a description into its own world; y-down engines (Physical, matter-js) mirror y.

export type ShapeDesc =
  | {
      readonly kind: 'box';
      /** Half-widths (m), as Box2D's b2MakeOffsetBox takes them. */
      readonly hw: number;
      readonly hh: number;
      readonly cx: number;
      readonly cy: number;
      readonly angle: number;
      /** Rounding radius (m) added around the box, as b2MakeRoundedBox; 0 or absent: sharp. */
      readonly radius?: number;
      readonly material?: MaterialDesc;
      readonly filter?: FilterDesc;
    }
  | {
      /** Every point within `radius` of the segment between the two centres (b2Capsule). */
      readonly kind: 'capsule';
      readonly x1: number;
      readonly y1: number;
      readonly x2: number;
      readonly y2: number;
      readonly radius: number;
      readonly material?: MaterialDesc;
      readonly filter?: FilterDesc;
    }
  | {
      readonly kind: 'polygon';
      /** Convex hull, counter-clockwise in the y-up frame, body-local (m). */
      readonly vertices: readonly (readonly [number, number])[];
      /** Rounding radius (m) around the hull, as b2MakePolygon's radius; 0 or absent: sharp. */
      readonly radius?: number;
      readonly material?: MaterialDesc;
      readonly filter?: FilterDesc;
    }
  | {
      readonly kind: 'segment';
      readonly x1: number;
      readonly y1: number;
      readonly x2: number;
      readonly y2: number;
      readonly material?: MaterialDesc;
      readonly filter?: FilterDesc;
    }
  | {
      readonly kind: 'circle';
      readonly radius: number;
      readonly cx: number;
      readonly cy: number;
      readonly material?: MaterialDesc;
      readonly filter?: FilterDesc;
    };

/**
 * Box2D's collision filter: two shapes collide when each one's category is in the other's mask,
 * unless they share a non-zero group (positive: always collide, negative: never).
 */
export interface FilterDesc {
  readonly category: number;
  readonly mask: number;
  readonly group: number;
}

export interface MaterialDesc {
  readonly density?: number;
  readonly friction?: number;
  readonly restitution?: number;
}

export type BodyKind = 'static' | 'dynamic' | 'kinematic';

export interface BodyDesc {
  readonly type: BodyKind;
  readonly x: number;
  readonly y: number;
  readonly angle?: number;
  readonly vx?: number;
  readonly vy?: number;
  readonly w?: number;
  readonly asleep?: boolean;
  readonly shapes: readonly ShapeDesc[];
  /**
   * A revolute joint to the static ground at the body origin with a motor (rad/s, N m). Engines
   * without motors make the body kinematic with angular velocity `speed` instead (and say so).
   */
  readonly motor?: { readonly speed: number; readonly maxTorque: number };
  /** False: this body never sleeps (Box2D's bodyDef.enableSleep). Default true. */
  readonly enableSleep?: boolean;
  /** Box2D's enableHitEvents on the body's shapes (only Box2D v3 has them). */
  readonly hitEvents?: boolean;
  /** Linear damping (1/s). Default 0. */
  readonly linearDamping?: number;
  /** Box2D's bodyDef.sleepThreshold (m/s); engines without it keep their own (and say so). */
  readonly sleepThreshold?: number;
}

/** A revolute joint between two bodies of the scene (indices into `bodies`) at a world point. */
export interface JointDesc {
  readonly a: number;
  readonly b: number;
  /** Anchor in world coordinates (m, Box2D's frame). */
  readonly x: number;
  readonly y: number;
  /**
   * The joint angle is angleB - angleA - referenceAngle (rad; Box2D v3: the rotation of localFrameA
   * when both bodies start unrotated). Default 0.
   */
  readonly referenceAngle?: number;
  /** Joint angle limits (rad). */
  readonly limit?: { readonly lower: number; readonly upper: number };
  /** Motor (rad/s, N m); speed 0 with a small torque is Box2D's joint friction. */
  readonly motor?: { readonly speed: number; readonly maxTorque: number };
  /** Torsion spring towards joint angle 0. */
  readonly spring?: { readonly hertz: number; readonly dampingRatio: number };
}

/** Bodies and joints created together while the scene runs (a column of ragdolls). */
export interface BodyGroupDesc {
  readonly bodies: readonly BodyDesc[];
  /** Joints between this group's bodies (`a`, `b` index `bodies`). */
  readonly joints: readonly JointDesc[];
}

/** Sent to a scene's per-step callback: moves a kinematic body towards a target pose in one step. */
export interface StepApi {
  moveKinematicTo(index: number, x: number, y: number, angle: number): void;
  /** Creates a group of bodies and joints (timed, as Box2D's rain creates ragdolls); a handle. */
  createGroup(group: BodyGroupDesc): number;
  /** Destroys a group's bodies and joints. */
  destroyGroup(handle: number): void;
}

export type QualitySpec =
  | { readonly kind: 'none' }
  | {
      readonly kind: 'pyramid';
      /** Indices of every pyramid box and its full width (m). */
      readonly boxes: readonly number[];
      readonly boxWidth: number;
      /** Index of each pyramid's top box. */
      readonly tops: readonly number[];
    }
  | {
      readonly kind: 'tumbler';
      readonly container: number;
      readonly boxes: readonly number[];
      /** Half-size of the container's inner square (m). */
      readonly innerHalf: number;
    };

export interface SceneDesc {
  readonly name: string;
  /** Total steps; step 0 is not timed, so steps - 1 are. */
  readonly steps: number;
  readonly gravity: { readonly x: number; readonly y: number };
  readonly sleep: boolean;
  /** Scene defaults for shapes without their own material (Box2D: density 1, friction 0.6). */
  readonly material: Required<MaterialDesc>;
  readonly bodies: readonly BodyDesc[];
  /** Revolute joints (joined bodies do not collide with each other). */
  readonly joints?: readonly JointDesc[];
  /**
   * False when no two shapes of the scene may collide (Box2D: filter category 2, mask ~2). Default
   * true.
   */
  readonly shapesCollide?: boolean;
  readonly onStep?: (step: number, api: StepApi) => void;
  /** True when onStep creates and destroys body groups (engines need createGroup). */
  readonly createsGroups?: boolean;
  /**
   * Every distinct shape filter the scene uses, those of groups created later included (absent
   * filter: DEFAULT_FILTER), for engines that turn filters into a fixed set of collision classes.
   */
  readonly filters?: readonly FilterDesc[];
  readonly quality: QualitySpec;
  /** What differs from Box2D's scene, if anything (printed). */
  readonly notes?: string;
}

export interface Pose {
  x: number;
  y: number;
  angle: number;
}

/** One engine's world for one scene. */
export interface World {
  step(): void;
  /** Pose of scene.bodies[index] in Box2D's frame (origin of the body, or its centre where noted). */
  pose(index: number): Pose;
  moveKinematicTo(index: number, x: number, y: number, angle: number): void;
  /** Body groups created while running (see StepApi); engines without it cannot run such scenes. */
  createGroup?(group: BodyGroupDesc): number;
  destroyGroup?(handle: number): void;
  /** Poses of every body of every live group (for the quality check at the end). */
  groupPoses?(): Pose[];
  /** Approximations this engine made for this scene, printed beside its settings. */
  readonly notes: readonly string[];
}

export interface Engine {
  readonly id: string;
  /** Settings used, written out in the results. */
  readonly settings: string;
  /** JavaScript engines can report gc events; for WASM engines gc covers only the JS glue. */
  readonly kind: 'js' | 'wasm';
  create(scene: SceneDesc): World;
  /** Scenes this engine cannot run, with the reason (printed in the quality column). */
  readonly unsupported?: Readonly<Record<string, string>>;
}

/**
 * Whether two shapes collide under Box2D's filter rule (a shared non-zero group decides, else the
 * category/mask bits both ways). Absent filters are category 1, mask all, group 0.
 */
export function filtersCollide(a: FilterDesc | undefined, b: FilterDesc | undefined): boolean {
  const fa = a ?? DEFAULT_FILTER;
  const fb = b ?? DEFAULT_FILTER;
  if (fa.group === fb.group && fa.group !== 0) return fa.group > 0;
  return (fa.category & fb.mask) !== 0 && (fb.category & fa.mask) !== 0;
}

export const DEFAULT_FILTER: FilterDesc = { category: 1, mask: 0xffffffff, group: 0 };

export const DT = 1 / 60;
export const SUB_STEPS = 4;

/** Material of a shape with the scene's defaults filled in. */
export function materialOf(scene: SceneDesc, shape: ShapeDesc): Required<MaterialDesc> {
  const m = shape.material ?? {};
  return {
    density: m.density ?? scene.material.density,
    friction: m.friction ?? scene.material.friction,
    restitution: m.restitution ?? scene.material.restitution,
  };
}

/** A world point (Box2D's frame) in the frame of a body as the scene creates it. */
export function localPoint(body: BodyDesc, x: number, y: number): [number, number] {
  const angle = body.angle ?? 0;
  const c = Math.cos(angle);
  const s = Math.sin(angle);
  const dx = x - body.x;
  const dy = y - body.y;
  return [c * dx + s * dy, -s * dx + c * dy];
}

/** Centroid of a convex polygon. */
export function centroid(vertices: readonly (readonly [number, number])[]): [number, number] {
  let area = 0;
  let cx = 0;
  let cy = 0;
  const [ox, oy] = vertices[0]!;
  for (let i = 1; i + 1 < vertices.length; i++) {
    const [ax, ay] = vertices[i]!;
    const [bx, by] = vertices[i + 1]!;
    const a = 0.5 * ((ax - ox) * (by - oy) - (ay - oy) * (bx - ox));
    area += a;
    cx += (a * (ox + ax + bx)) / 3;
    cy += (a * (oy + ay + by)) / 3;
  }
  return [cx / area, cy / area];
}

/** Convex hull (Andrew's monotone chain), counter-clockwise in the y-up frame. */
export function hull(points: readonly (readonly [number, number])[]): [number, number][] {
  const p = [...points].sort((a, b) => a[0] - b[0] || a[1] - b[1]);
  const cross = (o: readonly number[], a: readonly number[], b: readonly number[]): number =>
    (a[0]! - o[0]!) * (b[1]! - o[1]!) - (a[1]! - o[1]!) * (b[0]! - o[0]!);
  const lower: [number, number][] = [];
  for (const q of p) {
    while (lower.length >= 2 && cross(lower[lower.length - 2]!, lower[lower.length - 1]!, q) <= 0)
      lower.pop();
    lower.push([q[0], q[1]]);
  }
  const upper: [number, number][] = [];
  for (let i = p.length - 1; i >= 0; i--) {
    const q = p[i]!;
    while (upper.length >= 2 && cross(upper[upper.length - 2]!, upper[upper.length - 1]!, q) <= 0)
      upper.pop();
    upper.push([q[0], q[1]]);
  }
  lower.pop();
  upper.pop();
  return lower.concat(upper);
}

/**
 * For engines without capsules or rounded boxes: the shape as a convex polygon of 8 vertices
 * inscribed in it (a capsule's half circles by 4 points each; a rounded box with its corners cut
 * between the arcs' ends). A rounded polygon loses its radius. Other shapes are returned unchanged. Counter-clockwise (y up).
 */
export type SharpShapeDesc = Exclude<ShapeDesc, { readonly kind: 'capsule' }>;

export function withoutRounding(shape: ShapeDesc): SharpShapeDesc {
  if (shape.kind === 'capsule') {
    const axis = Math.atan2(shape.y2 - shape.y1, shape.x2 - shape.x1);
    const vertices: [number, number][] = [];
    for (const [cx, cy, start] of [
      [shape.x2, shape.y2, -Math.PI / 2],
      [shape.x1, shape.y1, Math.PI / 2],
    ] as const) {
      for (let k = 0; k < 4; k++) {
        const angle = axis + start + (k * Math.PI) / 3;
        vertices.push([cx + shape.radius * Math.cos(angle), cy + shape.radius * Math.sin(angle)]);
      }
    }
    return sharpPolygon(shape, vertices);
  }
  if (shape.kind === 'box' && (shape.radius ?? 0) > 0) {
    const r = shape.radius!;
    const { hw, hh } = shape;
    const local: [number, number][] = [
      [hw + r, -hh],
      [hw + r, hh],
      [hw, hh + r],
      [-hw, hh + r],
      [-hw - r, hh],
      [-hw - r, -hh],
      [-hw, -hh - r],
      [hw, -hh - r],
    ];
    const c = Math.cos(shape.angle);
    const s = Math.sin(shape.angle);
    const vertices = local.map(([x, y]): [number, number] => [
      c * x - s * y + shape.cx,
      s * x + c * y + shape.cy,
    ]);
    return sharpPolygon(shape, vertices);
  }
  if (shape.kind === 'polygon' && (shape.radius ?? 0) > 0) {
    // The rounding is dropped: the hull alone (a rounded polygon's corner radius is small here).
    return sharpPolygon(shape, shape.vertices);
  }
  return shape;
}

function sharpPolygon(
  shape: ShapeDesc,
  vertices: readonly (readonly [number, number])[],
): SharpShapeDesc {
  return {
    kind: 'polygon',
    vertices,
    ...(shape.material === undefined ? {} : { material: shape.material }),
    ...(shape.filter === undefined ? {} : { filter: shape.filter }),
  };
}
