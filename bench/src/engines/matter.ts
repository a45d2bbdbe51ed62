import Matter, { type BodyOptions, type MatterBody } from 'matter-js';
import {
  DT,
  centroid,
  materialOf,
  withoutRounding,
  type Engine,
  type Pose,
  type SceneDesc,
  type ShapeDesc,
  type World,
} from '../types.ts';

/** matter-js works in pixels: 1 m = SCALE units, so its pixel-sized tolerances (slop 0.05) fit. */
const SCALE = 50;
/** Segments become static rectangles this thick (m), top face on the segment. */
const SEGMENT_THICKNESS = 0.2;

interface Moving {
  body: MatterBody;
  /** Centre of mass relative to the body origin, body frame, Box2D axes (m). */
  lx: number;
  ly: number;
  x: number;
  y: number;
  angle: number;
  vx: number;
  vy: number;
  w: number;
}

/**
 * matter-js: y-down like Physical, so y is mirrored. No kinematic bodies, motors or segments:
 * kinematic and motor-driven bodies are static bodies moved by Body.setPosition/setAngle every step,
 * segments are thin static rectangles. Matter's default air friction (0.01) is set to 0 since the
 * scenes have no damping; density is scaled by matter's default 0.001.
 */
export const matterEngine: Engine = {
  id: 'matter-js',
  kind: 'js',
  unsupported: {
    rain: 'no revolute joints with angle limits, motors or springs (matter-js constraints are pins)',
  },
  settings: `matter-js defaults: positionIterations 6, velocityIterations 4, constraintIterations 2, slop 0.05, no sub-steps, no CCD; Engine.update(1000/60 ms); 1 m = ${SCALE} px; sleep per scene (enableSleeping); frictionAir set to 0; no kinematic bodies or motors (static bodies moved with setPosition/setAngle each step); segments as ${SEGMENT_THICKNESS} m static rectangles`,
  create: (scene) => createWorld(scene),
};

