import {
  Body as P2Body,
  Box,
  Capsule,
  Circle,
  Convex,
  Line,
  RevoluteConstraint,
  World as P2World,
  type Shape,
} from 'p2-es';
import {
  DT,
  centroid,
  materialOf,
  withoutRounding,
  type Engine,
  type Pose,
  type ShapeDesc,
  type World,
} from '../types.ts';

function area(original: ShapeDesc): number {
  if (original.kind === 'capsule') {
    const length = Math.hypot(original.x2 - original.x1, original.y2 - original.y1);
    return 2 * original.radius * length + Math.PI * original.radius * original.radius;
  }
  const shape = withoutRounding(original);
  switch (shape.kind) {
    case 'box':
      return 4 * shape.hw * shape.hh;
    case 'circle':
      return Math.PI * shape.radius * shape.radius;
    case 'segment':
      return 0;
    case 'polygon': {
      let a = 0;
      const v = shape.vertices;
      for (let i = 0; i < v.length; i++) {
        const [x1, y1] = v[i]!;
        const [x2, y2] = v[(i + 1) % v.length]!;
        a += x1 * y2 - x2 * y1;
      }
      return a / 2;
    }
  }
}

/**
 * p2-es (p2.js in ES modules): Gauss-Seidel solver with its default 10 iterations, SAP broadphase,
 * world.step(1/60) as one fixed step. p2 has no per-shape density, so each body's mass is the scene's
 * density times its area; it mixes friction per material pair, so the scene's friction goes on the
 * default contact material; its bodies' default damping (0.1) is set to 0, as the scenes have none.
 */
export const p2Engine: Engine = {
  id: 'p2-es',
  kind: 'js',
  unsupported: {
    rain: 'adapter not built for rain: no body creation/destruction while running, no revolute joint limits/spring wiring yet',
  },
  settings:
    'p2-es defaults: GSSolver 10 iterations, SAPBroadphase, island split on, no sub-steps, no CCD (ccdSpeedThreshold -1); sleep per scene (BODY_SLEEPING); body damping set to 0 (p2 default 0.1); friction on the default contact material; revolute motor where the scene has one',
  create(scene) {
    const world = new P2World({ gravity: [scene.gravity.x, scene.gravity.y] });
    world.sleepMode = scene.sleep ? P2World.BODY_SLEEPING : P2World.NO_SLEEPING;
    world.defaultContactMaterial.friction = scene.material.friction;
    world.defaultContactMaterial.restitution = scene.material.restitution;
    const bodies: P2Body[] = [];
    let ground: P2Body | null = null;
    let rounded = false;
    const types = { static: P2Body.STATIC, dynamic: P2Body.DYNAMIC, kinematic: P2Body.KINEMATIC };
    for (const desc of scene.bodies) {
      const mass =
        desc.type === 'dynamic'
          ? desc.shapes.reduce((m, s) => m + area(s) * materialOf(scene, s).density, 0)
          : 0;
      const body = new P2Body({
        type: types[desc.type],
        mass,
        position: [desc.x, desc.y],
        angle: desc.angle ?? 0,
        velocity: [desc.vx ?? 0, desc.vy ?? 0],
        angularVelocity: desc.w ?? 0,
        damping: 0,
        angularDamping: 0,
      });
      let offCentre = false;
      for (const original of desc.shapes) {
        let s: Shape;
        let offset: [number, number] = [0, 0];
        let angle = 0;
        if (original.kind === 'capsule') {
          // p2's capsule lies along its local x axis, centred.
          const dx = original.x2 - original.x1;
          const dy = original.y2 - original.y1;
          s = new Capsule({ length: Math.hypot(dx, dy), radius: original.radius });
          body.addShape(
            s,
            [(original.x1 + original.x2) / 2, (original.y1 + original.y2) / 2],
            Math.atan2(dy, dx),
          );
          continue;
        }
        const shape = withoutRounding(original);
        if (shape !== original) rounded = true;
        switch (shape.kind) {
          case 'box':
            s = new Box({ width: 2 * shape.hw, height: 2 * shape.hh });
            offset = [shape.cx, shape.cy];
            angle = shape.angle;
            break;
          case 'polygon': {
            const [cx, cy] = centroid(shape.vertices);
            s = new Convex({ vertices: shape.vertices.map(([x, y]) => [x - cx, y - cy]) });
            offset = [cx, cy];
            break;
          }
          case 'segment': {
            const dx = shape.x2 - shape.x1;
            const dy = shape.y2 - shape.y1;
            s = new Line({ length: Math.hypot(dx, dy) });
            offset = [(shape.x1 + shape.x2) / 2, (shape.y1 + shape.y2) / 2];
            angle = Math.atan2(dy, dx);
            break;
          }
          case 'circle':
            s = new Circle({ radius: shape.radius });
            offset = [shape.cx, shape.cy];
            break;
        }
        if (offset[0] !== 0 || offset[1] !== 0) offCentre = true;
        if (scene.shapesCollide === false) {
          // Box2D's joint_grid filter: group 2, colliding with every group but 2.
          s.collisionGroup = 2;
          s.collisionMask = ~2;
        }
        body.addShape(s, offset, angle);
      }
      if (desc.type === 'dynamic' && offCentre) body.adjustCenterOfMass();
      world.addBody(body);
      if (desc.asleep && scene.sleep) body.sleep();
      if (desc.type === 'static' && ground === null) ground = body;
      if (desc.motor && ground) {
        const joint = new RevoluteConstraint(ground, body, { worldPivot: [desc.x, desc.y] });
        joint.enableMotor();
        // p2's motor speed is bodyA's rate relative to bodyB: negate it so bodyB turns at +speed.
        joint.setMotorSpeed(-desc.motor.speed);
        joint.motorMaxForce = desc.motor.maxTorque;
        world.addConstraint(joint);
      }
      bodies.push(body);
    }
    for (const joint of scene.joints ?? []) {
      world.addConstraint(
        new RevoluteConstraint(bodies[joint.a]!, bodies[joint.b]!, {
          worldPivot: [joint.x, joint.y],
          collideConnected: false,
        }),
      );
    }
    return {
      notes: [
        ...(scene.bodies.some((b) => b.shapes.length > 1 && b.type === 'dynamic')
          ? ['compound bodies: pose is the centre of mass (adjustCenterOfMass)']
          : []),
        ...(rounded ? ['rounded boxes as inscribed 8-gons (p2 has no rounded polygons)'] : []),
      ],
      step() {
        world.step(DT);
      },
      pose(index): Pose {
        const body = bodies[index]!;
        return { x: body.position[0], y: body.position[1], angle: body.angle };
      },
      moveKinematicTo(index, x, y, angle) {
        const body = bodies[index]!;
        body.velocity[0] = (x - body.position[0]) / DT;
        body.velocity[1] = (y - body.position[1]) / DT;
        body.angularVelocity = (angle - body.angle) / DT;
      },
    } satisfies World;
  },
};
