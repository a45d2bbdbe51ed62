import {
  DEFAULT_FILTER,
  type BodyDesc,
  type BodyGroupDesc,
  type FilterDesc,
  type JointDesc,
  type SceneDesc,
  type ShapeDesc,
} from '../types.ts';
import { BOX2D_MATERIAL, box, type SceneOptions } from './common.ts';

/**
 * One bone of Box2D v3's human ragdoll (shared/human.c, CreateHuman, scale 1): the body's height
 * above the figure's feet, its capsule (vertical, body-local ends and radius), linear damping, and
 * the revolute joint to its parent (pivot height, limits in units of pi, motor-friction scale).
 */
interface Bone {
  readonly y: number;
  readonly capsule: readonly [y1: number, y2: number, radius: number];
  readonly damping: number;
  readonly foot?: boolean;
  readonly joint?: {
    readonly parent: number;
    readonly pivotY: number;
    readonly lower: number;
    readonly upper: number;
    readonly friction: number;
    /** Box2D rotates the parent's joint frame by this (pi units): the elbow rests bent. */
    readonly reference?: number;
  };
}

// Bone order as Box2D's BoneId: hip, torso, head, upper/lower left leg, upper/lower right leg,
// upper/lower left arm, upper/lower right arm.
const UPPER_LEG: Bone = {
  y: 0.775,
  capsule: [-0.125, 0.125, 0.06],
  damping: 0,
  joint: { parent: 0, pivotY: 0.9, lower: -0.05, upper: 0.4, friction: 1 },
};
const lowerLeg = (parent: number): Bone => ({
  y: 0.475,
  capsule: [-0.155, 0.125, 0.045],
  damping: 0,
  foot: true,
  joint: { parent, pivotY: 0.625, lower: -0.5, upper: -0.02, friction: 0.5 },
});
const UPPER_ARM: Bone = {
  y: 1.225,
  capsule: [-0.125, 0.125, 0.035],
  damping: 0,
  joint: { parent: 1, pivotY: 1.35, lower: -0.1, upper: 0.8, friction: 0.5 },
};
const lowerArm = (parent: number): Bone => ({
  y: 0.975,
  capsule: [-0.125, 0.125, 0.03],
  damping: 0.1,
  joint: { parent, pivotY: 1.1, lower: -0.2, upper: 0.3, friction: 0.1, reference: 0.25 },
});
const BONES: readonly Bone[] = [
  { y: 0.95, capsule: [-0.02, 0.02, 0.095], damping: 0 },
  {
    y: 1.2,
    capsule: [-0.135, 0.135, 0.09],
    damping: 0,
    joint: { parent: 0, pivotY: 1.0, lower: -0.25, upper: 0, friction: 0.5 },
  },
  {
    y: 1.475,
    capsule: [-0.038, 0.039, 0.075],
    damping: 0.1,
    joint: { parent: 1, pivotY: 1.4, lower: -0.3, upper: 0.1, friction: 0.25 },
  },
  UPPER_LEG,
  lowerLeg(3),
  UPPER_LEG,
  lowerLeg(5),
  UPPER_ARM,
  lowerArm(7),
  UPPER_ARM,
  lowerArm(9),
];

/** The foot: a rounded quad on the lower leg (hull of 4 points, radius 0.015 m). */
const FOOT: readonly (readonly [number, number])[] = [
  [-0.03, -0.185],
  [0.11, -0.185],
  [0.11, -0.16],
  [-0.03, -0.14],
];

// CreateRain's joint settings: friction torque 0.05 N m (x each bone's scale), spring 5 Hz / 0.5.
const JOINT_FRICTION = 0.05;
const JOINT_HERTZ = 5;
const JOINT_DAMPING_RATIO = 0.5;
const SLEEP_THRESHOLD = 0.1;

/**
 * Adds one ragdoll standing on (x, y) to the lists. Capsules: friction 0.2, category 2, mask 1 | 2;
 * feet: friction 0.05, mask 1 (ground only); all share the negative group `-slot`, so a ragdoll
 * never collides with itself.
 */
