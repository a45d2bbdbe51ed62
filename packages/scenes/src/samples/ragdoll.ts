import { type Body, World, box, capsule, particle } from '@physical/engine';
import { type HingeRecord, hinge, largestHingeGap } from '../hinges.ts';
import { defineScene } from '../scene.ts';

const hingesOf = new WeakMap<World, HingeRecord[]>();

/** One ragdoll: capsule limbs on revolute joints with angle limits, head a particle. */
function ragdoll(world: World, hinges: HingeRecord[], x: number, y: number, stiffness: number) {
  const limb = (cx: number, cy: number, length: number, angle: number) =>
    world.add(capsule({ position: { x: x + cx, y: y + cy }, length, radius: 0.12, angle }));
  const torso = limb(0, 0, 0.6, Math.PI / 2);
  const head = world.add(particle({ position: { x, y: y - 0.62 }, radius: 0.2 }));
  const joint = (a: Body, b: Body, ax: number, ay: number, lower: number, upper: number) =>
    hinge(
      world,
      hinges,
      a,
      b,
      { x: x + ax, y: y + ay },
      {
        enableLimit: true,
        lowerAngle: lower,
        upperAngle: upper,
        // A weak motor at zero speed is a joint's friction: the doll sags rather than flops.
        enableMotor: stiffness > 0,
        motorSpeed: 0,
        maxMotorTorque: stiffness,
      },
    );
  joint(torso, head, 0, -0.42, -0.5, 0.5);
  for (const side of [-1, 1]) {
    const upperArm = limb(side * 0.35, -0.3, 0.35, 0);
    const lowerArm = limb(side * 0.8, -0.3, 0.35, 0);
    joint(torso, upperArm, side * 0.12, -0.3, -1.5, 1.5);
    joint(upperArm, lowerArm, side * 0.58, -0.3, side < 0 ? 0 : -2, side < 0 ? 2 : 0);
    const thigh = limb(side * 0.12, 0.65, 0.35, Math.PI / 2);
    const shin = limb(side * 0.12, 1.12, 0.35, Math.PI / 2);
    joint(torso, thigh, side * 0.12, 0.42, -1.2, 1.2);
    joint(thigh, shin, side * 0.12, 0.88, side < 0 ? -2 : -2, 0);
  }
}

/**
 * Ragdolls tumbling down stairs: capsule limbs on revolute joints with angle limits (elbows and
 * knees bend one way) and a little joint friction.
 */
export default defineScene({
  id: 'ragdoll',
  title: 'Ragdolls',
  description:
    'Dolls of capsules held by revolute joints with angle limits fall down a flight of stairs. Knees and elbows bend only one way; joint friction sets how limp they are.',
  parameters: [
    { name: 'count', label: 'Ragdolls', min: 1, max: 6, step: 1, default: 3 },
    { name: 'stiffness', label: 'Joint friction (N m)', min: 0, max: 5, step: 0.5, default: 1 },
  ],
  camera: { x: -1, y: -9, width: 16, height: 11 },
  pixelsPerMeter: 40,
  steps: 360,
  build({ count, stiffness }) {
    const world = new World();
    const hinges: HingeRecord[] = [];
    hingesOf.set(world, hinges);
    for (let i = 0; i < 8; i++) {
      world.add(
        box({
          type: 'static',
          position: { x: 1 + 1.5 * i, y: -5 + 0.7 * i },
          width: 1.5,
          height: 0.2,
        }),
      );
    }
    world.add(box({ type: 'static', position: { x: 7, y: 1 }, width: 18, height: 0.4 }));
    for (let i = 0; i < count; i++) ragdoll(world, hinges, 1 + 0.9 * i, -7 - 2.6 * i, stiffness);
    return world;
  },
  check(world) {
    const gap = largestHingeGap(hingesOf.get(world)!);
    if (gap > 0.05) return `a joint came apart by ${(100 * gap).toFixed(1)} cm`;
    for (const body of world.bodies)
      if (body.position.y > 1) return 'a limb fell through the floor';
    return null;
  },
});
