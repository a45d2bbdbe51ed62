import { describe, expect, it } from 'vitest';
import { World, box, particle, revoluteJoint, wall } from '@physical/engine';

// Hinge chains with unlike masses (solved exactly, pin-chains.ts) under a constant torque on
// their first link stay finite for 600 steps, over a grid of bob ratios, chain lengths, torques,
// sub-steps and speed limits. Before the chains' stiffening was bounded (MAX_STIFFENING), a
// stiffened link needed larger impulses to turn, which stiffened it more: a 10,000:1 chain of five
// links with 1,000 N m on its first link went NaN at step 99, and 5 of these 32 worlds did.

const LINK = 0.4;

function torquedChain(
  ratio: number,
  links: number,
  torque: number,
  subSteps: number,
  maxLinearSpeed: number,
): World {
  const world = new World({ subSteps, maxLinearSpeed });
  world.add(wall({ from: { x: -40, y: 0 }, to: { x: 40, y: 0 } }));
  let previous = world.add(
    box({ type: 'static', position: { x: 14, y: -12 }, width: 0.2, height: 0.2 }),
  );
  for (let k = 0; k < links; k++) {
    const link = world.add(
      box({
        position: { x: 14 + LINK * (k + 0.5), y: -12 },
        width: LINK,
        height: 0.05,
        density: 20,
      }),
    );
    world.addJoint(
      revoluteJoint({ bodyA: previous, bodyB: link, anchor: { x: 14 + LINK * k, y: -12 } }),
    );
    if (k === 0) link.applyTorque(torque, { duration: 'constant' });
    previous = link;
  }
  const end = 14 + LINK * links;
  const bob = world.add(
    particle({ position: { x: end, y: -12 }, radius: 0.1, density: 32 * ratio }),
  );
  world.addJoint(revoluteJoint({ bodyA: previous, bodyB: bob, anchor: { x: end, y: -12 } }));
  return world;
}

function firstNonFinite(world: World): string | null {
  for (const [n, b] of world.bodies.entries()) {
    const numbers = [
      b.position.x,
      b.position.y,
      b.angle,
      b.linearVelocity.x,
      b.linearVelocity.y,
      b.angularVelocity,
    ];
    if (!numbers.every(Number.isFinite)) return `body ${n}`;
  }
  for (const [n, j] of world.joints.entries()) {
    if (![j.reactionForce.x, j.reactionForce.y, j.reactionTorque].every(Number.isFinite)) {
      return `joint ${n}`;
    }
  }
  return null;
}

describe('torqued hinge chains', () => {
  it('stay finite for 600 steps (1000:1 and 10,000:1, 5 and 8 links, +-1000 N m)', () => {
    const failures: string[] = [];
    for (const ratio of [1000, 10_000]) {
      for (const links of [5, 8]) {
        for (const torque of [-1000, 1000]) {
          for (const subSteps of [2, 4]) {
            for (const maxLinearSpeed of [40, 400]) {
              const world = torquedChain(ratio, links, torque, subSteps, maxLinearSpeed);
              for (let i = 0; i < 600; i++) {
                world.step(1 / 60);
                const bad = firstNonFinite(world);
                if (bad !== null) {
                  failures.push(
                    `${ratio}:1, ${links} links, ${torque} N m, ${subSteps} sub-steps, ` +
                      `${maxLinearSpeed} m/s: ${bad} at step ${i}`,
                  );
                  break;
                }
              }
            }
          }
        }
      }
    }
    expect(failures).toEqual([]);
  }, 300_000);
});
