import { afterEach, beforeEach, describe, expect, it, vi, type MockInstance } from 'vitest';
import { World, box, particle, wall } from '@physical/engine';

// Development builds warn once per world about a moving body outside 0.1..10 m (Box2D's unit
// guidance); production builds (process.env.NODE_ENV === 'production') stay silent.
describe('size warning', () => {
  // The engine's tests compile without DOM or Node types: the console as the warning uses it.
  const host = globalThis as unknown as { console: { warn(message: string): void } };
  let warn: MockInstance<(message: string) => void>;
  const nodeEnv = process.env['NODE_ENV'];
  beforeEach(() => {
    warn = vi.spyOn(host.console, 'warn').mockImplementation(() => undefined);
  });
  afterEach(() => {
    warn.mockRestore();
    process.env['NODE_ENV'] = nodeEnv;
  });

  it('warns once per world about an 80 m box (pixels by mistake), naming its size and the range', () => {
    const world = new World();
    world.add(box({ position: { x: 0, y: 0 }, width: 80, height: 80 }));
    world.add(box({ position: { x: 200, y: 0 }, width: 120, height: 40 }));
    expect(warn).toHaveBeenCalledTimes(1);
    const message = String(warn.mock.calls[0]![0]);
    expect(message).toContain('80 m across');
    expect(message).toContain('0.1 to 10 m');
    expect(message).toContain('pixels');
    new World().add(box({ width: 80, height: 80 }));
    expect(warn).toHaveBeenCalledTimes(2); // a new world warns again
  });

  it('warns about a body smaller than 0.1 m', () => {
    new World().add(particle({ radius: 0.02 }));
    expect(warn).toHaveBeenCalledTimes(1);
    expect(String(warn.mock.calls[0]![0])).toContain('0.04 m across');
  });

  it('stays silent for bodies in range, at its edges, and for large static walls', () => {
    const world = new World();
    world.add(box({ width: 1, height: 1 }));
    world.add(box({ width: 10, height: 0.1 }));
    world.add(particle({ radius: 0.05 }));
    world.add(wall({ from: { x: -500, y: 0 }, to: { x: 500, y: 0 } }));
    world.add(box({ type: 'static', width: 80, height: 80 }));
    expect(warn).not.toHaveBeenCalled();
  });

  it('stays silent in production builds', () => {
    process.env['NODE_ENV'] = 'production';
    new World().add(box({ width: 80, height: 80 }));
    expect(warn).not.toHaveBeenCalled();
  });
});
