import type RAPIER from '@dimforge/rapier2d-compat';
import {
  DEFAULT_FILTER,
  DT,
  localPoint,
  materialOf,
  filtersCollide,
  type BodyDesc,
  type Engine,
  type FilterDesc,
  type JointDesc,
  type Pose,
  type SceneDesc,
  type ShapeDesc,
  type World,
} from '../types.ts';
import { bodyGroups } from './body-groups.ts';

type Rapier = typeof RAPIER;

/**
 * Rapier 2D (wasm-bindgen): the -compat packages embed the .wasm, so `await RAPIER.init()` is all.
 * The SIMD package (rapier2d-simd-compat) is an older release (0.19) than the plain one (0.21).
 */
export async function loadRapier(simd: boolean): Promise<Engine> {
  const rapier = (
    simd
      ? (await import('@dimforge/rapier2d-simd-compat')).default
      : (await import('@dimforge/rapier2d-compat')).default
  ) as Rapier;
  await rapier.init();
  const probe = new rapier.World({ x: 0, y: 0 });
  const p = probe.integrationParameters;
  const settings =
    `rapier ${rapier.version()}${simd ? ' (WASM SIMD build)' : ''}: defaults, numSolverIterations ${p.numSolverIterations} ` +
    `(its soft-TGS sub-steps), numInternalPgsIterations ${p.numInternalPgsIterations}, timestep 1/60, CCD off (per-body opt-in, default off), ` +
    `sleep per scene (canSleep), revolute motor (configureMotorVelocity) where the scene has one`;
  probe.free();
  return {
    id: simd ? 'rapier2d-simd' : 'rapier2d',
    kind: 'wasm',
    settings,
    create: (scene) => createWorld(rapier, scene),
  };
}

