/* global console, require */
/* eslint-disable no-console, @typescript-eslint/no-require-imports -- a CommonJS script on purpose */
// A Node CommonJS script: the packages are ESM only, loaded by require() of ESM (Node >= 20.19).
const assert = require('node:assert/strict');
const { World, box, wall } = require('@physical/engine');
const { PhysicalCanvasElement } = require('@physical/canvas');
const { PhysicalUI } = require('@physical/dom');

const world = new World();
world.add(wall({ from: { x: 0, y: 5 }, to: { x: 10, y: 5 } }));
const crate = world.add(box({ position: { x: 5, y: 0 }, width: 1, height: 1 }));
for (let i = 0; i < 120; i++) world.step(1 / 60);
assert.ok(crate.position.y > 4, `the box fell to the wall (y = ${crate.position.y})`);
assert.equal(typeof PhysicalCanvasElement, 'function');
assert.equal(typeof PhysicalUI, 'function');
console.log(`node require: box at y = ${crate.position.y.toFixed(3)} m`);
