import { describe, expect, it } from 'vitest';
import { World, particle, wall } from '@physical/engine';

// Finding 9: a listener removed during dispatch (by itself or by another listener) is not called
// again, not even for the other events of the same step.

function fourLandings(): World {
  const world = new World();
  world.add(wall({ from: { x: -10, y: 1 }, to: { x: 10, y: 1 } }));
  for (let i = 0; i < 4; i++)
    world.add(particle({ position: { x: 2 * i - 3, y: 0.5 }, radius: 0.25 }));
  return world;
}

describe('listener removal is immediate', () => {
  it('a world listener that removes itself runs once, though four bodies land in the step', () => {
    const world = fourLandings();
    let calls = 0;
    const stop = world.on('collision', () => {
      calls++;
      stop();
    });
    for (let i = 0; i < 60 && calls === 0; i++) world.step();
    for (let i = 0; i < 30; i++) world.step();
    expect(calls).toBe(1);
  });

  it('a listener removed by an earlier listener of the same event is not called', () => {
    const world = fourLandings();
    let secondCalls = 0;
    const second = (): void => {
      secondCalls++;
    };
    world.on('collision', () => world.off('collision', second));
    world.on('collision', second);
    for (let i = 0; i < 90; i++) world.step();
    expect(secondCalls).toBe(0);
  });

  it('a body listener that removes itself runs once', () => {
    const world = fourLandings();
    const body = world.bodies[1]!;
    let calls = 0;
    const stop = body.on('move', () => {
      calls++;
      stop();
    });
    for (let i = 0; i < 30; i++) world.step();
    expect(calls).toBe(1);
  });
});
