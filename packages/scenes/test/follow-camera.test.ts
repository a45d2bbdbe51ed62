import { describe, expect, it } from 'vitest';
import { World, particle } from '@physical/engine';
import {
  type Scene,
  defineScene,
  findScene,
  runScene,
  sceneValues,
  sceneView,
} from '@physical/scenes';

function scene(id: string): Scene {
  const found = findScene(id);
  if (found === undefined) throw new Error(`no sample ${id}`);
  return found;
}

describe('a camera that follows a body', () => {
  const car = scene('car');
  const chassis = (world: ReturnType<typeof runScene>) =>
    world.bodies.find((body) => body.shapes.length === 2)!;

  it('shows the declared camera while the body is inside its band', () => {
    const { x, y, width, height } = car.camera;
    expect(sceneView(car, runScene(car, sceneValues(car), 0))).toEqual({ x, y, width, height });
  });

  it('slides with the body, keeping it at the band\u2019s edge, on x only', () => {
    for (const steps of [480, 1200]) {
      const world = runScene(car, sceneValues(car), steps);
      const view = sceneView(car, world);
      const [, to] = car.camera.follow!.within!;
      // The car drove right out of the declared view: the view moved to keep it at 40 %.
      expect(view.x).toBeGreaterThan(car.camera.x + 10);
      expect(chassis(world).position.x - view.x).toBeCloseTo(to * view.width, 9);
      expect(view.y).toBe(car.camera.y);
      expect(view.width).toBe(car.camera.width);
    }
  });

  it('is the declared camera for a sample that follows nothing', () => {
    const stack = scene('vertical-stack');
    const { x, y, width, height } = stack.camera;
    expect(sceneView(stack, runScene(stack))).toEqual({ x, y, width, height });
  });

  it("with axes 'xy', slides down after a falling body too", () => {
    const falling = defineScene({
      id: 'falling-ball',
      title: 'A falling ball',
      description: 'One ball, falling.',
      parameters: [],
      camera: {
        x: 0,
        y: 0,
        width: 10,
        height: 10,
        follow: { body: (w) => w.bodies[0], axes: 'xy' },
      },
      pixelsPerMeter: 40,
      steps: 60,
      build: () => {
        const world = new World();
        world.add(particle({ position: { x: 5, y: 5 }, radius: 0.5 }));
        return world;
      },
      check: () => null,
    });
    const world = runScene(falling);
    const ball = world.bodies[0]!.position;
    // 1 s of free fall: y = 5 + g / 2, about 9.9 m, past the band's bottom at 6.5 m.
    expect(ball.y).toBeGreaterThan(9);
    expect(sceneView(falling, world)).toEqual({ x: 0, y: ball.y - 6.5, width: 10, height: 10 });
  });
});
