import { World, box, wall } from '@physical/engine';
import { defineScene } from '../scene.ts';

/** A triangle of boxes: many contacts sharing load. It must not lean or slide apart. */
export default defineScene({
  id: 'pyramid',
  title: 'Pyramid',
  description:
    'Rows of half-metre boxes, each row one box shorter. The top must stay above the middle: a lean shows a biased solver.',
  parameters: [{ name: 'rows', label: 'Rows', min: 2, max: 30, step: 1, default: 15 }],
  camera: { x: -9, y: -13, width: 18, height: 14 },
  pixelsPerMeter: 30,
  steps: 300,
  build({ rows }) {
    const world = new World();
    world.add(wall({ from: { x: -30, y: 0 }, to: { x: 30, y: 0 } }));
    const size = 0.5;
    for (let row = 0; row < rows; row++) {
      const count = rows - row;
      for (let i = 0; i < count; i++) {
        const x = (i - (count - 1) / 2) * size * 1.05;
        world.add(box({ position: { x, y: -size / 2 - row * size }, width: size, height: size }));
      }
    }
    return world;
  },
  check(world, { rows }) {
    const top = world.bodies[world.bodies.length - 1]!;
    const expectedY = -0.25 - (rows - 1) * 0.5;
    if (Math.abs(top.position.x) > 0.05) return `top box leans: x = ${top.position.x.toFixed(3)} m`;
    if (Math.abs(top.position.y - expectedY) > 0.1) {
      return `top box sank to y = ${top.position.y.toFixed(3)} m (built at ${expectedY})`;
    }
    return null;
  },
});
