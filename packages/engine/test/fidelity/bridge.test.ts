import { describe, expect, it } from 'vitest';
import { reportMeasured } from './measured.ts';
import { World, box, revoluteJoint, type Body, type Vec2 } from '@physical/engine';

// A rope bridge of 30 planks (1 m x 0.25 m, 5 kg each) on 31 revolute joints between two static
// banks, hanging with some slack, catches a 10 kg box dropped on its middle. The joints must hold:
// every pair of joined anchor points stays within 1 cm over 10 s, and the box stays on the bridge.

const PLANKS = 30;
const SLACK_ANGLE = 0.4; // the end planks' slope (rad); the slope changes evenly along the bridge
const DT = 1 / 60;
const TOLERANCE = 0.01;

interface Hinge {
  a: Body;
  b: Body;
  localA: Vec2;
  localB: Vec2;
}

describe('bridge', () => {
  it('30 planks on revolute joints hold a 10 kg box with joint error under 1 cm', () => {
    const world = new World();
    const bank = world.add(
      box({ type: 'static', position: { x: -0.5, y: 0 }, width: 1, height: 0.25 }),
    );
    const hinges: Hinge[] = [];
    const hinge = (a: Body, b: Body, anchor: Vec2): void => {
      world.addJoint(revoluteJoint({ bodyA: a, bodyB: b, anchor }));
      hinges.push({ a, b, localA: a.getLocalPoint(anchor), localB: b.getLocalPoint(anchor) });
    };
    let previous = bank;
    let x = 0;
    let y = 0;
    for (let i = 0; i < PLANKS; i++) {
      const angle = SLACK_ANGLE * (1 - (2 * i + 1) / PLANKS);
      const c = Math.cos(angle);
      const s = Math.sin(angle);
      const plank = world.add(
        box({
          position: { x: x + 0.5 * c, y: y + 0.5 * s },
          angle,
          width: 1,
          height: 0.25,
          density: 20,
        }),
      );
      hinge(previous, plank, { x, y });
      previous = plank;
      x += c;
      y += s;
    }
    const otherBank = world.add(
      box({ type: 'static', position: { x: x + 0.5, y }, width: 1, height: 0.25 }),
    );
    hinge(previous, otherBank, { x, y });
    const load = world.add(
      box({ position: { x: x / 2, y: -1 }, width: 1, height: 1, density: 10 }),
    );
    expect(load.mass).toBeCloseTo(10, 12);

    let worst = 0;
    for (let i = 0; i < 600; i++) {
      world.step(DT);
      for (const { a, b, localA, localB } of hinges) {
        const p = a.getWorldPoint(localA);
        const q = b.getWorldPoint(localB);
        worst = Math.max(worst, Math.hypot(p.x - q.x, p.y - q.y));
      }
    }
    reportMeasured(
      'bridge of 30 planks with a 10 kg box: largest joint error (m)',
      worst,
      TOLERANCE,
    );
    expect(worst).toBeLessThan(TOLERANCE);
    // Still on the bridge: above the lowest the planks can reach, between the banks.
    expect(load.position.y).toBeLessThan(x / 2);
    expect(load.position.x).toBeGreaterThan(0);
    expect(load.position.x).toBeLessThan(x);
  });
});
