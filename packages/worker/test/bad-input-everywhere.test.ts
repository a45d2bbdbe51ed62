import { describe, expect, it } from 'vitest';
import { PhysicalError, type World } from '@physical/engine';
import { serveWorld, type WorkerEndpoint } from '@physical/worker';

// The worker side of @physical/worker's boundary: every message a page (a buggy one, another
// version, a hostile frame) can post to serveWorld, malformed every way. Each is either answered
// with a `failure` message naming the field (a PhysicalError's) or applied as documented; none
// throws out of the message handler, none changes the served world's methods or its bodies'
// ids, and afterwards the world still steps 60 times, finite, with every body the page added.

interface Served {
  readonly world: World;
  readonly posted: Record<string, unknown>[];
  send(message: unknown): void;
}

async function served(): Promise<Served> {
  let listener: ((event: MessageEvent) => void) | null = null;
  const posted: Record<string, unknown>[] = [];
  const endpoint: WorkerEndpoint = {
    postMessage: (message) => posted.push(message as Record<string, unknown>),
    addEventListener: (_type, l) => (listener = l),
  };
  const ready = serveWorld(endpoint);
  const send = (message: unknown): void => listener!({ data: message } as MessageEvent);
  send({ type: 'init', options: { gravity: { x: 0, y: 10 } }, shared: null, offscreen: null });
  const world = await ready;
  send({
    type: 'add',
    id: 0,
    definition: { kind: 'box', type: 'static', position: { x: 0, y: 5 }, width: 20, height: 1 },
  });
  send({
    type: 'add',
    id: 1,
    definition: { kind: 'box', position: { x: 0, y: 3 }, width: 1, height: 1 },
  });
  send({
    type: 'add',
    id: 2,
    definition: { kind: 'particle', position: { x: 2, y: 3 }, radius: 0.5 },
  });
  send({ type: 'listen', events: ['move', 'contactBegin'] });
  send({ type: 'step', dt: 1 / 60, count: 2 });
  return { world, posted, send };
}

const BAD: readonly [string, unknown][] = [
  ['NaN', NaN],
  ['Infinity', Infinity],
  ['-1', -1],
  ['1e9', 1e9],
  ['2.5', 2.5],
  ["'a'", 'a'],
  ['null', null],
  ['undefined', undefined],
  ['{}', {}],
  ['[]', []],
  ["'__proto__'", '__proto__'],
  ["'constructor'", 'constructor'],
  ["'step'", 'step'],
];

/** Good messages of every type; each field of each gets every bad value in turn. */
const MESSAGES: readonly Record<string, unknown>[] = [
  { type: 'add', id: 7, definition: { kind: 'particle', position: { x: -2, y: 3 }, radius: 0.3 } },
  { type: 'remove', id: 2 },
  {
    type: 'addJoint',
    id: 0,
    definition: {
      kind: 'distance',
      bodyA: 1,
      bodyB: 2,
      anchorA: { x: 0, y: 3 },
      anchorB: { x: 2, y: 3 },
    },
  },
  { type: 'removeJoint', id: 0 },
  { type: 'body', id: 1, operation: { op: 'applyImpulse', impulse: { x: 1, y: 0 } } },
  {
    type: 'body',
    id: 1,
    operation: { op: 'applyForce', forceId: 0, force: { x: 1, y: 0 }, duration: 1 },
  },
  { type: 'body', id: 1, operation: { op: 'set', property: 'angle', value: 0.5 } },
  { type: 'setting', name: 'subSteps', value: 4 },
  { type: 'step', dt: 1 / 60, count: 1 },
  { type: 'listen', events: ['move'] },
  { type: 'query', queryId: 1, query: { kind: 'bodyAt', point: { x: 0, y: 3 } } },
  { type: 'query', queryId: 2, query: { kind: 'body', id: 1 } },
  { type: 'grab', pointerId: 1, id: 1, x: 0, y: 3, toX: 0, toY: 2 },
  { type: 'grabMove', pointerId: 1, x: 0, y: 2 },
  { type: 'grabEnd', pointerId: 1, vx: 1, vy: 0, isThrow: true },
];

function* malformed(): Generator<[string, unknown]> {
  for (const [label, value] of BAD) yield [`the message = ${label}`, value];
  yield ['an unknown type', { type: 'banana' }];
  yield ['add with an id in use', { ...MESSAGES[0], id: 1 }];
  yield ['addJoint with an id in use', { ...MESSAGES[2], id: 0 }];
  for (const message of MESSAGES) {
    const fields = Object.entries(message).filter(([key]) => key !== 'type');
    for (const [key, good] of fields) {
      for (const [label, value] of BAD) {
        yield [`${String(message['type'])}.${key} = ${label}`, { ...message, [key]: value }];
        if (good !== null && typeof good === 'object' && !Array.isArray(good)) {
          for (const inner of Object.keys(good)) {
            yield [
              `${String(message['type'])}.${key}.${inner} = ${label}`,
              { ...message, [key]: { ...good, [inner]: value } },
            ];
          }
        }
      }
    }
  }
}

function finite(world: World): boolean {
  return world.bodies.every((b) =>
    [
      b.position.x,
      b.position.y,
      b.angle,
      b.linearVelocity.x,
      b.linearVelocity.y,
      b.angularVelocity,
    ].every(Number.isFinite),
  );
}

describe('serveWorld: every malformed message from the page', () => {
  const cases = [...malformed()];
  it('drives every message type', () => {
    expect(cases.length).toBeGreaterThan(500);
  });
  it.each(cases)('%s', async (_label, message) => {
    const s = await served();
    const methods = ['step', 'add', 'remove', 'addJoint'].map(
      (name) => (s.world as unknown as Record<string, unknown>)[name],
    );
    const kept = s.world.bodies.filter((b) => b !== s.world.bodies[2]);
    const before = s.posted.length;
    expect(() => s.send(message)).not.toThrow();
    // A failure, if any, names a field when the engine's or the server's check refused it.
    for (const reply of s.posted.slice(before)) {
      if (reply['type'] !== 'failure') continue;
      expect(typeof reply['message']).toBe('string');
      if (reply['field'] !== null) {
        expect(String(reply['message']).startsWith(`${String(reply['field'])}: `)).toBe(true);
      }
      expect(Number.isInteger(reply['lostSteps']) && (reply['lostSteps'] as number) >= 0).toBe(
        true,
      );
    }
    // The world's own methods and prototype are untouched, and it steps on.
    expect(Object.getPrototypeOf(s.world)).toBe(
      Object.getPrototypeOf(await served().then((t) => t.world)),
    );
    ['step', 'add', 'remove', 'addJoint'].forEach((name, i) =>
      expect((s.world as unknown as Record<string, unknown>)[name]).toBe(methods[i]),
    );
    const after = s.posted.length;
    s.send({ type: 'step', dt: 1 / 60, count: 60 });
    expect(s.posted.slice(after).filter((m) => m['type'] === 'failure')).toEqual([]);
    expect(s.posted.slice(after).filter((m) => m['type'] === 'frame')).toHaveLength(60);
    expect(finite(s.world)).toBe(true);
    for (const body of kept) expect(s.world.has(body)).toBe(true);
  });
});

it('a PhysicalError is what the server reports for a field', () => {
  expect(new PhysicalError('count', 'x').message).toBe('count: x');
});
