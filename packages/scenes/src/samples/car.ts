import { Body, World, particle, revoluteJoint, wall } from '@physical/engine';
import { defineScene } from '../scene.ts';

/** Terrain heights (m, y-down: negative is up) every 4 m from x = -10, repeated LAPS times. */
const HILLS = [0, 0, 0, -0.5, 0.2, -1, -0.6, 0.4, 0, -1.5, -1.2, 0.5, 0.3, 0, 0, -0.4, 0, 0];

/** Where the road starts (m), and how many times the hills repeat along it. */
const START_X = -10;
const LAPS = 3;

/**
 * A car on hilly ground: a chassis and two wheels on revolute joints whose motors turn the
 * wheels. Friction between tyres and ground drives it forward, and the camera follows it.
 */
export default defineScene({
  id: 'car',
  title: 'Car on terrain',
  description:
    'A chassis on two wheels; each wheel hangs on a revolute joint with a motor. Friction at the tyres turns the motors\u2019 torque into forward drive over the hills.',
  parameters: [
    { name: 'speed', label: 'Motor speed (rad/s)', min: 0, max: 30, step: 1, default: 12 },
    { name: 'torque', label: 'Motor torque (N m)', min: 5, max: 200, step: 5, default: 60 },
  ],
  camera: {
    x: -10,
    y: -8,
    width: 24,
    height: 11,
    // The chassis (the body with two shapes) starts near the left edge: keep it in the left
    // 10-40 % of the view, with the road ahead in sight.
    follow: {
      body: (world) => world.bodies.find((body) => body.shapes.length === 2),
      within: [0.1, 0.4],
    },
  },
  pixelsPerMeter: 40,
  steps: 360,
  build({ speed, torque }) {
    const world = new World();
    // A long road (about 40 s at the default speed), with a barrier at each end.
    const terrain = [HILLS[0]!];
    for (let lap = 0; lap < LAPS; lap++) terrain.push(...HILLS.slice(1));
    for (let i = 0; i + 1 < terrain.length; i++) {
      world.add(
        wall({
          from: { x: START_X + 4 * i, y: terrain[i]! },
          to: { x: START_X + 4 + 4 * i, y: terrain[i + 1]! },
          friction: 0.9,
        }),
      );
    }
    for (const x of [START_X, START_X + 4 * (terrain.length - 1)]) {
      world.add(wall({ from: { x, y: 0 }, to: { x, y: -3 } }));
    }
    const chassis = world.add(
      new Body({
        position: { x: -6, y: -1.2 },
        shapes: [
          { type: 'box', width: 3, height: 0.5, density: 2 },
          { type: 'box', width: 1.4, height: 0.5, offset: { x: -0.2, y: -0.45 }, density: 1 },
        ],
      }),
    );
    for (const dx of [-1.1, 1.1]) {
      const wheel = world.add(
        particle({ position: { x: -6 + dx, y: -0.6 }, radius: 0.45, density: 2, friction: 0.9 }),
      );
      world.addJoint(
        revoluteJoint({
          bodyA: chassis,
          bodyB: wheel,
          anchor: wheel.position,
          enableMotor: true,
          motorSpeed: speed, // positive: clockwise on screen, rolling to the right
          maxMotorTorque: torque,
        }),
      );
    }
    return world;
  },
  check(world, { speed }) {
    const chassis = world.bodies.find((body) => body.shapes.length === 2)!;
    if (Math.abs(chassis.angle) > 1.2)
      return `the car rolled over (angle ${chassis.angle.toFixed(2)} rad)`;
    const travelled = chassis.position.x + 6;
    if (speed >= 5 && travelled < 10) return `the car drove only ${travelled.toFixed(2)} m`;
    return null;
  },
});
