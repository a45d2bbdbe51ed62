import { MessageChannel, type MessagePort } from 'node:worker_threads';
import fc from 'fast-check';
import { afterEach, describe, expect, it } from 'vitest';
import { PhysicalError, type World } from '@physical/engine';
import { serveWorld, WorkerWorld, type BodyId, type WorkerLike } from '@physical/worker';

// Random worker calls, valid and invalid, through the real message channel: every call either
// throws a PhysicalError on the page and posts nothing, or is posted; afterwards every promise
// settles, the page and the worker hold the same bodies, no step stays in flight, and no event
// named a body the page had removed. Fixed seed and run count, so it runs in `npm test`.

const RUNS = 40;

const ports: MessagePort[] = [];
afterEach(() => {
  for (const port of ports.splice(0)) port.close();
});

/** A class vector: its x and y are getters, which a structured clone drops. */
class GetterVec {
  constructor(
    private readonly px: number,
    private readonly py: number,
  ) {}
  get x(): number {
    return this.px;
  }
  get y(): number {
    return this.py;
  }
}

const number = fc.oneof(
  fc.double({ min: -3, max: 3, noNaN: true }),
  fc.constantFrom(0, Number.NaN, Number.POSITIVE_INFINITY, -1, 1e300, 1e-9, 10),
);
const vector = fc.oneof(
  fc.record({ x: number, y: number }),
  fc.tuple(number, number).map(([x, y]) => new GetterVec(x, y)),
  fc.constantFrom(null, undefined, {}, 'up', Symbol('v')),
);
const key = fc.constantFrom(
  'position',
  'angle',
  'linearVelocity',
  'angularVelocity',
  'gravityScale',
  'mass',
  'bullet',
  'type',
  'banana',
  '__proto__',
  'constructor',
);
const value = fc.oneof(
  number,
  vector,
  fc.boolean(),
  fc.constantFrom('static', () => 1),
);

/** One call: a body index (taken modulo the bodies added so far, or a bad id) and arguments. */
const call = fc.oneof(
  fc.record({
    op: fc.constant('add' as const),
    kind: fc.constantFrom('box', 'particle', 'capsule', 'bad'),
    position: vector,
    extra: fc.constantFrom(null, 'symbol', 'function'),
  }),
  fc.record({ op: fc.constant('remove' as const), body: fc.nat(12) }),
  fc.record({ op: fc.constant('set' as const), body: fc.nat(12), key, value }),
  fc.record({ op: fc.constant('setPosition' as const), body: fc.nat(12), value: vector }),
  fc.record({ op: fc.constant('setLinearVelocity' as const), body: fc.nat(12), value: vector }),
  fc.record({ op: fc.constant('impulse' as const), body: fc.nat(12), value: vector }),
  fc.record({
    op: fc.constant('force' as const),
    body: fc.nat(12),
    value: vector,
    duration: fc.oneof(number, fc.constantFrom('constant', 'instant', 'forever')),
  }),
  fc.record({ op: fc.constant('gravity' as const), value: vector }),
  fc.record({ op: fc.constant('step' as const), dt: fc.oneof(fc.constant(1 / 60), number) }),
  fc.record({ op: fc.constant('query' as const), body: fc.nat(12) }),
);

type Call = typeof call extends fc.Arbitrary<infer T> ? T : never;

function connect(): { world: WorkerWorld; posted: unknown[]; served: Promise<World> } {
  const { port1, port2 } = new MessageChannel();
  ports.push(port1, port2);
  const served = serveWorld(port2 as unknown as Parameters<typeof serveWorld>[0]);
  port2.start();
  const posted: unknown[] = [];
  const spy: WorkerLike = {
    postMessage: (message, transfer) => {
      posted.push(message);
      port1.postMessage(message, transfer as never);
    },
    addEventListener: (type, listener) =>
      port1.addEventListener(type as 'message', listener as never),
  };
  const world = new WorkerWorld(spy);
  port1.start();
  return { world, posted, served };
}

