// Run by removal-releases-memory.test.ts in a child process with --expose-gc (vitest's own
// workers cannot collect on demand). Prints one line of JSON: what was collected, and the heap.
import { World, box, capsule, particle, revoluteJoint, type Body } from '../../src/index.ts';

const gc = (globalThis as { gc?: () => void }).gc;
if (gc === undefined) throw new Error('run with node --expose-gc');
const total = Number(process.argv[2] ?? 100_000);
const batch = Number(process.argv[3] ?? 10_000);

async function settle(): Promise<void> {
  for (let i = 0; i < 6; i++) {
    gc!();
    await new Promise((resolve) => setTimeout(resolve, 0));
  }
}

async function heap(): Promise<number> {
  await settle();
  return process.memoryUsage().heapUsed;
}

function scene(): World {
  const world = new World({ gravity: { x: 0, y: 10 } });
  world.add(box({ type: 'static', position: { x: 0, y: 60 }, width: 1000, height: 1 }));
  world.add(particle({ type: 'kinematic', radius: 3, sensor: true, position: { x: 0, y: 55 } }));
  return world;
}

/** A batch of bodies of every shape kind, some joined, resting on the ground and each other. */
function fill(world: World, count: number, userData: (i: number) => object): Body[] {
  const bodies: Body[] = [];
  for (let i = 0; i < count; i++) {
    const position = { x: (i % 400) * 1.1 - 220, y: 59 - Math.floor(i / 400) * 1.1 };
    const kind = i % 3;
    const body =
      kind === 0
        ? box({ width: 0.5, height: 0.5, position, userData: userData(i) })
        : kind === 1
          ? particle({ radius: 0.25, position, bullet: i % 30 === 1, userData: userData(i) })
          : capsule({ length: 0.4, radius: 0.2, position, userData: userData(i) });
    bodies.push(world.add(body));
    if (i % 50 === 2) {
      world.addJoint(revoluteJoint({ bodyA: bodies[i - 1]!, bodyB: body, anchor: position }));
    }
  }
  return bodies;
}

// Warm up: the engine's code compiled, so the baseline holds it too.
{
  const warm = scene();
  for (const body of fill(warm, 2000, () => ({}))) void body;
  for (let s = 0; s < 5; s++) warm.step(1 / 60);
  warm.clear();
}
const world = scene();
world.step(1 / 60);
const empty = await heap();

let collectedBodies = 0;
let collectedData = 0;
const registry = new FinalizationRegistry<'body' | 'data'>((what) => {
  if (what === 'body') collectedBodies++;
  else collectedData++;
});
let watched = 0;
// Watched: bodies of the first and the last batch; the last batch is removed with no step after.
const run = (): void => {
  for (let start = 0; start < total; start += batch) {
    const isWatched = start === 0 || start + batch >= total;
    const bodies = fill(world, batch, (i) => ({ index: i, payload: new Array(32).fill(i) }));
    if (isWatched) {
      for (const body of bodies) {
        registry.register(body, 'body');
        registry.register(body.userData as object, 'data');
        watched++;
      }
    }
    for (let s = 0; s < 4; s++) world.step(1 / 60);
    for (const body of bodies) world.remove(body);
  }
};
run();
const after = await heap();
await settle();
// eslint-disable-next-line no-console -- the probe's one line of output, read by the test
console.log(
  JSON.stringify({
    watched,
    collectedBodies,
    collectedData,
    empty,
    after,
    bodies: world.bodies.length,
  }),
);
