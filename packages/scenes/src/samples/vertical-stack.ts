import { World, box, wall } from '@physical/engine';
import { defineScene } from '../scene.ts';

/** A column of equal boxes on the ground: the solver's oldest test. It must stand still. */
export default defineScene({
  id: 'vertical-stack',
  title: 'Vertical stack',
  description:
    'Boxes of 1 m stacked on the ground. A good solver keeps the column upright and lets it fall asleep.',
  parameters: [
    { name: 'count', label: 'Boxes', min: 2, max: 20, step: 1, default: 10 },
    { name: 'friction', label: 'Friction', min: 0.1, max: 1, step: 0.05, default: 0.6 },
  ],
  camera: { x: -6, y: -12, width: 12, height: 13 },
  pixelsPerMeter: 40,
  steps: 300,
  build({ count, friction }) {
    const world = new World();
    world.add(wall({ from: { x: -20, y: 0 }, to: { x: 20, y: 0 }, friction }));
    for (let i = 0; i < count; i++) {
      world.add(box({ position: { x: 0, y: -0.5 - i }, width: 1, height: 1, friction }));
    }
    return world;
  },
  check(world, { count }) {
    const boxes = world.bodies.slice(1);
    for (let i = 0; i < boxes.length; i++) {
      const { x, y } = boxes[i]!.position;
      if (Math.abs(x) > 0.05) return `box ${i} drifted to x = ${x.toFixed(3)} m`;
      if (Math.abs(y - (-0.5 - i)) > 0.05) return `box ${i} is at y = ${y.toFixed(3)} m`;
    }
    return boxes.length === count ? null : `expected ${count} boxes`;
  },
});
