import { describe, expect, it } from 'vitest';
import {
  Body,
  PhysicalError,
  World,
  box,
  particle,
  polygon,
  regularPolygon,
  wall,
} from '@physical/engine';

// Every bad value gets a PhysicalError naming the field and saying what to do: never a silent NaN.

function errorOf(action: () => unknown): PhysicalError {
  try {
    action();
  } catch (error) {
    if (error instanceof PhysicalError) return error;
    throw new Error(`expected a PhysicalError, got ${String(error)}`, { cause: error });
  }
  throw new Error('expected a PhysicalError, but nothing was thrown');
}

describe('bad numbers', () => {
  it.each([
    ['position.x', () => particle({ position: { x: NaN, y: 0 }, radius: 1 })],
    ['position.y', () => particle({ position: { x: 0, y: Infinity }, radius: 1 })],
    ['angle', () => box({ angle: NaN, width: 1, height: 1 })],
    ['linearVelocity.x', () => particle({ radius: 1, linearVelocity: { x: -Infinity, y: 0 } })],
    ['angularVelocity', () => particle({ radius: 1, angularVelocity: NaN })],
    ['gravityScale', () => particle({ radius: 1, gravityScale: NaN })],
    ['linearDamping', () => particle({ radius: 1, linearDamping: -1 })],
    ['drag', () => particle({ radius: 1, drag: -0.5 })],
  ])('%s is rejected', (field, action) => {
    const error = errorOf(action);
    expect(error.field).toBe(field);
    expect(error.message).toContain(field);
  });

  it('a NaN gravity, dt or sub-step count is rejected', () => {
    expect(errorOf(() => new World({ gravity: { x: 0, y: NaN } })).field).toBe('gravity.y');
    expect(errorOf(() => new World({ subSteps: 0 })).field).toBe('subSteps');
    expect(errorOf(() => new World({ subSteps: 2.5 })).field).toBe('subSteps');
    const world = new World();
    expect(errorOf(() => world.step(NaN)).field).toBe('dt');
    expect(errorOf(() => world.step(-1 / 60)).field).toBe('dt');
    expect(errorOf(() => (world.gravity = { x: Infinity, y: 0 })).field).toBe('gravity.x');
  });
});

describe('bad mass', () => {
  it('zero or negative density on a dynamic body is rejected', () => {
    const error = errorOf(() => particle({ radius: 1, density: 0 }));
    expect(error.field).toBe('density');
    expect(error.message).toMatch(/greater than zero/);
    expect(errorOf(() => box({ width: 1, height: 1, density: -2 })).field).toBe('density');
  });

  it('zero density is fine on a static body', () => {
    expect(box({ type: 'static', width: 1, height: 1, density: 0 }).mass).toBe(0);
  });

  it('zero or negative mass or inertia set by hand is rejected', () => {
    expect(errorOf(() => particle({ radius: 1, mass: 0 })).field).toBe('mass');
    expect(errorOf(() => particle({ radius: 1, inertia: -1 })).field).toBe('inertia');
    const body = particle({ radius: 1 });
    expect(errorOf(() => (body.mass = -3)).field).toBe('mass');
    expect(body.mass).toBeCloseTo(Math.PI, 12); // unchanged
  });

  it('a dynamic body with no shape and no mass is rejected', () => {
    expect(errorOf(() => new Body({})).message).toMatch(/positive mass/);
  });

  it('a dynamic body of segments is rejected (no area, no mass)', () => {
    const error = errorOf(
      () => new Body({ shapes: [{ type: 'segment', from: { x: 0, y: 0 }, to: { x: 1, y: 0 } }] }),
    );
    expect(error.field).toBe('shapes[0]');
    expect(error.message).toMatch(/static or kinematic/);
  });
});

