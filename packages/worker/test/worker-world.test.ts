import { MessageChannel, type MessagePort } from 'node:worker_threads';
import { afterEach, describe, expect, it } from 'vitest';
import {
  PhysicalError,
  World,
  box,
  distanceJoint,
  mouseJoint,
  revoluteJoint,
  wall,
} from '@physical/engine';
import type { DrawingSource } from '@physical/canvas';
import { serveWorld, WorkerWorld, worldStateHash, type WorkerLike } from '@physical/worker';

// The page and the worker joined by a MessageChannel in one Node process: the same messages,
// clones and transfers as a real worker, without a browser.
const ports: MessagePort[] = [];
afterEach(() => {
  for (const port of ports.splice(0)) port.close();
});

function connect(): WorkerWorld {
  const { port1, port2 } = new MessageChannel();
  ports.push(port1, port2);
  serveWorld(port2 as unknown as Parameters<typeof serveWorld>[0]);
  port2.start();
  const world = new WorkerWorld(port1 as unknown as WorkerLike);
  port1.start();
  return world;
}

describe('WorkerWorld', () => {
  // Up to 30 s: a busy machine delays the channel's messages, never the result.
  it(
    'steps exactly as the same world on the page (same state hash after 120 steps)',
    { timeout: 30_000 },
    async () => {
      const local = new World();
      const remote = connect();
      local.add(wall({ from: { x: -5, y: 5 }, to: { x: 5, y: 5 } }));
      remote.add({ kind: 'wall', from: { x: -5, y: 5 }, to: { x: 5, y: 5 } });
      const ids = [];
      for (let i = 0; i < 20; i++) {
        const options = {
          width: 0.5,
          height: 0.4,
          position: { x: (i % 5) * 0.6 - 1.5, y: 4 - Math.floor(i / 5) * 0.5 },
          angle: i * 0.01,
        };
        local.add(box(options));
        ids.push(remote.add({ kind: 'box', ...options }));
      }
      local.bodies[3]!.applyForce({ x: 5, y: 0 }, { duration: 0.5 });
      remote.applyForce(ids[2]!, { x: 5, y: 0 }, { duration: 0.5 });
      local.bodies[5]!.applyImpulse({ x: 0, y: -2 });
      remote.applyImpulse(ids[4]!, { x: 0, y: -2 });
      for (let i = 0; i < 120; i++) {
        local.step(1 / 60);
        remote.step(1 / 60);
      }
      expect(await remote.stateHash()).toBe(worldStateHash(local));
      // A changed world hashes differently: the comparison can fail.
      local.step(1 / 60);
      expect(await remote.stateHash()).not.toBe(worldStateHash(local));
    },
  );

  it('counts the steps in flight, which the canvas holds back on', async () => {
    const world = connect();
    world.add({ kind: 'box', width: 1, height: 1 });
    expect(world.stepsInFlight).toBe(0);
    for (let i = 0; i < 3; i++) world.step();
    expect(world.stepsInFlight).toBe(3);
    expect(world.remote.stepsInFlight?.()).toBe(3);
    await world.flush();
    expect(world.stepsInFlight).toBe(0);
    expect(world.steps).toBe(3);
  });

  it('streams the poses of moved bodies and applies them at the next step', async () => {
    const world = connect();
    const ball = world.add({ kind: 'particle', radius: 0.2, position: { x: 0, y: 0 } });
    world.add({ kind: 'wall', from: { x: -5, y: 5 }, to: { x: 5, y: 5 } });
    for (let i = 0; i < 30; i++) world.step(1 / 60);
    await world.flush();
    expect(world.steps).toBe(30);
    // Free fall for 0.5 s, 4 sub-steps of h = dt / 4 with symplectic Euler: y = g h^2 m(m+1)/2
    // after m = 120 sub-steps (float32 poses: 6 digits).
    const h = 1 / 240;
    expect(world.position(ball).y).toBeCloseTo((9.81 * h * h * 120 * 121) / 2, 5);
    // Only the ball moves: 16 bytes (id, x, y, angle as float32) per step.
    world.step(1 / 60);
    await world.flush();
    expect(world.lastPoseBytes).toBe(16);
  });

  it('refuses bad input on the page with the engine’s PhysicalError and field', () => {
    const world = connect();
    const inThread = (build: () => unknown): string => {
      try {
        build();
      } catch (error) {
        return (error as PhysicalError).field;
      }
      return 'none';
    };
    const fieldOf = (call: () => unknown): string => {
      try {
        call();
      } catch (error) {
        expect(error).toBeInstanceOf(PhysicalError);
        return (error as PhysicalError).field;
      }
      return 'none';
    };
    expect(fieldOf(() => world.add({ kind: 'box', width: -1, height: 1 }))).toBe(
      inThread(() => box({ width: -1, height: 1 })),
    );
    const id = world.add({ kind: 'box', width: 1, height: 1 });
    expect(fieldOf(() => world.setLinearVelocity(id, { x: Number.NaN, y: 0 }))).toBe(
      inThread(() => {
        box({ width: 1, height: 1 }).linearVelocity = { x: Number.NaN, y: 0 };
      }),
    );
    expect(fieldOf(() => world.applyForce(id, { x: 1, y: 0 }, { duration: -2 }))).toBe(
      inThread(() => box({ width: 1, height: 1 }).applyForce({ x: 1, y: 0 }, { duration: -2 })),
    );
    expect(fieldOf(() => (world.gravity = { x: Number.POSITIVE_INFINITY, y: 0 }))).toBe(
      inThread(() => (new World().gravity = { x: Number.POSITIVE_INFINITY, y: 0 })),
    );
    const other = world.add({ kind: 'box', width: 1, height: 1 });
    expect(
      fieldOf(() =>
        world.addJoint({
          kind: 'revolute',
          bodyA: id,
          bodyB: other,
          anchor: { x: Number.NaN, y: 0 },
        }),
      ),
    ).toBe(
      inThread(() =>
        revoluteJoint({
          bodyA: box({ width: 1, height: 1 }),
          bodyB: box({ width: 1, height: 1 }),
          anchor: { x: Number.NaN, y: 0 },
        }),
      ),
    );
    expect(fieldOf(() => world.remove(999 as never))).toBe('id');
    expect(
      fieldOf(() => world.add({ kind: 'box', width: 1, height: 1, onMove: () => {} } as never)),
    ).toBe('onMove');
  });

  it("keeps page copies of its joints at the anchors the engine's joints report, and removes them with a body", () => {
    const world = connect();
    const place = [
      { position: { x: -1, y: 0.5 }, angle: 0.3, width: 1, height: 1 },
      { position: { x: 2, y: -1 }, angle: -0.7, width: 1, height: 0.5 },
    ];
    const a = world.add({ kind: 'box', ...place[0]! });
    const b = world.add({ kind: 'box', ...place[1]! });
    const hinge = world.addJoint({
      kind: 'revolute',
      bodyA: a,
      bodyB: b,
      anchor: { x: 0.5, y: 0.2 },
    });
    world.addJoint({
      kind: 'distance',
      bodyA: a,
      bodyB: b,
      anchorA: { x: -1, y: 0 },
      anchorB: { x: 2, y: -1.1 },
    });
    world.addJoint({ kind: 'mouse', body: b, target: { x: 3, y: -2 } });
    const engine = [
      revoluteJoint({ bodyA: box(place[0]!), bodyB: box(place[1]!), anchor: { x: 0.5, y: 0.2 } }),
      distanceJoint({
        bodyA: box(place[0]!),
        bodyB: box(place[1]!),
        anchorA: { x: -1, y: 0 },
        anchorB: { x: 2, y: -1.1 },
      }),
      mouseJoint({ body: box(place[1]!), target: { x: 3, y: -2 } }),
    ];
    expect(world.joints.map((joint) => joint.type)).toEqual(['revolute', 'distance', 'mouse']);
    world.joints.forEach((copy, i) => {
      for (const end of ['anchorA', 'anchorB'] as const) {
        expect(copy[end].x).toBeCloseTo(engine[i]![end].x, 12);
        expect(copy[end].y).toBeCloseTo(engine[i]![end].y, 12);
      }
    });
    // Anchors ride the page copies: a teleported body carries its anchors (a mouse target stays).
    world.setPosition(b, { x: 3, y: -1 });
    expect(world.joints[0]!.anchorB.x).toBeCloseTo(engine[0]!.anchorB.x + 1, 12);
    expect(world.joints[2]!.anchorA.x).toBeCloseTo(3, 12);
    world.removeJoint(hinge);
    expect(world.joints.map((joint) => joint.type)).toEqual(['distance', 'mouse']);
    world.remove(b);
    expect(world.joints).toEqual([]);
  });

  it('is a drawing source for <physical-canvas>, as World is', () => {
    const sources: DrawingSource[] = [new World(), connect()];
    expect(sources.every((source) => typeof source.step === 'function')).toBe(true);
  });
});
