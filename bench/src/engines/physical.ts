import { Body, World as PhysicalWorld, type ShapeOptions } from '@physical/engine';
import {
  DT,
  SUB_STEPS,
  materialOf,
  type Engine,
  type Pose,
  type SceneDesc,
  type ShapeDesc,
  type World,
} from '../types.ts';

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

export const physical: Engine = {
  id: 'physical',
  kind: 'js',
  settings: `subSteps ${SUB_STEPS}, contact 30 Hz / damping 10, push-out 3 m/s, sleep per scene, continuous on (defaults); measured from packages/engine/dist (tsc build)`,
  create(scene) {
    const world = new PhysicalWorld({
      gravity: { x: scene.gravity.x, y: -scene.gravity.y },
      subSteps: SUB_STEPS,
      enableSleep: scene.sleep,
      enableContinuous: true,
    });
    const notes: string[] = [];
    const bodies: Body[] = [];
    for (const desc of scene.bodies) {
      let type = desc.type;
      let w = desc.w ?? 0;
      if (desc.motor) {
        type = 'kinematic';
        w = desc.motor.speed;
        notes.push(
          'no motors yet (joints are being built on another branch): the motor-driven body is a kinematic body turning at the motor speed',
        );
      }
      const body = new Body({
        type,
        position: { x: desc.x, y: -desc.y },
        angle: -(desc.angle ?? 0),
        linearVelocity: { x: desc.vx ?? 0, y: -(desc.vy ?? 0) },
        angularVelocity: -w,
        asleep: desc.asleep ?? false,
        allowSleep: desc.enableSleep ?? true,
        shapes: desc.shapes.map((s) => shapeOptions(scene, s)),
      });
      world.add(body);
      bodies.push(body);
    }
    if (scene.bodies.some((b) => b.hitEvents)) notes.push('no hit-event listener registered');
    return {
      notes: [...new Set(notes)],
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
  },
};
