import { MessageChannel, type MessagePort } from 'node:worker_threads';
import { afterEach, describe, expect, it } from 'vitest';
import { Body, PhysicalError, World, box } from '@physical/engine';
import { serveWorld, WorkerWorld, type BodyId, type WorkerLike } from '@physical/worker';

// The message boundary between the page and the worker: every call is checked on the page with
// the engine's own rule before anything is posted, page and worker agree on which bodies exist,
// every request settles, and no event names a body the page removed.

const ports: MessagePort[] = [];
afterEach(() => {
  for (const port of ports.splice(0)) port.close();
});

interface Connection {
  readonly world: WorkerWorld;
  /** Messages the page posted, in order. */
  readonly posted: { type: string }[];
  /** The world the worker simulates. */
  readonly served: Promise<World>;
}

function connect(): Connection {
  const { port1, port2 } = new MessageChannel();
  ports.push(port1, port2);
  const served = serveWorld(port2 as unknown as Parameters<typeof serveWorld>[0]);
  port2.start();
  const posted: { type: string }[] = [];
  const spy: WorkerLike = {
    postMessage: (message, transfer) => {
      posted.push(message as { type: string });
      port1.postMessage(message, transfer as never);
    },
    addEventListener: (type, listener) =>
      port1.addEventListener(type as 'message', listener as never),
  };
  const world = new WorkerWorld(spy);
  port1.start();
  return { world, posted, served };
}

/** The PhysicalError field a call throws (fails the test when it throws something else). */
function fieldOf(call: () => unknown): string {
  try {
    call();
  } catch (error) {
    expect(error).toBeInstanceOf(PhysicalError);
    return (error as PhysicalError).field;
  }
  return 'none';
}

/** A vector whose x and y are class getters (a structured clone keeps neither). */
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

describe('WorkerWorld refuses on the page what the engine refuses, and posts nothing', () => {
  it('step: the engine’s range of dt, the same field', () => {
    const { world, posted } = connect();
    for (const dt of [10, 1e-9, -1, Number.NaN, Number.POSITIVE_INFINITY, '1' as never]) {
      const before = posted.length;
      expect(fieldOf(() => world.step(dt))).toBe(fieldOf(() => new World().step(dt)));
      expect(fieldOf(() => world.step(dt))).not.toBe('none');
      expect(posted.length).toBe(before);
      expect(world.stepsInFlight).toBe(0);
    }
  });

  it('null and undefined vectors throw a PhysicalError, not a TypeError', () => {
    const { world, posted } = connect();
    const id = world.add({ kind: 'box', width: 1, height: 1 });
    const page = new World();
    const body = page.add(box({ width: 1, height: 1 }));
    const before = posted.length;
    expect(fieldOf(() => (world.gravity = null as never))).toBe(
      fieldOf(() => (page.gravity = null as never)),
    );
    expect(fieldOf(() => world.setPosition(id, null as never))).toBe(
      fieldOf(() => (body.position = null as never)),
    );
    expect(fieldOf(() => world.setLinearVelocity(id, undefined as never))).toBe(
      fieldOf(() => (body.linearVelocity = undefined as never)),
    );
    expect(fieldOf(() => world.applyImpulse(id, null as never))).toBe(
      fieldOf(() => body.applyImpulse(null as never)),
    );
    expect(fieldOf(() => world.applyForce(id, undefined as never))).toBe(
      fieldOf(() => body.applyForce(undefined as never)),
    );
    expect(fieldOf(() => world.rayCast(null as never, { x: 0, y: 0 }))).toBe('from');
    expect(posted.length).toBe(before);
  });

  it('set accepts only the settable properties', () => {
    const { world, posted } = connect();
    const id = world.add({ kind: 'box', width: 1, height: 1 });
    const copy = world.bodyOf(id);
    const before = posted.length;
    for (const key of ['type', 'banana', '__proto__', 'constructor', 'toString', 'shapes']) {
      expect(fieldOf(() => world.set(id, key as never, {}))).toBe('property');
    }
    expect(posted.length).toBe(before);
    expect(Object.getPrototypeOf(copy)).toBe(Body.prototype);
    expect(copy.type).toBe('dynamic');
  });

  it('a definition that cannot cross is refused before the page adds the body', async () => {
    const { world, posted } = connect();
    world.add({ kind: 'box', width: 1, height: 1 });
    const before = posted.length;
    const symbol = { kind: 'box', width: 1, height: 1, position: { x: Symbol('x'), y: 0 } };
    expect(fieldOf(() => world.add(symbol as never))).toBe('position.x');
    const fn = { kind: 'box', width: 1, height: 1, filter: { categoryBits: () => 1 } };
    expect(fieldOf(() => world.add(fn as never))).toBe('filter.categoryBits');
    const cycle: Record<string, unknown> = { x: 0, y: 0 };
    cycle['self'] = cycle;
    expect(
      fieldOf(() => world.add({ kind: 'box', width: 1, height: 1, position: cycle } as never)),
    ).not.toBe('none');
    expect(posted.length).toBe(before);
    expect(world.bodyIds.length).toBe(1);
    // The worker holds the same one body.
    const served = await connectServed(world);
    expect(served).toBe(1);
  });

  it('vectors with getters cross as their values (page and worker agree)', async () => {
    const { world, served } = connect();
    const id = world.add({
      kind: 'box',
      width: 1,
      height: 1,
      position: new GetterVec(1, 2) as never,
      linearVelocity: new GetterVec(0.5, 0) as never,
    });
    world.setAngularVelocity(id, 0);
    const state = await world.getBody(id);
    expect(state?.position).toEqual({ x: 1, y: 2 });
    expect(state?.linearVelocity).toEqual({ x: 0.5, y: 0 });
    world.setPosition(id, new GetterVec(3, 4) as never);
    world.setLinearVelocity(id, new GetterVec(-1, 0) as never);
    world.gravity = new GetterVec(0, 1) as never;
    world.applyImpulse(id, new GetterVec(0, 0) as never, new GetterVec(3, 4) as never);
    const moved = await world.getBody(id);
    expect(moved?.position).toEqual({ x: 3, y: 4 });
    expect(moved?.linearVelocity).toEqual({ x: -1, y: 0 });
    expect((await served).gravity).toEqual({ x: 0, y: 1 });
    expect(world.gravity).toEqual({ x: 0, y: 1 });
    expect((await served).bodies.length).toBe(world.bodyIds.length);
  });
});

