import { describe, expect, it } from 'vitest';
import { type Scene, findScene, runScene, sceneValues } from '@physical/scenes';

function scene(id: string): Scene {
  const found = findScene(id);
  if (found === undefined) throw new Error(`no sample ${id}`);
  return found;
}

// The physical checks must be able to fail: each catches a world that went wrong.
describe('sample checks reject broken outcomes', () => {
  it('vertical stack: a box pushed off the column', () => {
    const stack = scene('vertical-stack');
    const world = runScene(stack);
    world.bodies[5]!.position = { x: 0.3, y: world.bodies[5]!.position.y };
    expect(stack.check(world, sceneValues(stack))).toMatch(/box 4 drifted/);
  });

  it("Newton's cradle: before the impact, the pulled ball is still out", () => {
    const cradle = scene('newtons-cradle');
    expect(cradle.check(runScene(cradle, sceneValues(cradle), 10), sceneValues(cradle))).toMatch(
      /ball 0 moved/,
    );
  });

  it('forces with durations: an extra impulse on the instant block', () => {
    const forces = scene('forces-with-durations');
    const world = runScene(forces);
    world.bodies[0]!.applyImpulse({ x: 0.001, y: 0 });
    expect(forces.check(world, sceneValues(forces))).toMatch(/instant force/);
  });

  it('bullets: a bullet behind the wall', () => {
    const bullets = scene('bullets');
    const world = runScene(bullets);
    world.bodies[1]!.position = { x: 9, y: -1 };
    expect(bullets.check(world, sceneValues(bullets))).toMatch(/passed through/);
  });

  it('bridge: a plank torn off its hinges', () => {
    const bridge = scene('bridge');
    const world = runScene(bridge);
    const plank = world.bodies[3]!;
    plank.position = { x: plank.position.x, y: plank.position.y + 0.5 };
    expect(bridge.check(world, sceneValues(bridge))).toMatch(/hinge opened/);
  });

  it('restitution row: a ball that never reached the ground', () => {
    const row = scene('restitution-row');
    expect(row.check(runScene(row, sceneValues(row), 5), sceneValues(row))).toMatch(
      /never bounced/,
    );
  });
});
