import { World, box, particle, wall } from '@physical/engine';
import { define } from '@physical/canvas';

define();
const world = new World(); // metres, y down, gravity 9.81 m/s² toward +y
world.add(wall({ from: { x: 0, y: -40 }, to: { x: 0, y: 7 } })); // a box open at the top:
world.add(wall({ from: { x: 0, y: 7 }, to: { x: 8, y: 7 } })); // the floor, 7 m down,
world.add(wall({ from: { x: 8, y: 7 }, to: { x: 8, y: -40 } })); // between two sides
for (let i = 0; i < 40; i++) {
  const position = { x: 1 + (i % 6), y: -i };
  world.add(
    i % 2 ? box({ position, width: 0.6, height: 0.6 }) : particle({ position, radius: 0.3 }),
  );
}
const canvas = document.querySelector('physical-canvas')!;
canvas.world = world;
canvas.addEventListener('bodytap', ({ detail }) => detail.body?.applyImpulse({ x: 0, y: -5 }));