import { describe, expect, it } from 'vitest';
import { World, particle } from '@physical/engine';
import { physicalErrorOf } from './expect-physical-error.ts';

// Finding 11: a misspelt event name or options of the wrong kind are errors, not silent no-ops.

describe('typos are errors', () => {
  it('world.on with an unknown event name', () => {
    const error = physicalErrorOf(() => new World().on('colision' as never, (() => {}) as never));
    expect(error.field).toBe('type');
    expect(error.message).toContain("'collision'");
  });

  it('body.on and off with an unknown event name', () => {
    const body = particle({ radius: 1 });
    physicalErrorOf(() => body.on('moved' as never, (() => {}) as never));
    physicalErrorOf(() => body.off('moved' as never, (() => {}) as never));
    physicalErrorOf(() => body.on('bodyAdded' as never, (() => {}) as never));
  });

  it('a listener that is not a function', () => {
    expect(physicalErrorOf(() => new World().on('move', 'fn' as never)).field).toBe('listener');
  });

  it("applyForce(f, 'constant') is refused, not an instant force", () => {
    const world = new World();
    const ball = world.add(particle({ radius: 1 }));
    const error = physicalErrorOf(() => ball.applyForce({ x: 1, y: 0 }, 'constant' as never));
    expect(error.field).toBe('options');
    expect(ball.forces.length).toBe(0);
    physicalErrorOf(() => ball.applyTorque(1, 'constant' as never));
  });

  it('an unknown duration string', () => {
    const ball = new World().add(particle({ radius: 1 }));
    expect(
      physicalErrorOf(() => ball.applyForce({ x: 1, y: 0 }, { duration: 'forever' as never }))
        .field,
    ).toBe('duration');
  });
});
