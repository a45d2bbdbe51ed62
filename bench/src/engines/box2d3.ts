import Box2DFactory from 'box2d3-wasm';
import {
  DT,
  SUB_STEPS,
  localPoint,
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

type B2 = Awaited<ReturnType<typeof Box2DFactory>>;
type BodyId = ReturnType<B2['b2CreateBody']>;

/**
 * Box2D v3 through box2d3-wasm: its entry picks the "deluxe" build (WASM SIMD + pthreads) in Node.
 * Default world def (workerCount left at its default, so single-threaded, no task system), 4
 * sub-steps per b2World_Step, default contact tuning, sleep per scene, continuous on.
 */
export async function loadBox2d3(): Promise<Engine> {
  const b2 = await Box2DFactory();
  const defaults = b2.b2DefaultWorldDef();
  const settings =
    `b2DefaultWorldDef (workerCount ${defaults.workerCount} = single-threaded, contact ${defaults.contactHertz} Hz / ` +
    `damping ${defaults.contactDampingRatio}, continuous ${defaults.enableContinuous ? 'on' : 'off'}), ` +
    `subStepCount ${SUB_STEPS}, sleep per scene, revolute motor where the scene has one; ` +
    `"deluxe" build (WASM SIMD + pthreads) chosen by the package entry`;
  return {
    id: 'box2d3-wasm',
    kind: 'wasm',
    settings,
    create: (scene) => createWorld(b2, scene),
  };
}

function vec(b2: B2, x: number, y: number): InstanceType<B2['b2Vec2']> {
  return new b2.b2Vec2(x, y);
}

function addShape(b2: B2, scene: SceneDesc, bodyId: BodyId, shape: ShapeDesc, hit: boolean): void {
  const def = b2.b2DefaultShapeDef();
  const m = materialOf(scene, shape);
  def.density = m.density;
  const material = def.material;
  material.friction = m.friction;
  material.restitution = m.restitution;
  def.material = material;
  def.enableHitEvents = hit;
  if (shape.filter) {
    const filter = def.filter;
    filter.categoryBits = shape.filter.category;
    filter.maskBits = shape.filter.mask;
    filter.groupIndex = shape.filter.group;
    def.filter = filter;
  } else if (scene.shapesCollide === false) {
    // Box2D's joint_grid filter: category 2, mask ~2, so no two shapes collide.
    const filter = def.filter;
    filter.categoryBits = 2;
    filter.maskBits = 0xfffffffd; // every category but 2 (only 2 exists in the scene)
    def.filter = filter;
  }
  switch (shape.kind) {
    case 'box': {
      const radius = shape.radius ?? 0;
      const polygon =
        radius > 0
          ? b2.b2MakeOffsetRoundedBox(
              shape.hw,
              shape.hh,
              vec(b2, shape.cx, shape.cy),
              b2.b2MakeRot(shape.angle),
              radius,
            )
          : shape.cx === 0 && shape.cy === 0 && shape.angle === 0
            ? b2.b2MakeBox(shape.hw, shape.hh)
            : b2.b2MakeOffsetBox(
                shape.hw,
                shape.hh,
                vec(b2, shape.cx, shape.cy),
                b2.b2MakeRot(shape.angle),
              );
      b2.b2CreatePolygonShape(bodyId, def, polygon);
      break;
    }
    case 'capsule': {
      const capsule = new b2.b2Capsule();
      capsule.center1 = vec(b2, shape.x1, shape.y1);
      capsule.center2 = vec(b2, shape.x2, shape.y2);
      capsule.radius = shape.radius;
      b2.b2CreateCapsuleShape(bodyId, def, capsule);
      break;
    }
    case 'polygon': {
      const hull = b2.b2ComputeHull(shape.vertices.map(([x, y]) => vec(b2, x, y)));
      b2.b2CreatePolygonShape(bodyId, def, b2.b2MakePolygon(hull, shape.radius ?? 0));
      break;
    }
    case 'segment': {
      const segment = new b2.b2Segment();
      segment.point1 = vec(b2, shape.x1, shape.y1);
      segment.point2 = vec(b2, shape.x2, shape.y2);
      b2.b2CreateSegmentShape(bodyId, def, segment);
      break;
    }
    case 'circle': {
      const circle = new b2.b2Circle();
      circle.center = vec(b2, shape.cx, shape.cy);
      circle.radius = shape.radius;
      b2.b2CreateCircleShape(bodyId, def, circle);
      break;
    }
  }
}

function createWorld(b2: B2, scene: SceneDesc): World {
  const worldDef = b2.b2DefaultWorldDef();
  worldDef.gravity = vec(b2, scene.gravity.x, scene.gravity.y);
  worldDef.enableSleep = scene.sleep;
  const worldId = b2.b2CreateWorld(worldDef);
  const types = {
    static: b2.b2BodyType.b2_staticBody,
    dynamic: b2.b2BodyType.b2_dynamicBody,
    kinematic: b2.b2BodyType.b2_kinematicBody,
  };
  const bodies: BodyId[] = [];
  let ground: BodyId | null = null;
  const makeBody = (desc: BodyDesc): BodyId => {
    const def = b2.b2DefaultBodyDef();
    def.type = types[desc.type];
    def.position = vec(b2, desc.x, desc.y);
    def.rotation = b2.b2MakeRot(desc.angle ?? 0);
    def.linearVelocity = vec(b2, desc.vx ?? 0, desc.vy ?? 0);
    def.angularVelocity = desc.w ?? 0;
    if (desc.asleep) def.isAwake = false;
    if (desc.enableSleep === false) def.enableSleep = false;
    if (desc.linearDamping !== undefined) def.linearDamping = desc.linearDamping;
    if (desc.sleepThreshold !== undefined) def.sleepThreshold = desc.sleepThreshold;
    const id = b2.b2CreateBody(worldId, def);
    for (const shape of desc.shapes) addShape(b2, scene, id, shape, desc.hitEvents ?? false);
    return id;
  };
  const makeJoint = (joint: JointDesc, ids: readonly BodyId[], descs: readonly BodyDesc[]) => {
    const def = b2.b2DefaultRevoluteJointDef();
    const base = def.base;
    base.bodyIdA = ids[joint.a]!;
    base.bodyIdB = ids[joint.b]!;
    const [ax, ay] = localPoint(descs[joint.a]!, joint.x, joint.y);
    const [bx, by] = localPoint(descs[joint.b]!, joint.x, joint.y);
    const frameA = new b2.b2Transform();
    frameA.p = vec(b2, ax, ay);
    // Box2D v3 measures the joint angle between the frames: A's rotation is the reference angle.
    frameA.q = b2.b2MakeRot(joint.referenceAngle ?? 0);
    base.localFrameA = frameA;
    const frameB = new b2.b2Transform();
    frameB.p = vec(b2, bx, by);
    frameB.q = b2.b2MakeRot(0);
    base.localFrameB = frameB;
    def.base = base;
    if (joint.limit) {
      def.enableLimit = true;
      def.lowerAngle = joint.limit.lower;
      def.upperAngle = joint.limit.upper;
    }
    if (joint.motor) {
      def.enableMotor = true;
      def.motorSpeed = joint.motor.speed;
      def.maxMotorTorque = joint.motor.maxTorque;
    }
    if (joint.spring) {
      def.enableSpring = true;
      def.hertz = joint.spring.hertz;
      def.dampingRatio = joint.spring.dampingRatio;
    }
    b2.b2CreateRevoluteJoint(worldId, def);
  };
  for (const desc of scene.bodies) {
    const id = makeBody(desc);
    if (desc.type === 'static' && ground === null) ground = id;
    if (desc.motor) {
      if (ground === null) throw new Error('a motor needs a static body before it');
      const joint = b2.b2DefaultRevoluteJointDef();
      const base = joint.base;
      base.bodyIdA = ground;
      base.bodyIdB = id;
      const frameA = new b2.b2Transform();
      frameA.p = vec(b2, desc.x, desc.y);
      frameA.q = b2.b2MakeRot(0);
      base.localFrameA = frameA;
      const frameB = new b2.b2Transform();
      frameB.p = vec(b2, 0, 0);
      frameB.q = b2.b2MakeRot(0);
      base.localFrameB = frameB;
      joint.base = base;
      joint.enableMotor = true;
      joint.motorSpeed = desc.motor.speed;
      joint.maxMotorTorque = desc.motor.maxTorque;
      b2.b2CreateRevoluteJoint(worldId, joint);
    }
    bodies.push(id);
  }
  for (const joint of scene.joints ?? []) makeJoint(joint, bodies, scene.bodies);
  const target = new b2.b2Transform();
  const targetP = vec(b2, 0, 0);
  return {
    notes: [],
    ...bodyGroups<BodyId>({
      create(group) {
        const ids = group.bodies.map(makeBody);
        for (const joint of group.joints) makeJoint(joint, ids, group.bodies);
        return ids;
      },
      // b2DestroyBody destroys the body's joints too.
      destroy: (id) => b2.b2DestroyBody(id),
      pose(id) {
        const p = b2.b2Body_GetPosition(id);
        return { x: p.x, y: p.y, angle: b2.b2Rot_GetAngle(b2.b2Body_GetRotation(id)) };
      },
    }),
    step() {
      b2.b2World_Step(worldId, DT, SUB_STEPS);
    },
    pose(index): Pose {
      const id = bodies[index]!;
      const p = b2.b2Body_GetPosition(id);
      const angle = b2.b2Rot_GetAngle(b2.b2Body_GetRotation(id));
      return { x: p.x, y: p.y, angle };
    },
    moveKinematicTo(index, x, y, angle) {
      targetP.x = x;
      targetP.y = y;
      target.p = targetP;
      target.q = b2.b2MakeRot(angle);
      b2.b2Body_SetTargetTransform(bodies[index]!, target, DT);
    },
  };
}
