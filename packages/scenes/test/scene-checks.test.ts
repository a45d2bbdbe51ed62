import { describe, expect, it } from 'vitest';
import { STEP, type Scene, findScene, runScene, sceneValues } from '@physical/scenes';

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
    // Bodies 0 and 1 are the two walls; the bullets follow.
    world.bodies[2]!.position = { x: 9, y: -1 };
    expect(bullets.check(world, sceneValues(bullets))).toMatch(/bullet 1 passed through the wall/);
  });

  it('bullets: a bullet behind the back wall', () => {
    const bullets = scene('bullets');
    const world = runScene(bullets);
    world.bodies[3]!.position = { x: -1, y: -1 };
    expect(bullets.check(world, sceneValues(bullets))).toMatch(/bullet 2 passed through the back/);
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

  it('sensors: a zone that counted one ball twice', () => {
    const sensors = scene('sensors');
    const world = runScene(sensors);
    const zone = world.bodies.find((body) => body.shapes[0]?.sensor === true)!;
    (zone.userData as { entered: number }).entered++;
    expect(sensors.check(world, sceneValues(sensors))).toMatch(/the zone counted/);
  });

  it('sensors: balls still above the zone', () => {
    const sensors = scene('sensors');
    expect(
      sensors.check(runScene(sensors, sceneValues(sensors), 10), sceneValues(sensors)),
    ).toMatch(/has not fallen past/);
  });

  it('collision filtering: teams never thrown at each other never touch', () => {
    const filtering = scene('collision-filtering');
    const values = sceneValues(filtering, { speed: 0 });
    expect(filtering.check(runScene(filtering, values), values)).toMatch(/ever touched/);
  });

  it('collision filtering: without the filters, teammates collide', () => {
    const filtering = scene('collision-filtering');
    const values = sceneValues(filtering);
    const world = filtering.build(values);
    for (const body of world.bodies) body.shapes[0]!.filter = { category: 1, mask: 0xffffffff };
    for (let i = 0; i < filtering.steps; i++) world.step(STEP);
    expect(filtering.check(world, values)).toMatch(/contacts between balls of one team/);
  });

  it('collision filtering: a red ball placed inside a blue one', () => {
    const filtering = scene('collision-filtering');
    const world = runScene(filtering);
    const red = world.bodies.find((body) => body.userData === 'red')!;
    const blue = world.bodies.find((body) => body.userData === 'blue')!;
    red.position = { x: blue.position.x + 0.1, y: blue.position.y };
    expect(filtering.check(world, sceneValues(filtering))).toMatch(/overlap by/);
  });

  it('bullet flag: without it, the plain balls pass through the moving plates', () => {
    const flag = scene('bullet-flag');
    const values = sceneValues(flag, { bullet: 0 });
    expect(flag.check(runScene(flag, values), values)).toMatch(/4 of 4 shots passed through/);
  });
});
