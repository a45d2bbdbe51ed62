import { describe, expect, it } from 'vitest';
import { reportMeasured } from './measured.ts';
import { World, box, distanceJoint, particle, revoluteJoint, type Body } from '@physical/engine';

// Newton's cradle: five equal, perfectly elastic balls hanging in a touching row. One ball swung
// in gives its momentum and energy to the last one, which swings out to the same height; the
// middle three stay put (within 1 cm) and the first one stops (within 1 cm).

const R = 0.1;
const L = 1;
const THETA = 0.4;
const DT = 1 / 60;
const MIDDLE_TOLERANCE = 0.01;

describe("Newton's cradle", () => {
  it.each(['revolute', 'distance'] as const)(
    'hung by %s joints: one ball in, one ball out',
    (kind) => {
      const world = new World({ enableSleep: false, restitutionThreshold: 0 });
      const ceiling = world.add(
        box({ type: 'static', position: { x: 0, y: -0.05 }, width: 3, height: 0.1 }),
      );
      const balls: { ball: Body; restX: number }[] = [];
      for (let i = 0; i < 5; i++) {
        const restX = (i - 2) * 2 * R;
        const position =
          i === 0 ? { x: restX - L * Math.sin(THETA), y: L * Math.cos(THETA) } : { x: restX, y: L };
        const ball = world.add(particle({ position, radius: R, restitution: 1, friction: 0 }));
        balls.push({ ball, restX });
        const pivot = { x: restX, y: 0 };
        if (kind === 'revolute') {
          world.addJoint(revoluteJoint({ bodyA: ceiling, bodyB: ball, anchor: pivot }));
        } else {
          world.addJoint(
            distanceJoint({ bodyA: ceiling, bodyB: ball, anchorA: pivot, anchorB: position }),
          );
        }
      }
      const last = balls[4]!;
      let hit = false;
      let middle = 0;
      let first = 0;
      let swing = 0;
      // Half a period after the impact: the last ball reaches the top of its swing.
      for (let i = 0; i < 60; i++) {
        world.step(DT);
        if (last.ball.linearVelocity.x > 0.01) hit = true;
        if (!hit) continue;
        for (let k = 1; k < 4; k++) {
          middle = Math.max(middle, Math.abs(balls[k]!.ball.position.x - balls[k]!.restX));
        }
        first = Math.max(first, Math.abs(balls[0]!.ball.position.x - balls[0]!.restX));
        swing = Math.max(swing, last.ball.position.x - last.restX);
      }
      expect(hit).toBe(true);
      reportMeasured(
        `Newton's cradle (${kind}): middle balls' largest move (m)`,
        middle,
        MIDDLE_TOLERANCE,
      );
      reportMeasured(
        `Newton's cradle (${kind}): first ball's largest move after impact (m)`,
        first,
        MIDDLE_TOLERANCE,
      );
      expect(middle).toBeLessThan(MIDDLE_TOLERANCE);
      expect(first).toBeLessThan(MIDDLE_TOLERANCE);
      // The last ball swings out as far as the first came in, within 2 % (a hinged disc also has
      // to spin up with its swing: 0.5 % of the energy for this bob).
      const expected = L * Math.sin(THETA);
      const swingError = Math.abs(swing - expected) / expected;
      reportMeasured(
        `Newton's cradle (${kind}): last ball's swing, relative error`,
        swingError,
        0.02,
      );
      expect(swingError).toBeLessThan(0.02);
    },
  );
});
