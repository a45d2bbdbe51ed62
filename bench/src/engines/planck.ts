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
  type Engine,
  type Pose,
  type ShapeDesc,
  type World,
} from '../types.ts';

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
    for (const desc of scene.bodies) {
      const body = world.createBody({
        type: desc.type,
        position: { x: desc.x, y: desc.y },
        angle: desc.angle ?? 0,
        linearVelocity: { x: desc.vx ?? 0, y: desc.vy ?? 0 },
        angularVelocity: desc.w ?? 0,
        awake: !(desc.asleep ?? false),
      });
      for (const shape of desc.shapes) {
        body.createFixture(makeShape(shape), materialOf(scene, shape));
      }
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
    const velocity = { x: 0, y: 0 };
    return {
      notes: [...notes],
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
