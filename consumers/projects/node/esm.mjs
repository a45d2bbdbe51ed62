/* global console */
/* eslint-disable no-console -- the script prints what it checked */
// A Node ESM script, as the engine README shows it.
import assert from 'node:assert/strict';
import { World, particle, wall } from '@physical/engine';
import { PhysicalCanvasElement, define } from '@physical/canvas';

const world = new World();
world.add(wall({ from: { x: 0, y: 5 }, to: { x: 10, y: 5 } }));
const ball = world.add(particle({ position: { x: 5, y: 0 }, radius: 0.25, restitution: 0.5 }));
let collisions = 0;
ball.on('collision', () => collisions++);
for (let i = 0; i < 120; i++) world.step(1 / 60);
assert.ok(ball.position.y > 4, `the ball fell to the wall (y = ${ball.position.y})`);
assert.ok(collisions > 0, 'a collision event arrived');
// Without a DOM the element class still loads (server rendering) and define() is a no-op.
assert.equal(define(), PhysicalCanvasElement);
console.log(
  `node esm: ball at y = ${ball.position.y.toFixed(3)} m, ${collisions} collision events`,
);