/** Bodies the worker holds, read through a query that answers after everything posted. */
async function connectServed(world: WorkerWorld): Promise<number> {
  const ids = await world.bodiesInAABB({ minX: -1e6, minY: -1e6, maxX: 1e6, maxY: 1e6 });
  return ids.length;
}

describe('every request settles', () => {
  it('a step the worker fails to take stops counting as in flight, and the world steps on', async () => {
    const { world, served } = connect();
    world.add({ kind: 'box', width: 1, height: 1 });
    const inner = await served;
    let throwing = true;
    inner.on('move', () => {
      if (throwing) throw new Error('the worker’s own listener failed');
    });
    const errors: Error[] = [];
    world.on('error', (error) => errors.push(error));
    for (let i = 0; i < 6; i++) world.step();
    await world.flush();
    expect(errors.length).toBe(6);
    expect(world.stepsInFlight).toBe(0);
    throwing = false;
    world.step();
    await world.flush();
    expect(world.stepsInFlight).toBe(0);
    expect(world.steps).toBe(1);
  });

  it('a query the worker fails to answer rejects', async () => {
    const { world, served } = connect();
    const id = world.add({ kind: 'box', width: 1, height: 1 });
    await world.flush();
    const inner = await served;
    // The worker's world fails while answering (a broken query answer, here a throwing getter).
    Object.defineProperty(inner.bodies[0]!, 'isAwake', {
      get: () => {
        throw new Error('broken');
      },
    });
    await expect(world.getBody(id)).rejects.toThrow('broken');
    // The channel still answers.
    await expect(world.flush()).resolves.toBeUndefined();
  });

  it('terminate and a worker error reject what is pending and leave no step in flight', async () => {
    const { world } = connect();
    world.add({ kind: 'box', width: 1, height: 1 });
    world.step();
    world.step();
    const pending = world.flush();
    world.terminate();
    await expect(pending).rejects.toThrow('terminated');
    expect(world.stepsInFlight).toBe(0);
    await expect(world.stateHash()).rejects.toThrow('terminated');

    const listeners = new Map<string, (event: Event) => void>();
    const fake: WorkerLike = {
      postMessage: () => {},
      addEventListener: (type, listener) => listeners.set(type, listener),
    };
    const failing = new WorkerWorld(fake);
    failing.on('error', () => {});
    failing.step();
    const query = failing.flush();
    listeners.get('error')!({ message: 'crashed' } as unknown as Event);
    await expect(query).rejects.toThrow('crashed');
    expect(failing.stepsInFlight).toBe(0);
  });
});

describe('events', () => {
  it('no event names a body after remove(id) returned', async () => {
    const { world } = connect();
    const ids: BodyId[] = [];
    for (let i = 0; i < 4; i++) {
      ids.push(world.add({ kind: 'box', width: 0.5, height: 0.5, position: { x: 2 * i, y: 0 } }));
    }
    const named: number[] = [];
    world.on('move', ({ body }) => {
      named.push(body);
      world.position(body); // throws for a body not in the world
      // The first listener call removes body 1: the rest of this batch must not name it.
      if (world.has(ids[1]!)) world.remove(ids[1]!);
    });
    for (let i = 0; i < 10; i++) world.step();
    world.remove(ids[0]!); // ten steps of move events naming it are still on their way
    const from = named.length;
    await world.flush();
    const after = named.slice(from);
    expect(after.length).toBeGreaterThan(0);
    expect(after).not.toContain(ids[0]);
    expect(named.filter((id) => id === ids[1]).length).toBeLessThanOrEqual(1);
  });
});

describe('serveWorld', () => {
  it('resolves with the world the worker simulates', async () => {
    const { world, served } = connect();
    world.add({ kind: 'box', width: 1, height: 1 });
    const inner = await served;
    const extra = inner.add(box({ width: 1, height: 1, position: { x: 10, y: 0 } }));
    for (let i = 0; i < 30; i++) world.step(1 / 60);
    await world.flush();
    expect(inner.steps).toBe(30);
    // Fell under gravity for half a second: y = g t^2 / 2 = 1.23 m (sub-stepped Euler: within 2 %).
    expect(extra.position.y).toBeCloseTo(9.81 * 0.125, 1);
    // Not known to the page.
    expect(world.bodyIds.length).toBe(1);
  });
});
