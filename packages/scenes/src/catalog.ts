import type { Scene } from './scene.ts';
import bridge from './samples/bridge.ts';
import bulletFlag from './samples/bullet-flag.ts';
import bullets from './samples/bullets.ts';
import collisionFiltering from './samples/collision-filtering.ts';
import capsulesAndRoundedBoxes from './samples/capsules-and-rounded-boxes.ts';
import car from './samples/car.ts';
import concaveShapes from './samples/concave-shapes.ts';
import compoundShapes from './samples/compound-shapes.ts';
import dominoes from './samples/dominoes.ts';
import dragAndThrow from './samples/drag-and-throw.ts';
import fallingPile from './samples/falling-pile.ts';
import forcesWithDurations from './samples/forces-with-durations.ts';
import frictionRamps from './samples/friction-ramps.ts';
import newtonForces from './samples/newton-forces.ts';
import newtonInertia from './samples/newton-inertia.ts';
import newtonReactions from './samples/newton-reactions.ts';
import newtonsCradle from './samples/newtons-cradle.ts';
import pyramid from './samples/pyramid.ts';
import ragdoll from './samples/ragdoll.ts';
import restitutionRow from './samples/restitution-row.ts';
import sensors from './samples/sensors.ts';
import tumbler from './samples/tumbler.ts';
import verticalStack from './samples/vertical-stack.ts';

/** Every sample, in the gallery's order: simple to elaborate, then the thesis's Newton scenes. */
export const scenes: readonly Scene[] = [
  fallingPile,
  verticalStack,
  pyramid,
  restitutionRow,
  frictionRamps,
  newtonsCradle,
  dominoes,
  bridge,
  car,
  ragdoll,
  tumbler,
  bullets,
  bulletFlag,
  sensors,
  collisionFiltering,
  compoundShapes,
  concaveShapes,
  capsulesAndRoundedBoxes,
  dragAndThrow,
  forcesWithDurations,
  newtonInertia,
  newtonForces,
  newtonReactions,
];

/** The sample with this id, or undefined. */
export function findScene(id: string): Scene | undefined {
  return scenes.find((scene) => scene.id === id);
}
