// Run by steady-steps-allocate-nothing.test.ts in a child node (flags there): steps one scene past
// its warm-up, then counts the bytes the young generation grew over the measured steps, with a new
// space large enough that nothing is collected in between, so the growth is what the steps
// allocated (short-lived objects, such as the heap numbers V8 boxes doubles into, start there;
// code compiled meanwhile does not). Prints one line of JSON.
import { PerformanceObserver } from 'node:perf_hooks';
import { getHeapSpaceStatistics } from 'node:v8';
import {
  Body,
  World,
  box,
  particle,
  revoluteJoint,
  type BoxShapeOptions,
} from '../../src/index.ts';

const gc = (globalThis as { gc?: () => void }).gc;
if (gc === undefined) throw new Error('run with node --expose-gc');
const [scene = 'drum', warmupText = '1500', stepsText = '500'] = process.argv.slice(2);
const warmup = Number(warmupText);
const steps = Number(stepsText);
const DT = 1 / 60;

/** Box2D's tumbler, smaller: a 9.5 m drum turned by a motor, 400 boxes tumbling in it, sleep on. */
function drum(): { world: World; onStep(step: number): void } {
  const world = new World({ gravity: { x: 0, y: 10 } });
  const ground = world.add(box({ type: 'static', position: { x: 0, y: 20 }, width: 1, height: 1 }));
  const wall = (width: number, height: number, x: number, y: number): BoxShapeOptions => ({
    type: 'box',
    width,
    height,
    offset: { x, y },
    density: 50,
  });
  const container = world.add(
    new Body({
      position: { x: 0, y: 0 },
      shapes: [
        wall(0.5, 9.5, -4.5, 0),
        wall(0.5, 9.5, 4.5, 0),
        wall(9.5, 0.5, 0, -4.5),
        wall(9.5, 0.5, 0, 4.5),
      ],
    }),
  );
  world.addJoint(
    revoluteJoint({
      bodyA: ground,
      bodyB: container,
      anchor: { x: 0, y: 0 },
      enableMotor: true,
      motorSpeed: (25 * Math.PI) / 180,
      maxMotorTorque: 1e8,
    }),
  );
  for (let i = 0; i < 20; i++) {
    for (let j = 0; j < 20; j++) {
      world.add(box({ position: { x: -4 + 0.4 * j, y: -4 + 0.4 * i }, width: 0.25, height: 0.25 }));
    }
  }
  return { world, onStep() {} };
}

/** A resting 20-row pyramid, sleep off (the bench's large_pyramid, smaller). */
function pyramid(): { world: World; onStep(step: number): void } {
  const world = new World({ gravity: { x: 0, y: 10 }, enableSleep: false });
  world.add(box({ type: 'static', position: { x: 0, y: 0.5 }, width: 40, height: 1 }));
  const rows = 20;
  for (let row = 0; row < rows; row++) {
    for (let i = 0; i < rows - row; i++) {
      const x = (i - (rows - row - 1) / 2) * 1.05;
      world.add(box({ position: { x, y: -0.5 - row * 1.0 }, width: 1, height: 1 }));
    }
  }
  return { world, onStep() {} };
}

/**
 * A pile that falls asleep, then is woken by a push every 120 steps (a particle and a box thrown
 * in at it), so islands fall asleep and wake again through the measured steps.
 */
function waking(): { world: World; onStep(step: number): void } {
  const world = new World({ gravity: { x: 0, y: 10 } });
  world.add(box({ type: 'static', position: { x: 0, y: 0.5 }, width: 30, height: 1 }));
  const bodies: Body[] = [];
  for (let i = 0; i < 200; i++) {
    const position = { x: -5 + (i % 20) * 0.55, y: -0.3 - Math.floor(i / 20) * 0.55 };
    bodies.push(
      world.add(
        i % 2 === 0
          ? box({ position, width: 0.5, height: 0.5 })
          : particle({ position, radius: 0.25 }),
      ),
    );
  }
  return {
    world,
    onStep(step: number) {
      if (step % 120 !== 0) return;
      const body = bodies[(step / 120) % bodies.length]!;
      body.applyImpulse({ x: 0, y: -2 * body.mass }, body.position);
    },
  };
}

/**
 * A chain of 30 hinges with a heavy last link, falling from level (the pin chains' exact solve);
 * its first links sweep past their static anchor (the sweeps' time of impact).
 */
function chain(): { world: World; onStep(step: number): void } {
  const world = new World({ gravity: { x: 0, y: 10 }, enableSleep: false });
  const ground = world.add(box({ type: 'static', position: { x: 0, y: 0 }, width: 1, height: 1 }));
  let last = ground;
  for (let i = 0; i < 30; i++) {
    const link = world.add(
      box({
        position: { x: 0.5 + i, y: 0 },
        width: 1,
        height: 0.1,
        density: i === 29 ? 100 : 1,
      }),
    );
    world.addJoint(revoluteJoint({ bodyA: last, bodyB: link, anchor: { x: i, y: 0 } }));
    last = link;
  }
  return { world, onStep() {} };
}

/** Bytes in use in the young generation. */
function youngBytes(): number {
  let bytes = 0;
  for (const space of getHeapSpaceStatistics()) {
    if (space.space_name === 'new_space') bytes += space.space_used_size;
  }
  return bytes;
}

const scenes: Record<string, () => { world: World; onStep(step: number): void }> = {
  drum,
  pyramid,
  waking,
  chain,
};
const build = scenes[scene];
if (build === undefined) throw new Error(`no scene ${scene}`);
const { world, onStep } = build();
let step = 0;
for (; step < warmup; step++) {
  onStep(step);
  world.step(DT);
}
gc();
// A collection makes the next steps allocate again what it threw away (feedback, handles):
// settle first.
for (let i = 0; i < 20; i++, step++) {
  onStep(step);
  world.step(DT);
}
let collections = 0;
const observer = new PerformanceObserver((list) => {
  collections += list.getEntries().length;
});
observer.observe({ entryTypes: ['gc'] });
const before = youngBytes();
for (let i = 0; i < steps; i++, step++) {
  onStep(step);
  world.step(DT);
}
const after = youngBytes();
await new Promise((resolve) => setTimeout(resolve, 0));
observer.disconnect();
const awake = world.bodies.filter((b) => b.type === 'dynamic' && b.isAwake).length;
process.stdout.write(
  `${JSON.stringify({ scene, steps, bytes: after - before, collections, bodies: world.bodies.length, awake })}\n`,
);
