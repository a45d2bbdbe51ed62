import {
  BoxShape,
  CircleShape,
  EdgeShape,
  PolygonShape,
  RevoluteJoint,
  World as PlanckWorld,
  type Body,
  type Shape,
} from 'planck';
import {
  DT,
  materialOf,
  withoutRounding,
  type BodyDesc,
  type Engine,
  type JointDesc,
  type Pose,
  type ShapeDesc,
  type World,
} from '../types.ts';
import { bodyGroups } from './body-groups.ts';

/** planck.js: Box2D v2.3's design in JavaScript. world.step(dt) uses its defaults (8 / 3). */
export const planckEngine: Engine = {
  id: 'planck',
  kind: 'js',
  settings:
    'planck defaults: 8 velocity / 3 position iterations, blockSolve on, warm starting on, continuousPhysics on, no sub-stepping; sleep per scene; revolute motor where the scene has one',
  create(scene) {
    const world = new PlanckWorld({ gravity: scene.gravity, allowSleep: scene.sleep });
    const notes = new Set<string>();
    const makeShape = (original: ShapeDesc): Shape => {
      const shape = withoutRounding(original);
      if (shape !== original)
        notes.add('capsules and rounded boxes as inscribed 8-gons (no such shapes)');
      switch (shape.kind) {
        case 'box':
          return new BoxShape(shape.hw, shape.hh, { x: shape.cx, y: shape.cy }, shape.angle);
        case 'polygon':
          return new PolygonShape(shape.vertices.map(([x, y]) => ({ x, y })));
        case 'segment':
          return new EdgeShape({ x: shape.x1, y: shape.y1 }, { x: shape.x2, y: shape.y2 });
        case 'circle':
          return new CircleShape({ x: shape.cx, y: shape.cy }, shape.radius);
      }
    };
    const bodies: Body[] = [];
    let ground: Body | null = null;
    const makeBody = (desc: BodyDesc): Body => {
      const body = world.createBody({
        type: desc.type,
        position: { x: desc.x, y: desc.y },
        angle: desc.angle ?? 0,
        linearVelocity: { x: desc.vx ?? 0, y: desc.vy ?? 0 },
        angularVelocity: desc.w ?? 0,
        linearDamping: desc.linearDamping ?? 0,
        awake: !(desc.asleep ?? false),
      });
      if (desc.sleepThreshold !== undefined) {
        notes.add('no per-body sleep threshold (world linearSleepTolerance default)');
      }
      for (const shape of desc.shapes) {
        body.createFixture(makeShape(shape), {
          ...materialOf(scene, shape),
          ...(shape.filter
            ? {
                // planck's filter bits are 16-bit.
                filterCategoryBits: shape.filter.category & 0xffff,
                filterMaskBits: shape.filter.mask & 0xffff,
                filterGroupIndex: shape.filter.group,
              }
            : // Box2D's joint_grid filter: category 2, mask ~2, so no two shapes collide.
              scene.shapesCollide === false
              ? { filterCategoryBits: 2, filterMaskBits: 0xfffd }
              : {}),
        });
      }
      return body;
    };
    const makeJoint = (joint: JointDesc, list: readonly Body[]): void => {
      if (joint.spring) notes.add('no revolute spring (Box2D v2.4 design): limits and motor only');
      const bodyA = list[joint.a]!;
      const bodyB = list[joint.b]!;
      const anchor = { x: joint.x, y: joint.y };
      world.createJoint(
        new RevoluteJoint({
          bodyA,
          bodyB,
          localAnchorA: bodyA.getLocalPoint(anchor),
          localAnchorB: bodyB.getLocalPoint(anchor),
          // As Box2D v3's rotated frame A: the joint angle is angleB - angleA - referenceAngle.
          referenceAngle: joint.referenceAngle ?? 0,
          ...(joint.limit
            ? { enableLimit: true, lowerAngle: joint.limit.lower, upperAngle: joint.limit.upper }
            : {}),
          ...(joint.motor
            ? {
                enableMotor: true,
                motorSpeed: joint.motor.speed,
                maxMotorTorque: joint.motor.maxTorque,
              }
            : {}),
        }),
      );
    };
    for (const desc of scene.bodies) {
      const body = makeBody(desc);
      if (desc.type === 'static' && ground === null) ground = body;
      if (desc.motor && ground) {
        world.createJoint(
          new RevoluteJoint(
            {
              enableMotor: true,
              motorSpeed: desc.motor.speed,
              maxMotorTorque: desc.motor.maxTorque,
            },
            ground,
            body,
            { x: desc.x, y: desc.y },
          ),
        );
      }
      bodies.push(body);
    }
    for (const joint of scene.joints ?? []) makeJoint(joint, bodies);
    const velocity = { x: 0, y: 0 };
    return {
      get notes() {
        return [...notes];
      },
      ...bodyGroups<Body>({
        create(group) {
          const list = group.bodies.map(makeBody);
          for (const joint of group.joints) makeJoint(joint, list);
          return list;
        },
        // destroyBody destroys the body's joints too.
        destroy: (body) => world.destroyBody(body),
        pose(body) {
          const p = body.getPosition();
          return { x: p.x, y: p.y, angle: body.getAngle() };
        },
      }),
      step() {
        world.step(DT);
      },
      pose(index): Pose {
        const body = bodies[index]!;
        const p = body.getPosition();
        return { x: p.x, y: p.y, angle: body.getAngle() };
      },
      moveKinematicTo(index, x, y, angle) {
        const body = bodies[index]!;
        const p = body.getPosition();
        velocity.x = (x - p.x) / DT;
        velocity.y = (y - p.y) / DT;
        body.setLinearVelocity(velocity);
        body.setAngularVelocity((angle - body.getAngle()) / DT);
      },
    } satisfies World;
  },
};
