import { World, box, particle, wall } from '@physical/engine';

/**
 * The scene issue #28 measured the engines' drift on (it was not tuned on): a walled box of 12
 * boxes and 12 balls thrown in turning and bouncing, which settle and rest. 900 steps of 1/60 s.
 * Only + - * / here, so the scene itself is built the same in every engine.
 */
export function buildHeldOutScene(): World {
  const world = new World();
  world.add(wall({ from: { x: -5, y: -10 }, to: { x: -5, y: 0 } }));
  world.add(wall({ from: { x: -5, y: 0 }, to: { x: 5, y: 0 } }));
  world.add(wall({ from: { x: 5, y: 0 }, to: { x: 5, y: -10 } }));
  for (let i = 0; i < 12; i++) {
    const column = i % 6;
    const row = (i - column) / 6;
    world.add(
      box({
        position: { x: -4 + 1.5 * column, y: -3 - 1.4 * row },
        width: 0.5 + 0.05 * i,
        height: 0.4 + 0.03 * i,
        angle: 0.3 * i - 1.2,
        linearVelocity: { x: 3 - 0.5 * i, y: -2 + 0.3 * i },
        angularVelocity: 4 - 0.7 * i,
        restitution: 0.4,
        friction: 0.5,
      }),
    );
    world.add(
      particle({
        position: { x: -3.7 + 1.4 * column, y: -6 - 1.2 * row },
        radius: 0.2 + 0.02 * i,
        linearVelocity: { x: -2 + 0.4 * i, y: 1 - 0.2 * i },
        angularVelocity: 2 - 0.3 * i,
        restitution: 0.7,
        friction: 0.3,
      }),
    );
  }
  return world;
}