function createWorld(R: Rapier, scene: SceneDesc): World {
  const world = new R.World(scene.gravity);
  world.timestep = DT;
  const notes = new Set<string>();
  const colliderDesc = (shape: ShapeDesc): InstanceType<typeof R.ColliderDesc> => {
    switch (shape.kind) {
      case 'box':
        return (
          (shape.radius ?? 0) > 0
            ? R.ColliderDesc.roundCuboid(shape.hw, shape.hh, shape.radius!)
            : R.ColliderDesc.cuboid(shape.hw, shape.hh)
        )
          .setTranslation(shape.cx, shape.cy)
          .setRotation(shape.angle);
      case 'capsule': {
        // Rapier's capsule runs along its local y axis: turn it onto the segment.
        const dx = shape.x2 - shape.x1;
        const dy = shape.y2 - shape.y1;
        return R.ColliderDesc.capsule(0.5 * Math.hypot(dx, dy), shape.radius)
          .setTranslation(0.5 * (shape.x1 + shape.x2), 0.5 * (shape.y1 + shape.y2))
          .setRotation(Math.atan2(dy, dx) - Math.PI / 2);
      }
      case 'polygon': {
        const points = new Float32Array(shape.vertices.flat());
        const desc =
          (shape.radius ?? 0) > 0
            ? R.ColliderDesc.roundConvexHull(points, shape.radius!)
            : R.ColliderDesc.convexHull(points);
        if (!desc) throw new Error('rapier rejected a convex hull');
        return desc;
      }
      case 'segment':
        return R.ColliderDesc.segment({ x: shape.x1, y: shape.y1 }, { x: shape.x2, y: shape.y2 });
      case 'circle':
        return R.ColliderDesc.ball(shape.radius).setTranslation(shape.cx, shape.cy);
    }
  };
  // Box2D's filters as Rapier interaction groups: each distinct filter of the scene is one class
  // (one of 16 membership bits); a class's filter bits are the classes Box2D's rule lets it touch.
  const classes = scene.filters ?? [];
  if (classes.length > 16) throw new Error('more than 16 distinct collision filters');
  const keyOf = (f: FilterDesc): string => `${f.category}/${f.mask}/${f.group}`;
  const groupBits = new Map<string, number>();
  classes.forEach((f, i) => {
    let touches = 0;
    classes.forEach((g, j) => {
      if (filtersCollide(f, g)) touches |= 1 << j;
    });
    groupBits.set(keyOf(f), ((1 << (i + 16)) | touches) >>> 0);
  });
  const defaultBits = groupBits.get(keyOf(DEFAULT_FILTER));
  const collisionGroups = (filter: FilterDesc | undefined): number | undefined => {
    if (filter === undefined) return defaultBits;
    const bits = groupBits.get(keyOf(filter));
    if (bits === undefined) throw new Error('a shape filter missing from scene.filters');
    return bits;
  };
  const bodies: InstanceType<typeof R.RigidBody>[] = [];
  let ground: InstanceType<typeof R.RigidBody> | null = null;
  const makeBody = (desc: BodyDesc): InstanceType<typeof R.RigidBody> => {
    const bd =
      desc.type === 'static'
        ? R.RigidBodyDesc.fixed()
        : desc.type === 'kinematic'
          ? R.RigidBodyDesc.kinematicVelocityBased()
          : R.RigidBodyDesc.dynamic();
    bd.setTranslation(desc.x, desc.y)
      .setRotation(desc.angle ?? 0)
      .setLinvel(desc.vx ?? 0, desc.vy ?? 0)
      .setAngvel(desc.w ?? 0)
      .setLinearDamping(desc.linearDamping ?? 0)
      .setCanSleep(scene.sleep && desc.enableSleep !== false);
    if (desc.asleep) bd.setSleeping(true);
    if (desc.sleepThreshold !== undefined) notes.add('no per-body sleep threshold: its default');
    const body = world.createRigidBody(bd);
    for (const shape of desc.shapes) {
      const m = materialOf(scene, shape);
      const collider = colliderDesc(shape)
        .setDensity(m.density)
        .setFriction(m.friction)
        .setRestitution(m.restitution);
      const bits = collisionGroups(shape.filter);
      if (bits !== undefined) collider.setCollisionGroups(bits);
      // Box2D's joint_grid filter: member of group 2, colliding with every group but 2.
      else if (scene.shapesCollide === false) {
        collider.setCollisionGroups((0x0002 << 16) | 0xfffd);
      }
      world.createCollider(collider, body);
    }
    return body;
  };
  const makeJoint = (
    joint: JointDesc,
    list: readonly InstanceType<typeof R.RigidBody>[],
    descs: readonly BodyDesc[],
  ): void => {
    const [ax, ay] = localPoint(descs[joint.a]!, joint.x, joint.y);
    const [bx, by] = localPoint(descs[joint.b]!, joint.x, joint.y);
    const created = world.createImpulseJoint(
      R.JointData.revolute({ x: ax, y: ay }, { x: bx, y: by }),
      list[joint.a]!,
      list[joint.b]!,
      true,
    ) as InstanceType<typeof R.RevoluteImpulseJoint>;
    // Rapier's angle is angleB - angleA (both bodies start unrotated): shift by the reference.
    const reference = joint.referenceAngle ?? 0;
    if (joint.limit)
      created.setLimits(joint.limit.lower + reference, joint.limit.upper + reference);
    if (joint.spring) {
      // One motor per joint: a position motor is the spring (acceleration-based, so stiffness
      // w^2 and damping 2 zeta w, as Box2D's soft spring); the friction motor is left out.
      const w = 2 * Math.PI * joint.spring.hertz;
      created.configureMotorModel(R.MotorModel.AccelerationBased);
      created.configureMotorPosition(reference, w * w, 2 * joint.spring.dampingRatio * w);
      if (joint.motor)
        notes.add('joint friction (a speed-0 motor) left out: the motor is the spring');
    } else if (joint.motor) {
      created.configureMotorVelocity(joint.motor.speed, 1e4);
    }
  };
  for (const desc of scene.bodies) {
    const body = makeBody(desc);
    if (desc.type === 'static' && ground === null) ground = body;
    if (desc.motor && ground) {
      const joint = world.createImpulseJoint(
        R.JointData.revolute({ x: desc.x, y: desc.y }, { x: 0, y: 0 }),
        ground,
        body,
        true,
      ) as InstanceType<typeof R.RevoluteImpulseJoint>;
      joint.configureMotorVelocity(desc.motor.speed, 1e4);
    }
    bodies.push(body);
  }
  for (const joint of scene.joints ?? []) makeJoint(joint, bodies, scene.bodies);
  const velocity = { x: 0, y: 0 };
  return {
    get notes() {
      return [...notes];
    },
    ...bodyGroups<InstanceType<typeof R.RigidBody>>({
      create(group) {
        const list = group.bodies.map(makeBody);
        for (const joint of group.joints) makeJoint(joint, list, group.bodies);
        return list;
      },
      // removeRigidBody removes the body's colliders and joints too.
      destroy: (body) => world.removeRigidBody(body),
      pose(body) {
        const p = body.translation();
        return { x: p.x, y: p.y, angle: body.rotation() };
      },
    }),
    step() {
      world.step();
    },
    pose(index): Pose {
      const body = bodies[index]!;
      const p = body.translation();
      return { x: p.x, y: p.y, angle: body.rotation() };
    },
    moveKinematicTo(index, x, y, angle) {
      const body = bodies[index]!;
      const p = body.translation();
      velocity.x = (x - p.x) / DT;
      velocity.y = (y - p.y) / DT;
      body.setLinvel(velocity, true);
      body.setAngvel((angle - body.rotation()) / DT, true);
    },
  };
}
