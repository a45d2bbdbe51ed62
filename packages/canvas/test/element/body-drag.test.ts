import { World, box, mouseJoint, type Body } from '@physical/engine';
import { describe, expect, it } from 'vitest';
import { BodyDrag } from '../../src/element/body-drag.ts';

function scene() {
  const world = new World({ gravity: { x: 0, y: 0 } });
  const ground = world.add(box({ type: 'static', position: { x: 0, y: 5 }, width: 10, height: 1 }));
  const crate = world.add(box({ position: { x: 0, y: 0 }, width: 1, height: 1 }));
  return { world, ground, crate, drag: new BodyDrag() };
}

/** Steps `world` `steps` times at `dt`, the drag pulling before each step (as the canvas does). */
function run(world: World, drag: BodyDrag, steps: number, dt = 1 / 60): void {
  for (let i = 0; i < steps; i++) {
    drag.pull(dt);
    world.step(dt);
  }
}

describe('BodyDrag', () => {
  it('pulls the pressed point of a dynamic body to the pointer, adding no joint', () => {
    const { world, crate, drag } = scene();
    expect(drag.start(world, 1, crate, 0.25, 0, 3.25, 0)).toBe(true);
    run(world, drag, 120);
    // The pressed point (0.25 m right of the centre) ends under the pointer at (3.25, 0).
    expect(crate.position.x).toBeCloseTo(3, 1);
    expect(drag.size).toBe(1);
    expect(drag.held[0]!.target).toEqual({ x: 3.25, y: 0 });
    expect(world.joints.length).toBe(0);
    drag.end(1, 0, 0, false);
    expect(drag.size).toBe(0);
  });

  it('pulls as a damped 5 Hz spring of ratio 0.7 (closed form, fine steps)', () => {
    // A free 1 kg body, pulled at its centre from rest 0.5 m short of the pointer (the force,
    // under 1000 N, never reaches the cap): x(t) = d (1 - e^(-z w t) (cos(wd t) + z w / wd sin(wd t))),
    // w = 2 pi 5, wd = w sqrt(1 - z^2). The soft step is implicit: with 1 ms steps it is within
    // 1 cm of the continuous spring.
    const { world, crate, drag } = scene();
    crate.mass = 1;
    drag.start(world, 1, crate, 0, 0, 0.5, 0);
    const w = 2 * Math.PI * 5;
    const z = 0.7;
    const wd = w * Math.sqrt(1 - z * z);
    let steps = 0;
    for (const t of [0.02, 0.05, 0.1, 0.2]) {
      run(world, drag, Math.round(t / 0.001) - steps, 0.001);
      steps = Math.round(t / 0.001);
      const expected =
        0.5 * (1 - Math.exp(-z * w * t) * (Math.cos(wd * t) + ((z * w) / wd) * Math.sin(wd * t)));
      expect(Math.abs(crate.position.x - expected)).toBeLessThan(0.01);
    }
  });

  it('pulls with at most 1000 N per kg: a far pointer accelerates the body at 1000 m/s^2', () => {
    const { world, crate, drag } = scene();
    drag.start(world, 1, crate, 0, 0, 100, 0);
    run(world, drag, 3);
    // v = a t, a = F / m = 1000 m/s^2, after 3 steps of 1/60 s: 50 m/s (the cap binds throughout).
    expect(crate.linearVelocity.x).toBeCloseTo(50, 6);
    expect(crate.linearVelocity.y).toBeCloseTo(0, 9);
  });

  it("keeps the held point within 3 cm of where the engine's mouse joint takes it", () => {
    // Under gravity, on a floor, grabbed off-centre and swung about for 4 s: the same path.
    const path = (pull: 'joint' | 'drag'): { x: number; y: number }[] => {
      const world = new World();
      world.add(box({ type: 'static', position: { x: 0, y: 5 }, width: 20, height: 1 }));
      const body: Body = world.add(box({ position: { x: 0, y: 4 }, width: 1, height: 0.6 }));
      const grab = { x: 0.3, y: 3.8 };
      const local = body.getLocalPoint(grab);
      const drag = new BodyDrag();
      const joint = pull === 'joint' ? world.addJoint(mouseJoint({ body, target: grab })) : null;
      if (pull === 'drag') drag.start(world, 1, body, grab.x, grab.y, grab.x, grab.y);
      const points = [];
      for (let i = 0; i < 240; i++) {
        const t = Math.min(i, 150) / 60;
        const x = 0.3 + 2 * Math.sin(2 * t);
        const y = 3.8 - 2 * t + (t > 1.5 ? 2 * (t - 1.5) : 0);
        if (joint !== null) joint.target = { x, y };
        else drag.move(1, x, y);
        drag.pull(1 / 60);
        world.step(1 / 60);
        points.push(body.getWorldPoint(local));
      }
      return points;
    };
    const joint = path('joint');
    const drag = path('drag');
    let farthest = 0;
    for (let i = 0; i < joint.length; i++) {
      farthest = Math.max(farthest, Math.hypot(joint[i]!.x - drag[i]!.x, joint[i]!.y - drag[i]!.y));
    }
    expect(farthest).toBeLessThan(0.03);
    // It did move: 2 m and more.
    expect(Math.hypot(drag[150]!.x - 0.3, drag[150]!.y - 3.8)).toBeGreaterThan(2);
  });

  it('refuses static bodies and bodies outside the world', () => {
    const { world, ground, drag } = scene();
    expect(drag.start(world, 1, ground, 0, 5, 1, 5)).toBe(false);
    const loose = box({ position: { x: 0, y: 0 }, width: 1, height: 1 });
    expect(drag.start(world, 2, loose, 0, 0, 1, 0)).toBe(false);
    expect(drag.size).toBe(0);
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
    expect(drag.size).toBe(2);
    world.remove(crate);
    drag.move(1, 1, 1);
    expect(() => drag.end(1, 5, 5, true)).not.toThrow();
    expect(crate.linearVelocity).toEqual({ x: 0, y: 0 });
    // A hold whose body leaves between steps is dropped by the next pull.
    world.remove(other);
    drag.pull(1 / 60);
    expect(drag.size).toBe(0);
    drag.start(world, 3, world.add(box({ width: 1, height: 1 })), 0, 0, 0, 0);
    drag.clear();
    expect(drag.size).toBe(0);
  });

  it('leaves a sleeping body asleep until the pointer moves', () => {
    const { world, crate, drag } = scene();
    drag.start(world, 1, crate, 0, 0, 0, 0);
    crate.sleep();
    drag.pull(1 / 60);
    expect(crate.isAwake).toBe(false);
    drag.move(1, 1, 0);
    expect(crate.isAwake).toBe(true);
  });
});
