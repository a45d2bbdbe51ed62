import { type Body, World, box, particle } from '@physical/engine';
import { type HingeRecord, hinge, largestHingeGap } from '../hinges.ts';
import { defineScene } from '../scene.ts';

const hingesOf = new WeakMap<World, HingeRecord[]>();

/**
 * A rope bridge: planks hinged end to end (revolute joints) between two banks, with a load
 * dropped on it. The joints must hold every plank to its neighbours.
 */
export default defineScene({
  id: 'bridge',
  title: 'Bridge',
  description:
    'Planks on revolute joints hang between two banks and catch falling crates and balls. Each hinge keeps the planks joined under the load.',
  parameters: [
    { name: 'planks', label: 'Planks', min: 4, max: 40, step: 1, default: 16 },
    { name: 'load', label: 'Load (kg each)', min: 1, max: 50, step: 1, default: 10 },
  ],
  camera: { x: -1.5, y: -6, width: 20, height: 12 },
  pixelsPerMeter: 40,
  steps: 300,
  build({ planks, load }) {
    const world = new World();
    const hinges: HingeRecord[] = [];
    hingesOf.set(world, hinges);
    const span = 17;
    const length = span / planks;
    const bank = (x: number) =>
      world.add(box({ type: 'static', position: { x, y: 0.25 }, width: 1, height: 0.5 }));
    let previous: Body = bank(-0.5);
    for (let i = 0; i < planks; i++) {
      const plank = world.add(
        box({
          position: { x: (i + 0.5) * length, y: 0.1 },
          width: length,
          height: 0.2,
          density: 20,
        }),
      );
      hinge(world, hinges, previous, plank, { x: i * length, y: 0.1 });
      previous = plank;
    }
    hinge(world, hinges, previous, bank(span + 0.5), { x: span, y: 0.1 });
    const side = Math.sqrt(load / 1); // a square crate of density 1 weighing `load` kg
    for (let i = 0; i < 4; i++) {
      const position = { x: 3 + i * 3.5, y: -3 - i };
      world.add(
        i % 2 === 0
          ? box({
              position,
              width: Math.min(side, 1.5),
              height: Math.min(side, 1.5),
              density: load / Math.min(side, 1.5) ** 2,
            })
          : particle({ position, radius: 0.5, density: load / (Math.PI * 0.25) }),
      );
    }
    return world;
  },
  check(world) {
    const gap = largestHingeGap(hingesOf.get(world)!);
    if (gap > 0.02) return `a hinge opened by ${(100 * gap).toFixed(1)} cm`;
    for (const body of world.bodies) {
      if (body.position.y > 8) return 'a load fell through the bridge';
    }
    return null;
  },
});
