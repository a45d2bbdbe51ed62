import { World, box } from '@physical/engine';
import { describe, expect, it } from 'vitest';
import { PoseHistory } from '../../src/element/pose-history.ts';

describe('PoseHistory', () => {
  it('blends the pose before the last step with the current one', () => {
    const world = new World();
    const body = world.add(box({ position: { x: 0, y: 0 }, width: 1, height: 1 }));
    const history = new PoseHistory();
    history.snapshot(world.bodies);
    const before = body.position.y;
    world.step(1 / 60);
    const after = body.position.y;
    const pose = history.interpolate(body, 0, 0.25, { x: 0, y: 0, angle: 0 });
    expect(pose.y).toBeCloseTo(0.75 * before + 0.25 * after, 12);
    expect(history.interpolate(body, 0, 1, pose).y).toBe(after);
  });

  it('draws a body that was not in the snapshot at its current pose', () => {
    const world = new World();
    const history = new PoseHistory();
    history.snapshot(world.bodies);
    const body = world.add(box({ position: { x: 2, y: 3 }, width: 1, height: 1 }));
    expect(history.interpolate(body, 0, 0.5, { x: 0, y: 0, angle: 0 })).toEqual({
      x: 2,
      y: 3,
      angle: 0,
    });
  });
});