function addHuman(
  bodies: BodyDesc[],
  joints: JointDesc[],
  x: number,
  y: number,
  slot: number,
): void {
  const base = bodies.length;
  const capsuleFilter: FilterDesc = { category: 2, mask: 1 | 2, group: -slot };
  const footFilter: FilterDesc = { category: 2, mask: 1, group: -slot };
  for (const bone of BONES) {
    const [y1, y2, radius] = bone.capsule;
    const shapes: ShapeDesc[] = [
      {
        kind: 'capsule',
        x1: 0,
        y1,
        x2: 0,
        y2,
        radius,
        material: { friction: 0.2 },
        filter: capsuleFilter,
      },
    ];
    if (bone.foot) {
      shapes.push({
        kind: 'polygon',
        vertices: FOOT,
        radius: 0.015,
        material: { friction: 0.05 },
        filter: footFilter,
      });
    }
    bodies.push({
      type: 'dynamic',
      x,
      y: y + bone.y,
      shapes,
      ...(bone.damping > 0 ? { linearDamping: bone.damping } : {}),
      sleepThreshold: SLEEP_THRESHOLD,
    });
    const j = bone.joint;
    if (j) {
      joints.push({
        a: base + j.parent,
        b: bodies.length - 1,
        x,
        y: y + j.pivotY,
        ...(j.reference === undefined ? {} : { referenceAngle: j.reference * Math.PI }),
        limit: { lower: j.lower * Math.PI, upper: j.upper * Math.PI },
        motor: { speed: 0, maxTorque: j.friction * JOINT_FRICTION },
        spring: { hertz: JOINT_HERTZ, dampingRatio: JOINT_DAMPING_RATIO },
      });
    }
  }
}

/**
 * Box2D's CreateRain / StepRain (shared/benchmarks.c): one static body with 5 rows of 501 boxes
 * 0.5 m wide (250 m), rows 45 m apart. Every 8th step a column of ragdolls (5 side by side,
 * 0.5 m apart, in each of the 5 rows, 40 m above its floor) is created; once 40 columns exist
 * the oldest column is destroyed and created again every 8 steps, so creation and destruction
 * are timed. Up to 1,000 ragdolls (11,000 bodies, 10,000 joints). Sleep on. Debug size: 3 rows,
 * 10 columns, 2 per group, 201 boxes per row, a column every 32 steps.
 */
export function rain({ small }: SceneOptions): SceneDesc {
  const rowCount = small ? 3 : 5;
  const columnCount = small ? 10 : 40;
  const groupSize = small ? 2 : 5;
  const gridSize = 0.5;
  const gridCount = small ? 200 : 500;
  const delay = small ? 0x1f : 0x7;

  const ground: ShapeDesc[] = [];
  for (let row = 0; row < rowCount; row++) {
    for (let j = 0; j <= gridCount; j++) {
      const x = -0.5 * gridCount * gridSize + j * gridSize;
      ground.push(box(0.5 * gridSize, 0.5 * gridSize, x, 45 * row));
    }
  }

  const span = gridCount * gridSize;
  const groups: BodyGroupDesc[] = [];
  for (let row = 0; row < rowCount; row++) {
    for (let column = 0; column < columnCount; column++) {
      const bodies: BodyDesc[] = [];
      const joints: JointDesc[] = [];
      const x = -0.5 * span + (span / columnCount) * (column + 0.5);
      for (let i = 0; i < groupSize; i++)
        addHuman(bodies, joints, x + 0.5 * i, 40 + 45 * row, i + 1);
      groups.push({ bodies, joints });
    }
  }

  // StepRain's state: columns created so far, then the next column to recycle.
  const handles = new Int32Array(rowCount * columnCount).fill(-1);
  let created = 0;
  let recycle = 0;
  return {
    name: 'rain',
    steps: 1000,
    gravity: { x: 0, y: -10 },
    sleep: true,
    material: BOX2D_MATERIAL,
    bodies: [{ type: 'static', x: 0, y: 0, shapes: ground }],
    createsGroups: true,
    filters: [
      DEFAULT_FILTER,
      ...Array.from({ length: groupSize }, (_, i) => [
        { category: 2, mask: 1 | 2, group: -(i + 1) },
        { category: 2, mask: 1, group: -(i + 1) },
      ]).flat(),
    ],
    onStep: (step, api) => {
      if ((step & delay) !== 0) return;
      let column: number;
      if (created < columnCount) {
        column = created++;
      } else {
        column = recycle;
        recycle = (recycle + 1) % columnCount;
      }
      for (let row = 0; row < rowCount; row++) {
        const k = row * columnCount + column;
        if (handles[k]! >= 0) api.destroyGroup(handles[k]!);
        handles[k] = api.createGroup(groups[k]!);
      }
    },
    quality: { kind: 'none' },
  };
}