/** Settles within `ms`, or fails the property (a request that never settles). */
function settled<T>(promise: Promise<T>, ms = 20_000): Promise<PromiseSettledResult<T>> {
  return Promise.race([
    Promise.allSettled([promise]).then(([result]) => result!),
    new Promise<never>((_, reject) =>
      setTimeout(() => reject(new Error('a request never settled')), ms),
    ),
  ]);
}

async function run(calls: readonly Call[]): Promise<void> {
  const { world, posted, served } = connect();
  world.on('error', () => {}); // failures are expected; they must settle, not hang
  const ids: BodyId[] = [];
  const removed = new Set<number>();
  const named: number[] = [];
  world.on('move', ({ body }) => {
    if (removed.has(body)) named.push(body);
  });
  world.on('contactBegin', ({ bodyA, bodyB }) => {
    if (removed.has(bodyA) || removed.has(bodyB)) named.push(bodyA);
  });
  const pending: Promise<unknown>[] = [];
  const pick = (n: number): BodyId =>
    ids.length === 0 || n >= 10 ? (999 as BodyId) : ids[n % ids.length]!;
  for (const c of calls) {
    const before = posted.length;
    try {
      switch (c.op) {
        case 'add': {
          const definition: Record<string, unknown> = { kind: c.kind, position: c.position };
          if (c.kind === 'box') Object.assign(definition, { width: 0.5, height: 0.5 });
          else Object.assign(definition, { radius: 0.2, length: 0.5 });
          if (c.extra === 'symbol') definition['friction'] = Symbol('f');
          if (c.extra === 'function') definition['filter'] = { groupIndex: () => 1 };
          ids.push(world.add(definition as never));
          break;
        }
        case 'remove': {
          const id = pick(c.body);
          world.remove(id);
          removed.add(id);
          break;
        }
        case 'set':
          world.set(pick(c.body), c.key as never, c.value);
          break;
        case 'setPosition':
          world.setPosition(pick(c.body), c.value as never);
          break;
        case 'setLinearVelocity':
          world.setLinearVelocity(pick(c.body), c.value as never);
          break;
        case 'impulse':
          world.applyImpulse(pick(c.body), c.value as never);
          break;
        case 'force':
          world.applyForce(pick(c.body), c.value as never, { duration: c.duration as never });
          break;
        case 'gravity':
          world.gravity = c.value as never;
          break;
        case 'step':
          world.step(c.dt);
          break;
        case 'query':
          pending.push(world.getBody(pick(c.body)));
          pending.push(world.stateHash());
          break;
      }
    } catch (error) {
      // A refusal: the engine's own error, synchronously, and nothing posted.
      if (!(error instanceof PhysicalError)) throw error;
      expect(posted.length).toBe(before);
    }
  }
  for (const promise of pending) await settled(promise);
  const flushed = await settled(world.flush());
  expect(flushed.status).toBe('fulfilled');
  expect(world.stepsInFlight).toBe(0);
  expect(named).toEqual([]);
  // The page and the worker hold the same bodies.
  const inner = await served;
  expect(inner.bodies.length).toBe(world.bodyIds.length);
  const everywhere = { minX: -1e7, minY: -1e7, maxX: 1e7, maxY: 1e7 };
  const remote = (await world.bodiesInAABB(everywhere)).sort((a, b) => a - b);
  expect(remote).toEqual([...world.bodyIds].sort((a, b) => a - b));
  world.terminate();
}

describe('the worker boundary under fuzzing', () => {
  it(`every call is refused on the page or posted; every request settles; page and worker agree (${RUNS} runs)`, async () => {
    await fc.assert(fc.asyncProperty(fc.array(call, { minLength: 1, maxLength: 30 }), run), {
      seed: 31,
      numRuns: RUNS,
    });
  }, 240_000);
});
