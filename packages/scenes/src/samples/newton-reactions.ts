import { World, particle } from '@physical/engine';
import { seededRandom } from '../random.ts';
import { type SceneValues, defineScene } from '../scene.ts';

/**
 * The thesis's third law: particles of different sizes collide in empty space. Every collision
 * pushes both bodies with equal and opposite impulses, so the total momentum never changes.
 */
export default defineScene({
  id: 'newton-reactions',
  title: 'Newton: reactions',
  description:
    'Third law. Particles of random size and bounciness fly together; every push comes with an equal and opposite one, so their total momentum stays what it was.',
  parameters: [
    { name: 'count', label: 'Particles', min: 2, max: 40, step: 1, default: 16 },
    { name: 'speed', label: 'Speed (m/s)', min: 0.5, max: 5, step: 0.5, default: 2 },
  ],
  camera: { x: -7, y: -5, width: 14, height: 10 },
  pixelsPerMeter: 40,
  steps: 240,
  build: (values) => build(values),
  check(world, values) {
    // Rebuild to read the momentum the particles started with.
    const before = momentum(build(values));
    const after = momentum(world);
    const error = Math.hypot(after.x - before.x, after.y - before.y);
    if (error > 1e-9) return `momentum changed by ${error} kg m/s`;
    return null;
  },
});

function build({ count, speed }: SceneValues): World {
  const world = new World({ gravity: { x: 0, y: 0 }, restitutionThreshold: 0.05 });
  const random = seededRandom(3);
  for (let i = 0; i < count; i++) {
    const angle = (2 * Math.PI * i) / count;
    const distance = 3.5 + random();
    // Aimed near the centre, not at it, with a drift to the right: momentum is not zero.
    const aim = angle + Math.PI + 0.3 * (random() - 0.5);
    world.add(
      particle({
        position: { x: distance * Math.cos(angle), y: distance * Math.sin(angle) },
        radius: 0.15 + 0.3 * random(),
        restitution: random(),
        friction: 0.3,
        linearVelocity: {
          x: speed * Math.cos(aim) + 0.2,
          y: speed * Math.sin(aim),
        },
      }),
    );
  }
  return world;
}

function momentum(world: World): { x: number; y: number } {
  let x = 0;
  let y = 0;
  for (const body of world.bodies) {
    x += body.mass * body.linearVelocity.x;
    y += body.mass * body.linearVelocity.y;
  }
  return { x, y };
}
