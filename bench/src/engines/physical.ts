import {
  Body,
  World as PhysicalWorld,
  revoluteJoint,
  type RevoluteJointOptions,
  type ShapeOptions,
} from '@physical/engine';
// For the `physical-javascript` engine (kernel: 'javascript').
import '@physical/engine/javascript-kernel';
import {
  DT,
  SUB_STEPS,
  materialOf,
  type BodyDesc,
  type Engine,
  type JointDesc,
  type Pose,
  type SceneDesc,
  type ShapeDesc,
  type World,
} from '../types.ts';
import { bodyGroups } from './body-groups.ts';

// Physical is y-down: every y, angle and angular velocity is mirrored on the way in and out.

function shapeOptions(scene: SceneDesc, shape: ShapeDesc): ShapeOptions {
  const material = materialOf(scene, shape);
  switch (shape.kind) {
    case 'box':
      return {
        type: 'box',
        width: 2 * shape.hw,
        height: 2 * shape.hh,
        offset: { x: shape.cx, y: -shape.cy },
        angle: -shape.angle,
        radius: shape.radius ?? 0,
        ...material,
      };
    case 'capsule':
      return {
        type: 'capsule',
        center1: { x: shape.x1, y: -shape.y1 },
        center2: { x: shape.x2, y: -shape.y2 },
        radius: shape.radius,
        ...material,
      };
    case 'polygon':
      return {
        type: 'polygon',
        vertices: shape.vertices.map(([x, y]) => ({ x, y: -y })).reverse(),
        radius: shape.radius ?? 0,
        ...material,
      };
    case 'segment':
      return {
        type: 'segment',
        from: { x: shape.x1, y: -shape.y1 },
        to: { x: shape.x2, y: -shape.y2 },
        ...material,
      };
    case 'circle':
      return {
        type: 'circle',
        radius: shape.radius,
        offset: { x: shape.cx, y: -shape.cy },
        ...material,
      };
  }
}

/** The joint's revolute options in Physical's y-down frame (see JointDesc for the angle). */
function revoluteOptions(
  joint: JointDesc,
  a: BodyDesc,
  b: BodyDesc,
  notes: Set<string>,
): Omit<RevoluteJointOptions, 'bodyA' | 'bodyB'> {
  // Physical measures the joint angle from the bodies' angles at creation and in y-down, so
  // Box2D's angle t = (angleB - angleA at creation) - referenceAngle - (Physical's angle).
  const offset = (b.angle ?? 0) - (a.angle ?? 0) - (joint.referenceAngle ?? 0);
  if (joint.spring && offset !== 0) {
    notes.add(
      'no reference-angle option on revoluteJoint: a spring of a joint with a reference angle (the elbows) rests at the creation angle (Box2D: at the reference angle)',
    );
  }
  return {
    anchor: { x: joint.x, y: -joint.y },
    ...(joint.limit
      ? {
          enableLimit: true,
          lowerAngle: offset - joint.limit.upper,
          upperAngle: offset - joint.limit.lower,
        }
      : {}),
    ...(joint.motor
      ? {
          enableMotor: true,
          motorSpeed: -joint.motor.speed,
          maxMotorTorque: unlimited(joint.motor.maxTorque),
        }
      : {}),
    ...(joint.spring
      ? {
          enableSpring: true,
          hertz: joint.spring.hertz,
          dampingRatio: joint.spring.dampingRatio,
        }
      : {}),
  };
}

export const physical: Engine = {
  id: 'physical',
  kind: 'js',
  settings: `subSteps ${SUB_STEPS}, contact 30 Hz / damping 10, push-out 3 m/s, sleep per scene, continuous on (defaults), revolute motor where the scene has one; measured from packages/engine/dist (tsc build)`,
  create: (scene) => createWorld(scene, 'auto'),
};

/**
 * Physical with `kernel: 'javascript'`: the contact passes' JavaScript build only, as where
 * WebAssembly cannot compile (a Content-Security-Policy without 'wasm-unsafe-eval'). Not in the
 * default engine list; `--engines physical,physical-javascript` compares the two builds.
 */
export const physicalJavaScript: Engine = {
  ...physical,
  id: 'physical-javascript',
  settings: `${physical.settings}; kernel: 'javascript'`,
  create: (scene) => createWorld(scene, 'javascript'),
};

/** Physical's World behind each bench world it made (for counters outside the bench interface). */
const physicalWorlds = new WeakMap<World, PhysicalWorld>();

