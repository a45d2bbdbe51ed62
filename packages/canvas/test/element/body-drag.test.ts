import { World, box } from '@physical/engine';
import { describe, expect, it } from 'vitest';
import { BodyDrag } from '../../src/element/body-drag.ts';

function scene() {
  const world = new World({ gravity: { x: 0, y: 0 } });
  const ground = world.add(box({ type: 'static', position: { x: 0, y: 5 }, width: 10, height: 1 }));
  const crate = world.add(box({ position: { x: 0, y: 0 }, width: 1, height: 1 }));
  return { world, ground, crate, drag: new BodyDrag() };
}

describe('BodyDrag', () => {
  it('pulls the pressed point of a dynamic body to the pointer', () => {
    const { world, crate, drag } = scene();
    expect(drag.start(world, 1, crate, 0.25, 0, 3.25, 0)).toBe(true);
    for (let i = 0; i < 120; i++) world.step(1 / 60);
    // The pressed point (0.25 m right of the centre) ends under the pointer at (3.25, 0).
    expect(crate.position.x).toBeCloseTo(3, 1);
    expect(world.joints.length).toBe(1);
    drag.end(1, 0, 0, false);
    expect(world.joints.length).toBe(0);
    expect(drag.size).toBe(0);
  });

  it('refuses static bodies and bodies outside the world', () => {
    const { world, ground, drag } = scene();
    expect(drag.start(world, 1, ground, 0, 5, 1, 5)).toBe(false);
    const loose = box({ position: { x: 0, y: 0 }, width: 1, height: 1 });
    expect(drag.start(world, 2, loose, 0, 0, 1, 0)).toBe(false);
    expect(world.joints.length).toBe(0);
  });

  it('throws with the finger velocity, capped at 50 m/s', () => {
    const { world, crate, drag } = scene();
    drag.start(world, 1, crate, 0, 0, 0, 0);
    drag.end(1, 3, -4, true);
    expect([crate.linearVelocity.x, crate.linearVelocity.y]).toEqual([3, -4]);
    drag.start(world, 1, crate, 0, 0, 0, 0);
    drag.end(1, 300, -400, true);
    expect(crate.linearVelocity.x).toBeCloseTo(30, 12);
    expect(crate.linearVelocity.y).toBeCloseTo(-40, 12);
  });

  it('lets go quietly when the held body left the world, and holds one body per pointer', () => {
    const { world, crate, drag } = scene();
    const other = world.add(box({ position: { x: 3, y: 0 }, width: 1, height: 1 }));
    drag.start(world, 1, crate, 0, 0, 0, 0);
    drag.start(world, 2, other, 3, 0, 3, 0);
    expect(world.joints.length).toBe(2);
    world.remove(crate); // takes its joint with it
    drag.move(1, 1, 1);
    expect(() => drag.end(1, 5, 5, true)).not.toThrow();
    drag.clear();
    expect(world.joints.length).toBe(0);
    expect(drag.size).toBe(0);
  });
});