function createWorld(scene: SceneDesc): World {
  const engine = Matter.Engine.create({ enableSleeping: scene.sleep });
  engine.gravity.x = (scene.gravity.x * SCALE) / 1000 / engine.gravity.scale / 1000;
  engine.gravity.y = (-scene.gravity.y * SCALE) / 1000 / engine.gravity.scale / 1000;
  const notes = new Set<string>();

  // A part at its world position (matter y-down pixels) for a body at (bx, by, angle) in Box2D's frame.
  const makePart = (
    original: ShapeDesc,
    bx: number,
    by: number,
    bangle: number,
    options: BodyOptions,
  ): MatterBody => {
    const cos = Math.cos(bangle);
    const sin = Math.sin(bangle);
    const toWorld = (lx: number, ly: number): [number, number] => [
      bx + cos * lx - sin * ly,
      by + sin * lx + cos * ly,
    ];
    const shape = withoutRounding(original);
    if (shape !== original)
      notes.add('capsules and rounded boxes as inscribed 8-gons (no such shapes)');
    switch (shape.kind) {
      case 'box': {
        const [x, y] = toWorld(shape.cx, shape.cy);
        return Matter.Bodies.rectangle(
          x * SCALE,
          -y * SCALE,
          2 * shape.hw * SCALE,
          2 * shape.hh * SCALE,
          {
            ...options,
            angle: -(bangle + shape.angle),
          },
        );
      }
      case 'polygon': {
        const [cx, cy] = centroid(shape.vertices);
        const [x, y] = toWorld(cx, cy);
        const vertices = shape.vertices.map(([vx, vy]) => {
          const [wx, wy] = toWorld(vx, vy);
          return { x: wx * SCALE, y: -wy * SCALE };
        });
        return Matter.Bodies.fromVertices(x * SCALE, -y * SCALE, [vertices], options);
      }
      case 'segment': {
        const [x1, y1] = toWorld(shape.x1, shape.y1);
        const [x2, y2] = toWorld(shape.x2, shape.y2);
        const length = Math.hypot(x2 - x1, y2 - y1);
        const angle = Math.atan2(y2 - y1, x2 - x1);
        // Centre half a thickness below the segment (in Box2D's frame), so the top face is on it.
        const nx = Math.sin(angle) * 0.5 * SEGMENT_THICKNESS;
        const ny = -Math.cos(angle) * 0.5 * SEGMENT_THICKNESS;
        notes.add(`segments as ${SEGMENT_THICKNESS} m thick static rectangles`);
        return Matter.Bodies.rectangle(
          ((x1 + x2) / 2 + nx) * SCALE,
          -((y1 + y2) / 2 + ny) * SCALE,
          length * SCALE,
          SEGMENT_THICKNESS * SCALE,
          { ...options, angle: -angle },
        );
      }
      case 'circle': {
        const [x, y] = toWorld(shape.cx, shape.cy);
        return Matter.Bodies.circle(x * SCALE, -y * SCALE, shape.radius * SCALE, options);
      }
    }
  };

  const bodies: MatterBody[] = [];
  const moving: Moving[] = [];
  const all: MatterBody[] = [];
  for (const desc of scene.bodies) {
    const angle = desc.angle ?? 0;
    const driven = desc.type === 'kinematic' || desc.motor !== undefined;
    const isStatic = desc.type !== 'dynamic' || driven;
    const partOptions = (shape: ShapeDesc): BodyOptions => {
      const m = materialOf(scene, shape);
      return {
        isStatic,
        density: m.density * 0.001,
        friction: m.friction,
        restitution: m.restitution,
        frictionAir: 0,
        // Box2D's joint_grid filter: category 2, colliding with every category but 2.
        ...(scene.shapesCollide === false
          ? { collisionFilter: { category: 2, mask: 0xfffffffd } }
          : {}),
      };
    };
    let body: MatterBody;
    if (desc.shapes.length === 0) {
      body = Matter.Body.create({ isStatic: true });
      Matter.Body.setPosition(body, { x: desc.x * SCALE, y: -desc.y * SCALE });
      bodies.push(body);
      continue;
    }
    if (desc.shapes.length === 1) {
      body = makePart(desc.shapes[0]!, desc.x, desc.y, angle, partOptions(desc.shapes[0]!));
    } else if (desc.type === 'static') {
      // A static compound would be one broad-phase entry spanning the whole floor; matter users add
      // separate static bodies, and so do we. The first one stands for the body.
      const parts = desc.shapes.map((s) => makePart(s, desc.x, desc.y, angle, partOptions(s)));
      all.push(...parts);
      bodies.push(parts[0]!);
      continue;
    } else {
      const parts = desc.shapes.map((s) => makePart(s, desc.x, desc.y, angle, partOptions(s)));
      body = Matter.Body.create({ parts, isStatic, frictionAir: 0 });
    }
    if (driven) {
      notes.add(
        desc.motor
          ? 'no motors or kinematic bodies: the container is a static body turned by setAngle each step'
          : 'no kinematic bodies: a static body moved by setPosition/setAngle each step',
      );
      const comX = body.position.x / SCALE - desc.x;
      const comY = -body.position.y / SCALE - desc.y;
      moving.push({
        body,
        lx: Math.cos(angle) * comX + Math.sin(angle) * comY,
        ly: -Math.sin(angle) * comX + Math.cos(angle) * comY,
        x: desc.x,
        y: desc.y,
        angle,
        vx: desc.vx ?? 0,
        vy: desc.vy ?? 0,
        w: desc.motor ? desc.motor.speed : (desc.w ?? 0),
      });
    } else if (desc.type === 'dynamic') {
      Matter.Body.setVelocity(body, {
        x: ((desc.vx ?? 0) * SCALE) / 60,
        y: (-(desc.vy ?? 0) * SCALE) / 60,
      });
      Matter.Body.setAngularVelocity(body, -(desc.w ?? 0) / 60);
      if (desc.asleep && scene.sleep) Matter.Sleeping.set(body, true);
    }
    all.push(body);
    bodies.push(body);
  }
  Matter.Composite.add(engine.world, all);
  // Revolute joints as matter's pin constraints (length 0, stiffness 1), at the anchor seen from
  // each body's centre; matter has no joint limits or motors.
  const constraints = (scene.joints ?? []).map((joint) => {
    const a = bodies[joint.a]!;
    const b = bodies[joint.b]!;
    const x = joint.x * SCALE;
    const y = -joint.y * SCALE;
    return Matter.Constraint.create({
      bodyA: a,
      bodyB: b,
      pointA: { x: x - a.position.x, y: y - a.position.y },
      pointB: { x: x - b.position.x, y: y - b.position.y },
      length: 0,
      stiffness: 1,
    });
  });
  if (constraints.length > 0) {
    Matter.Composite.add(engine.world, constraints);
    notes.add('revolute joints as pin constraints (length 0, stiffness 1)');
  }
  if (scene.bodies.some((b) => b.shapes.length > 1 && b.type === 'dynamic')) {
    notes.add('compound bodies: pose is the centre of mass');
  }

  const place = (m: Moving): void => {
    const cos = Math.cos(m.angle);
    const sin = Math.sin(m.angle);
    const x = m.x + cos * m.lx - sin * m.ly;
    const y = m.y + sin * m.lx + cos * m.ly;
    Matter.Body.setPosition(m.body, { x: x * SCALE, y: -y * SCALE }, true);
    Matter.Body.setAngle(m.body, -m.angle, true);
  };
  const movingByIndex = new Map<number, Moving>();
  scene.bodies.forEach((_, i) => {
    const m = moving.find((mm) => mm.body === bodies[i]);
    if (m) movingByIndex.set(i, m);
  });
  const targets = new Set<Moving>();
  return {
    notes: [...notes],
    step() {
      for (const m of moving) {
        if (targets.has(m)) continue;
        m.x += m.vx * DT;
        m.y += m.vy * DT;
        m.angle += m.w * DT;
        place(m);
      }
      targets.clear();
      Matter.Engine.update(engine, 1000 * DT);
    },
    pose(index): Pose {
      const body = bodies[index]!;
      return { x: body.position.x / SCALE, y: -body.position.y / SCALE, angle: -body.angle };
    },
    moveKinematicTo(index, x, y, angle) {
      const m = movingByIndex.get(index);
      if (!m) return;
      m.x = x;
      m.y = y;
      m.angle = angle;
      place(m);
      targets.add(m);
    },
  };
}