/** The Physical World behind a bench world made by `physical.create`, if it is one. */
export function physicalWorldOf(world: World): PhysicalWorld | undefined {
  return physicalWorlds.get(world);
}

function createWorld(scene: SceneDesc, kernel: 'auto' | 'javascript'): World {
  const adapter = createAdapter(scene, kernel);
  physicalWorlds.set(adapter.bench, adapter.world);
  return adapter.bench;
}

function createAdapter(
  scene: SceneDesc,
  kernel: 'auto' | 'javascript',
): { bench: World; world: PhysicalWorld } {
  const world = new PhysicalWorld({
    gravity: { x: scene.gravity.x, y: -scene.gravity.y },
    subSteps: SUB_STEPS,
    enableSleep: scene.sleep,
    enableContinuous: true,
    kernel,
  });
  const notes = new Set<string>();
  const bodies: Body[] = [];
  let ground: Body | null = null;
  const makeBody = (desc: BodyDesc): Body => {
    if (desc.sleepThreshold !== undefined) {
      notes.add('no per-body sleep threshold (Box2D bodyDef.sleepThreshold): the default');
    }
    return new Body({
      type: desc.type,
      position: { x: desc.x, y: -desc.y },
      angle: -(desc.angle ?? 0),
      linearVelocity: { x: desc.vx ?? 0, y: -(desc.vy ?? 0) },
      angularVelocity: -(desc.w ?? 0),
      linearDamping: desc.linearDamping ?? 0,
      asleep: desc.asleep ?? false,
      allowSleep: desc.enableSleep ?? true,
      shapes: desc.shapes.map((s) =>
        s.filter
          ? { ...shapeOptions(scene, s), filter: s.filter }
          : // Box2D's joint_grid filter: category 2, mask ~2, so no two shapes ever collide.
            scene.shapesCollide === false
            ? { ...shapeOptions(scene, s), filter: { category: 2, mask: 0xfffffffd } }
            : shapeOptions(scene, s),
      ),
    });
  };
  const makeJoint = (joint: JointDesc, list: readonly Body[], descs: readonly BodyDesc[]) =>
    world.addJoint(
      revoluteJoint({
        bodyA: list[joint.a]!,
        bodyB: list[joint.b]!,
        ...revoluteOptions(joint, descs[joint.a]!, descs[joint.b]!, notes),
      }),
    );
  for (const desc of scene.bodies) {
    const body = makeBody(desc);
    world.add(body);
    bodies.push(body);
    if (desc.type === 'static' && ground === null) ground = body;
    if (desc.motor) {
      if (ground === null) throw new Error('a motor needs a static body before it');
      // y-down: a positive (counter-clockwise) Box2D speed is a negative angular velocity here.
      world.addJoint(
        revoluteJoint({
          bodyA: ground,
          bodyB: body,
          anchor: { x: desc.x, y: -desc.y },
          enableMotor: true,
          motorSpeed: -desc.motor.speed,
          maxMotorTorque: unlimited(desc.motor.maxTorque),
        }),
      );
    }
  }
  for (const joint of scene.joints ?? []) makeJoint(joint, bodies, scene.bodies);
  if (scene.bodies.some((b) => b.hitEvents)) notes.add('no hit-event listener registered');
  const bench = {
    get notes() {
      return [...notes];
    },
    ...bodyGroups<Body>({
      create(group) {
        const list = group.bodies.map((desc) => world.add(makeBody(desc)));
        for (const joint of group.joints) makeJoint(joint, list, group.bodies);
        return list;
      },
      // Removing a body removes its joints.
      destroy: (body) => world.remove(body),
      pose: (body) => ({ x: body.position.x, y: -body.position.y, angle: -body.angle }),
    }),
    step() {
      world.step(DT);
    },
    pose(index): Pose {
      const body = bodies[index]!;
      const p = body.position;
      return { x: p.x, y: -p.y, angle: -body.angle };
    },
    moveKinematicTo(index, x, y, angle) {
      const body = bodies[index]!;
      const p = body.position;
      body.linearVelocity = { x: (x - p.x) / DT, y: (-y - p.y) / DT };
      body.angularVelocity = (-angle - body.angle) / DT;
    },
  } satisfies World;
  return { bench, world };
}

/**
 * Box2D's scenes write "no limit" as FLT_MAX (3.4e38); Physical refuses forces and torques past
 * 1e18 (an absurd value is an error there), which is as unlimited for any scene.
 */
function unlimited(value: number): number {
  return Math.min(value, 1e18);
}