describe('bad shapes', () => {
  it('a box with a negative or zero size is rejected, naming the option', () => {
    expect(errorOf(() => box({ width: -1, height: 1 })).field).toBe('width');
    expect(errorOf(() => box({ width: 1, height: 0 })).field).toBe('height');
  });

  it('a negative or zero radius is rejected', () => {
    expect(errorOf(() => particle({ radius: -1 })).field).toBe('radius');
    expect(errorOf(() => particle({ radius: 0 })).field).toBe('radius');
  });

  it('a polygon with fewer than three distinct points is rejected', () => {
    const error = errorOf(() =>
      polygon({
        vertices: [
          { x: 0, y: 0 },
          { x: 1, y: 0 },
          { x: 1, y: 0 },
        ],
      }),
    );
    expect(error.field).toBe('vertices');
    expect(error.message).toMatch(/3/);
  });

  it('collinear points are rejected', () => {
    const error = errorOf(() =>
      polygon({
        vertices: [
          { x: 0, y: 0 },
          { x: 1, y: 1 },
          { x: 2, y: 2 },
        ],
      }),
    );
    expect(error.message).toMatch(/collinear|area/i);
  });

  it('a self-intersecting point list is rejected', () => {
    const bowTie = [
      { x: 0, y: 0 },
      { x: 1, y: 1 },
      { x: 1, y: 0 },
      { x: 0, y: 1 },
    ];
    expect(errorOf(() => polygon({ vertices: bowTie })).message).toMatch(/self-intersect|cross/i);
  });

  it('a rounded concave polygon is rejected, naming the radius', () => {
    const arrow = [
      { x: 0, y: 0 },
      { x: 2, y: 0 },
      { x: 2, y: 2 },
      { x: 1, y: 1 },
      { x: 0, y: 2 },
    ];
    expect(polygon({ vertices: arrow }).shapes.length).toBe(2);
    const error = errorOf(() => polygon({ vertices: arrow, radius: 0.1 }));
    expect(error.field).toBe('radius');
    expect(error.message).toMatch(/concave/i);
  });

  it('a zero-length wall is rejected', () => {
    const error = errorOf(() => wall({ from: { x: 1, y: 1 }, to: { x: 1, y: 1 } }));
    expect(error.message).toMatch(/differ/);
  });

  it('a regular polygon needs 3 to 8 whole sides', () => {
    expect(errorOf(() => regularPolygon({ sides: 2, radius: 1 })).field).toBe('sides');
    expect(errorOf(() => regularPolygon({ sides: 4.5, radius: 1 })).field).toBe('sides');
    expect(errorOf(() => regularPolygon({ sides: 5, radius: -1 })).field).toBe('radius');
  });

  it('an unknown shape type is rejected', () => {
    const error = errorOf(
      () =>
        new Body({ shapes: [{ type: 'triangle' } as unknown as { type: 'circle'; radius: 1 }] }),
    );
    expect(error.field).toBe('shapes[0].type');
  });
});

describe('bad world changes', () => {
  it('adding a body twice or to two worlds is rejected', () => {
    const world = new World();
    const ball = world.add(particle({ radius: 1 }));
    expect(errorOf(() => world.add(ball)).message).toMatch(/added twice/);
    expect(errorOf(() => new World().add(ball)).message).toMatch(/another world/);
    expect(world.bodies).toHaveLength(1);
  });

  it('removing a body twice is rejected, and nothing is lost', () => {
    const world = new World();
    const ball = world.add(particle({ radius: 1 }));
    const other = world.add(particle({ radius: 1, position: { x: 5, y: 0 } }));
    world.remove(ball);
    expect(errorOf(() => world.remove(ball)).message).toMatch(/removed twice/);
    expect(world.bodies).toEqual([other]);
  });

  it('forces act only on dynamic bodies, with a valid duration', () => {
    const ground = box({ type: 'static', width: 10, height: 1 });
    expect(errorOf(() => ground.applyForce({ x: 1, y: 0 })).message).toMatch(/dynamic/);
    const ball = particle({ radius: 1 });
    expect(errorOf(() => ball.applyForce({ x: 1, y: 0 }, { duration: -1 })).field).toBe('duration');
    expect(errorOf(() => ball.applyForce({ x: NaN, y: 0 })).field).toBe('force.x');
    expect(errorOf(() => ball.applyTorque(Infinity)).field).toBe('torque');
  });

  it('stepping from inside a listener is rejected', () => {
    const world = new World({ gravity: { x: 0, y: 0 } });
    world.add(particle({ radius: 1, linearVelocity: { x: 1, y: 0 } }));
    let caught: unknown = null;
    world.on('move', () => {
      try {
        world.step();
      } catch (error) {
        caught = error;
      }
    });
    world.step();
    expect(caught).toBeInstanceOf(PhysicalError);
  });
});
