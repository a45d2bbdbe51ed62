// Scenes of the canvas benchmark, built in the page.
import { World, box, wall } from '@physical/engine';

/**
 * 1,000 boxes of 0.3 m bouncing without gravity or friction in a closed 20 m x 15 m room:
 * they never come to rest, so every frame steps and draws all of them.
 */
export function movingBoxes(count = 1000): World {
  const world = new World({ gravity: { x: 0, y: 0 }, enableSleep: false });
  const corners = [
    { x: 0, y: 0 },
    { x: 20, y: 0 },
    { x: 20, y: 15 },
    { x: 0, y: 15 },
  ];
  for (let i = 0; i < 4; i++)
    world.add(wall({ from: corners[i]!, to: corners[(i + 1) % 4]!, friction: 0 }));
  let seed = 1;
  const random = (): number => ((seed = (seed * 16807) % 2147483647) - 1) / 2147483646;
  const columns = 40;
  for (let i = 0; i < count; i++) {
    world.add(
      box({
        position: { x: 0.5 + (i % columns) * 0.475, y: 0.5 + Math.floor(i / columns) * 0.55 },
        width: 0.3,
        height: 0.3,
        angle: random() * Math.PI,
        friction: 0,
        restitution: 1,
        linearVelocity: { x: (random() - 0.5) * 4, y: (random() - 0.5) * 4 },
      }),
    );
  }
  return world;
}

/** 100 boxes dropped in rows onto a floor: a pile that comes to rest within seconds. */
export function settlingPile(): World {
  const world = new World();
  world.add(wall({ from: { x: 0, y: 14 }, to: { x: 20, y: 14 } }));
  for (let i = 0; i < 100; i++) {
    const position = { x: 2 + (i % 20) * 0.8, y: 13.6 - Math.floor(i / 20) * 0.85 };
    world.add(box({ position, width: 0.7, height: 0.7 }));
  }
  return world;
}
