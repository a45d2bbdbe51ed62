import { describe, expect, it } from 'vitest';
import { reportMeasured } from './measured.ts';
import { World, box, particle, wall } from '@physical/engine';
import type { Body } from '@physical/engine';

// Law 12: no tunneling. A 0.1 m circle and a 0.2 m box spinning at 50 rad/s, each at 100 m/s
// toward a static wall (a segment, or a thin static box; square on or at an angle), never end a
// step on the far side of it (60 Hz, checked after every step for 2 s).

const DT = 1 / 60;
const SPEED = 100;

type Projectile = 'circle' | 'box';
type Barrier = 'segment' | 'thin box';

function scenario(projectile: Projectile, barrier: Barrier, tilt: number): number {
  const world = new World({ gravity: { x: 0, y: 0 } });
  // The barrier passes through the origin; its normal n = (cos tilt, sin tilt) points back toward
  // the projectile, which starts 5 m away along n and flies along -n.
  const nx = Math.cos(tilt);
  const ny = Math.sin(tilt);
  const half = 500; // long enough that a body sliding along it stays on it for 2 s
  if (barrier === 'segment') {
    world.add(wall({ from: { x: -ny * half, y: nx * half }, to: { x: ny * half, y: -nx * half } }));
  } else {
    world.add(
      box({ type: 'static', position: { x: 0, y: 0 }, angle: tilt, width: 0.02, height: 2 * half }),
    );
  }
  const options = {
    position: { x: 5 * nx, y: 5 * ny },
    linearVelocity: { x: -SPEED * nx, y: -SPEED * ny },
  };
  const body: Body =
    projectile === 'circle'
      ? world.add(particle({ ...options, radius: 0.1 }))
      : world.add(box({ ...options, width: 0.2, height: 0.2, angularVelocity: 50 }));
  // Signed distance of the centre from the barrier's mid-plane: must stay positive.
  let closest = Infinity;
  for (let i = 0; i < 2 / DT; i++) {
    world.step(DT);
    const d = body.position.x * nx + body.position.y * ny;
    closest = Math.min(closest, d);
    if (d <= 0) return d;
  }
  return closest;
}

describe('tunneling', () => {
  for (const projectile of ['circle', 'box'] as const) {
    for (const barrier of ['segment', 'thin box'] as const) {
      it.each([0, 0.5, 1.2])(
        `a ${projectile} at 100 m/s stays in front of a ${barrier} (tilt %f rad)`,
        (tilt) => {
          const closest = scenario(projectile, barrier, tilt);
          reportMeasured(
            '12 tunneling, closest distance in front of the wall (m, must stay > 0)',
            closest,
            0,
          );
          expect(closest).toBeGreaterThan(0);
        },
      );
    }
  }
});
