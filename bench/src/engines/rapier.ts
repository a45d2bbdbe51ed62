import type RAPIER from '@dimforge/rapier2d-compat';
import {
  DT,
  materialOf,
  type Engine,
  type Pose,
  type SceneDesc,
  type ShapeDesc,
  type World,
} from '../types.ts';

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
        const desc = R.ColliderDesc.convexHull(new Float32Array(shape.vertices.flat()));
        if (!desc) throw new Error('rapier rejected a convex hull');
        return desc;
      }
      case 'segment':
        return R.ColliderDesc.segment({ x: shape.x1, y: shape.y1 }, { x: shape.x2, y: shape.y2 });
      case 'circle':
        return R.ColliderDesc.ball(shape.radius).setTranslation(shape.cx, shape.cy);
    }
  };
  const bodies: InstanceType<typeof R.RigidBody>[] = [];
  let ground: InstanceType<typeof R.RigidBody> | null = null;
  for (const desc of scene.bodies) {
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
      .setCanSleep(scene.sleep && desc.enableSleep !== false);
    if (desc.asleep) bd.setSleeping(true);
    const body = world.createRigidBody(bd);
    for (const shape of desc.shapes) {
      const m = materialOf(scene, shape);
      world.createCollider(
        colliderDesc(shape)
          .setDensity(m.density)
          .setFriction(m.friction)
          .setRestitution(m.restitution),
        body,
      );
    }
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
  const velocity = { x: 0, y: 0 };
  return {
    notes: [],
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
