import {
  b2BodyType,
  b2CircleShape,
  b2EdgeShape,
  b2PolygonShape,
  b2RevoluteJointDef,
  b2World,
  type b2Body,
  type b2Shape,
} from '@box2d/core';
import {
  DT,
  materialOf,
  withoutRounding,
  type Engine,
  type Pose,
  type ShapeDesc,
  type World,
} from '../types.ts';

const ITERATIONS = { velocityIterations: 8, positionIterations: 3 };

/** Box2D v2.4 ported to TypeScript (@box2d/core, Lusito). */
export const box2dCore: Engine = {
  id: '@box2d/core',
  kind: 'js',
  unsupported: {
    rain: 'adapter not built for rain: it has no body creation/destruction while running (Box2D v2.4 has no capsules, no revolute spring)',
  },
  settings: `Box2D v2.4 TS port: ${ITERATIONS.velocityIterations} velocity / ${ITERATIONS.positionIterations} position iterations (v2's usual default), no sub-steps, sleep per scene, continuous on (default), revolute motor where the scene has one`,
  create(scene) {
    const world = b2World.Create(scene.gravity);
    world.SetAllowSleeping(scene.sleep);
    const types = {
      static: b2BodyType.b2_staticBody,
      dynamic: b2BodyType.b2_dynamicBody,
      kinematic: b2BodyType.b2_kinematicBody,
    };
    const notes = new Set<string>();
    const makeShape = (original: ShapeDesc): b2Shape => {
      const shape = withoutRounding(original);
      if (shape !== original)
        notes.add('capsules and rounded boxes as inscribed 8-gons (no such shapes)');
      switch (shape.kind) {
        case 'box':
          return new b2PolygonShape().SetAsBox(
            shape.hw,
            shape.hh,
            { x: shape.cx, y: shape.cy },
            shape.angle,
          );
        case 'polygon': {
          const s = new b2PolygonShape();
          s.Set(shape.vertices.map(([x, y]) => ({ x, y })));
          return s;
        }
        case 'segment':
          return new b2EdgeShape().SetTwoSided(
            { x: shape.x1, y: shape.y1 },
            { x: shape.x2, y: shape.y2 },
          );
        case 'circle': {
          const s = new b2CircleShape(shape.radius);
          s.m_p.Set(shape.cx, shape.cy);
          return s;
        }
      }
    };
    const bodies: b2Body[] = [];
    let ground: b2Body | null = null;
    for (const desc of scene.bodies) {
      const body = world.CreateBody({
        type: types[desc.type],
        position: { x: desc.x, y: desc.y },
        angle: desc.angle ?? 0,
        linearVelocity: { x: desc.vx ?? 0, y: desc.vy ?? 0 },
        angularVelocity: desc.w ?? 0,
        awake: !(desc.asleep ?? false),
      });
      for (const shape of desc.shapes) {
        body.CreateFixture({
          shape: makeShape(shape),
          ...materialOf(scene, shape),
          // Box2D's joint_grid filter: category 2, mask ~2, so no two shapes collide.
          ...(scene.shapesCollide === false
            ? { filter: { categoryBits: 2, maskBits: 0xfffd } }
            : {}),
        });
      }
      if (desc.type === 'static' && ground === null) ground = body;
      if (desc.motor && ground) {
        const jd = new b2RevoluteJointDef();
        jd.Initialize(ground, body, { x: desc.x, y: desc.y });
        jd.enableMotor = true;
        jd.motorSpeed = desc.motor.speed;
        jd.maxMotorTorque = desc.motor.maxTorque;
        world.CreateJoint(jd);
      }
      bodies.push(body);
    }
    for (const joint of scene.joints ?? []) {
      const jd = new b2RevoluteJointDef();
      jd.Initialize(bodies[joint.a]!, bodies[joint.b]!, { x: joint.x, y: joint.y });
      world.CreateJoint(jd);
    }
    const velocity = { x: 0, y: 0 };
    return {
      notes: [...notes],
      step() {
        world.Step(DT, ITERATIONS);
      },
      pose(index): Pose {
        const body = bodies[index]!;
        const p = body.GetPosition();
        return { x: p.x, y: p.y, angle: body.GetAngle() };
      },
      moveKinematicTo(index, x, y, angle) {
        const body = bodies[index]!;
        const p = body.GetPosition();
        velocity.x = (x - p.x) / DT;
        velocity.y = (y - p.y) / DT;
        body.SetLinearVelocity(velocity);
        body.SetAngularVelocity((angle - body.GetAngle()) / DT);
      },
    } satisfies World;
  },
};
