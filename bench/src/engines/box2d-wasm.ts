import type Box2DFactory from 'box2d-wasm';
import { readFileSync } from 'node:fs';
import { createRequire } from 'node:module';
import { dirname, join } from 'node:path';
import {
  DT,
  materialOf,
  withoutRounding,
  type Engine,
  type Pose,
  type SceneDesc,
  type ShapeDesc,
  type World,
} from '../types.ts';

type B2 = Awaited<ReturnType<typeof Box2DFactory>>;
type B2Body = ReturnType<InstanceType<B2['b2World']>['CreateBody']>;

const VELOCITY_ITERATIONS = 8;
const POSITION_ITERATIONS = 3;

/**
 * Box2D v2.4.1 through box2d-wasm. Its package entry fetch()es the .wasm by path, which Node's fetch
 * cannot do, so we load the same build its entry would pick (SIMD when WebAssembly SIMD validates)
 * and hand emscripten the bytes as `wasmBinary`.
 */
export async function loadBox2dWasm(): Promise<Engine> {
  const require = createRequire(import.meta.url);
  const dir = dirname(require.resolve('box2d-wasm'));
  const simd = WebAssembly.validate(
    new Uint8Array([
      0, 97, 115, 109, 1, 0, 0, 0, 1, 5, 1, 96, 0, 1, 123, 3, 2, 1, 0, 10, 10, 1, 8, 0, 65, 0, 253,
      15, 253, 98, 11,
    ]),
  );
  const name = simd ? 'Box2D.simd' : 'Box2D';
  const factory = require(join(dir, `${name}.js`)) as typeof Box2DFactory;
  const bytes = readFileSync(join(dir, `${name}.wasm`));
  const wasmBinary = bytes.buffer.slice(bytes.byteOffset, bytes.byteOffset + bytes.byteLength);
  const b2 = await factory({ wasmBinary });
  return {
    id: 'box2d-wasm',
    kind: 'wasm',
    unsupported: {
      rain: 'adapter not built for rain: it has no body creation/destruction while running (Box2D v2.4 has no capsules, no revolute spring)',
    },
    settings: `Box2D v2.4.1 (${name}.wasm): ${VELOCITY_ITERATIONS} velocity / ${POSITION_ITERATIONS} position iterations (v2's usual default), no sub-steps, sleep per scene, continuous on (default), revolute motor where the scene has one`,
    create: (scene) => createWorld(b2, scene),
  };
}

function createWorld(b2: B2, scene: SceneDesc): World {
  const world = new b2.b2World(new b2.b2Vec2(scene.gravity.x, scene.gravity.y));
  world.SetAllowSleeping(scene.sleep);
  world.SetContinuousPhysics(true);
  const types = {
    static: b2.b2_staticBody,
    dynamic: b2.b2_dynamicBody,
    kinematic: b2.b2_kinematicBody,
  };
  const vertexBuffer = b2._malloc(8 * 8);
  const notes = new Set<string>();
  const addShape = (body: B2Body, original: ShapeDesc): void => {
    const shape = withoutRounding(original);
    if (shape !== original)
      notes.add('capsules and rounded boxes as inscribed 8-gons (no such shapes)');
    const m = materialOf(scene, shape);
    const fd = new b2.b2FixtureDef();
    fd.set_density(m.density);
    fd.set_friction(m.friction);
    fd.set_restitution(m.restitution);
    if (scene.shapesCollide === false) {
      // Box2D's joint_grid filter: category 2, mask ~2, so no two shapes collide.
      const filter = fd.get_filter();
      filter.set_categoryBits(2);
      filter.set_maskBits(0xfffd);
      fd.set_filter(filter);
    }
    switch (shape.kind) {
      case 'box': {
        const s = new b2.b2PolygonShape();
        s.SetAsBox(shape.hw, shape.hh, new b2.b2Vec2(shape.cx, shape.cy), shape.angle);
        fd.set_shape(s);
        break;
      }
      case 'polygon': {
        const s = new b2.b2PolygonShape();
        shape.vertices.forEach(([x, y], i) => {
          b2.HEAPF32[(vertexBuffer >> 2) + 2 * i] = x;
          b2.HEAPF32[(vertexBuffer >> 2) + 2 * i + 1] = y;
        });
        s.Set(vertexBuffer, shape.vertices.length);
        fd.set_shape(s);
        break;
      }
      case 'segment': {
        const s = new b2.b2EdgeShape();
        s.SetTwoSided(new b2.b2Vec2(shape.x1, shape.y1), new b2.b2Vec2(shape.x2, shape.y2));
        fd.set_shape(s);
        break;
      }
      case 'circle': {
        const s = new b2.b2CircleShape();
        s.set_m_radius(shape.radius);
        s.set_m_p(new b2.b2Vec2(shape.cx, shape.cy));
        fd.set_shape(s);
        break;
      }
    }
    body.CreateFixture(fd);
  };
  const bodies: B2Body[] = [];
  let ground: B2Body | null = null;
  for (const desc of scene.bodies) {
    const bd = new b2.b2BodyDef();
    bd.set_type(types[desc.type]);
    bd.set_position(new b2.b2Vec2(desc.x, desc.y));
    bd.set_angle(desc.angle ?? 0);
    bd.set_linearVelocity(new b2.b2Vec2(desc.vx ?? 0, desc.vy ?? 0));
    bd.set_angularVelocity(desc.w ?? 0);
    if (desc.asleep) bd.set_awake(false);
    const body = world.CreateBody(bd);
    for (const shape of desc.shapes) addShape(body, shape);
    if (desc.type === 'static' && ground === null) ground = body;
    if (desc.motor && ground) {
      const jd = new b2.b2RevoluteJointDef();
      jd.Initialize(ground, body, new b2.b2Vec2(desc.x, desc.y));
      jd.set_enableMotor(true);
      jd.set_motorSpeed(desc.motor.speed);
      jd.set_maxMotorTorque(desc.motor.maxTorque);
      world.CreateJoint(jd);
    }
    bodies.push(body);
  }
  for (const joint of scene.joints ?? []) {
    const jd = new b2.b2RevoluteJointDef();
    jd.Initialize(bodies[joint.a]!, bodies[joint.b]!, new b2.b2Vec2(joint.x, joint.y));
    world.CreateJoint(jd);
  }
  const velocity = new b2.b2Vec2(0, 0);
  return {
    notes: [...notes],
    step() {
      world.Step(DT, VELOCITY_ITERATIONS, POSITION_ITERATIONS);
    },
    pose(index): Pose {
      const body = bodies[index]!;
      const p = body.GetPosition();
      return { x: p.get_x(), y: p.get_y(), angle: body.GetAngle() };
    },
    moveKinematicTo(index, x, y, angle) {
      const body = bodies[index]!;
      const p = body.GetPosition();
      velocity.Set((x - p.get_x()) / DT, (y - p.get_y()) / DT);
      body.SetLinearVelocity(velocity);
      body.SetAngularVelocity((angle - body.GetAngle()) / DT);
    },
  };
}
