import { describe, expect, it } from 'vitest';
import {
  World,
  bodyAtPoint,
  box,
  capsule,
  checkQueryBox,
  checkRay,
  checkTimeStep,
  checkWorldOptions,
  checkWorldSetting,
  particle,
  wall,
  type Body,
  type WorldOptions,
  type WorldSettingName,
} from '@physical/engine';
import { physicalErrorOf } from './expect-physical-error.ts';

// A page that drives a world living elsewhere (a worker world) checks its input with these
// functions instead of a World: each must refuse exactly what World refuses, with the same
// field and message, and accept what World accepts.

const badOptions: unknown[] = [
  null,
  { gravity: { x: Number.NaN, y: 0 } },
  { subSteps: 0 },
  { subSteps: 2.5 },
  { restitutionThreshold: -1 },
  { contactHertz: 0 },
  { enableSleep: 'yes' },
  { kernel: 'wasm' },
];

const badSettings: [WorldSettingName, unknown][] = [
  ['gravity', { x: 0, y: Number.POSITIVE_INFINITY }],
  ['gravity', { x: 1e9, y: 0 }],
  ['subSteps', 65],
  ['restitutionThreshold', Number.NaN],
  ['enableSleep', 1],
];

describe('world checks refuse as World does', () => {
  it('refuses the options new World refuses, with its error', () => {
    for (const options of badOptions) {
      const fromWorld = physicalErrorOf(() => new World(options as WorldOptions));
      const fromCheck = physicalErrorOf(() => checkWorldOptions(options as WorldOptions));
      expect(fromCheck.field).toBe(fromWorld.field);
      expect(fromCheck.message).toBe(fromWorld.message);
    }
  });

  it('returns the settings a new World starts with', () => {
    const options = { gravity: { x: 1, y: -2 }, subSteps: 8, enableSleep: false };
    const world = new World(options);
    const settings = checkWorldOptions(options);
    expect(settings.gravity).toEqual({ x: world.gravity.x, y: world.gravity.y });
    expect(settings.subSteps).toBe(world.subSteps);
    expect(settings.restitutionThreshold).toBe(world.restitutionThreshold);
    expect(settings.enableSleep).toBe(world.enableSleep);
    const defaults = checkWorldOptions({});
    expect(defaults.restitutionThreshold).toBe(new World().restitutionThreshold);
  });

  it("refuses the settings World's setters refuse, and returns what World holds", () => {
    for (const [name, value] of badSettings) {
      const world = new World() as unknown as Record<string, unknown>;
      const fromWorld = physicalErrorOf(() => (world[name] = value));
      const fromCheck = physicalErrorOf(() => checkWorldSetting(name, value));
      expect(fromCheck.field).toBe(fromWorld.field);
      expect(fromCheck.message).toBe(fromWorld.message);
    }
    expect(checkWorldSetting('gravity', { x: 3, y: 4, z: 9 })).toEqual({ x: 3, y: 4 });
    expect(checkWorldSetting('subSteps', 12)).toBe(12);
  });

  it('refuses the time steps World.step refuses, and accepts 0 and 1/60', () => {
    const world = new World();
    for (const dt of [-1 / 60, Number.NaN, 2, 1e-9, Number.POSITIVE_INFINITY]) {
      const fromWorld = physicalErrorOf(() => world.step(dt));
      const fromCheck = physicalErrorOf(() => checkTimeStep(dt));
      expect(fromCheck.field).toBe(fromWorld.field);
      expect(fromCheck.message).toBe(fromWorld.message);
    }
    expect(() => checkTimeStep(0)).not.toThrow();
    expect(() => checkTimeStep(1 / 60)).not.toThrow();
  });

  it('refuses the rays and boxes the queries refuse', () => {
    const world = new World();
    const rays: [unknown, unknown][] = [
      [null, { x: 0, y: 0 }],
      [
        { x: 0, y: 0 },
        { x: Number.NaN, y: 0 },
      ],
    ];
    for (const [from, to] of rays) {
      const args = [from, to] as Parameters<typeof checkRay>;
      const fromWorld = physicalErrorOf(() => world.rayCast(...args));
      expect(physicalErrorOf(() => checkRay(...args)).message).toBe(fromWorld.message);
    }
    const boxes: unknown[] = [null, { minX: 0, minY: 0, maxX: Number.NaN, maxY: 1 }];
    for (const queryBox of boxes) {
      const arg = queryBox as Parameters<typeof checkQueryBox>[0];
      const fromWorld = physicalErrorOf(() => world.bodiesInAABB(arg));
      expect(physicalErrorOf(() => checkQueryBox(arg)).message).toBe(fromWorld.message);
    }
  });
});

describe('bodyAtPoint', () => {
  it('finds the body World.bodyAt finds, at every point of a grid over overlapping bodies', () => {
    const world = new World({ gravity: { x: 0, y: 0 } });
    const bodies: Body[] = [
      world.add(particle({ position: { x: 0, y: 0 }, radius: 1 })),
      world.add(box({ position: { x: 1, y: 0.5 }, width: 2, height: 1, angle: 0.6 })),
      world.add(capsule({ position: { x: -0.5, y: 1 }, length: 2, radius: 0.4, angle: -0.3 })),
      world.add(wall({ from: { x: -3, y: 2 }, to: { x: 3, y: 2 } })),
      world.add(particle({ position: { x: 0.4, y: 0.2 }, radius: 0.3 })),
    ];
    let found = 0;
    for (let x = -2.5; x <= 2.5; x += 0.125) {
      for (let y = -1.5; y <= 2.5; y += 0.125) {
        const expected = world.bodyAt({ x, y });
        if (expected !== null) found++;
        expect(bodyAtPoint(bodies, { x, y })).toBe(expected);
      }
    }
    // The grid reaches every body but the wall (segments are never under a point).
    expect(found).toBeGreaterThan(100);
  });

  it('refuses a point that is not a finite vector, as World.bodyAt does', () => {
    const point = { x: Number.NaN, y: 0 };
    const fromWorld = physicalErrorOf(() => new World().bodyAt(point));
    expect(physicalErrorOf(() => bodyAtPoint([], point)).message).toBe(fromWorld.message);
  });
});
