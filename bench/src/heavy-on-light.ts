// Heavy on light (issue #13): the same stacks in every engine, at the engines' defaults, 10 s of
// 1/60 s steps. Prints how far each box sank into the one below (m) and how far it drifted
// sideways (on the slopes: down the slope), at the end and at worst. Usage: npx tsx bench/src/heavy-on-light.ts [engines]
import { ENGINES } from './engines/index.ts';
import type { BodyDesc, SceneDesc } from './types.ts';

/** A 1 m box of `mass` kg resting with its bottom at `bottom` (m, y up). */
function block(bottom: number, mass: number): BodyDesc {
  return {
    type: 'dynamic',
    x: 0,
    y: bottom + 0.5,
    shapes: [
      { kind: 'box', hw: 0.5, hh: 0.5, cx: 0, cy: 0, angle: 0, material: { density: mass } },
    ],
  };
}

/** A 1 kg ball of radius 0.25 m resting on the ground (y up). */
const BALL: BodyDesc = {
  type: 'dynamic',
  x: 0,
  y: 0.25,
  shapes: [
    {
      kind: 'circle',
      radius: 0.25,
      cx: 0,
      cy: 0,
      material: { density: 1 / (Math.PI * 0.25 * 0.25) },
    },
  ],
};

/**
 * Boxes of the given masses, bottom first, stacked on a static ground whose top is y = 0; with
 * `ball`, a 1 kg ball of radius 0.25 m replaces the bottom box (the box above rests at 0.5 m).
 */
function stack(name: string, masses: readonly number[], ball = false, slope = 0): SceneDesc {
  const bodies: BodyDesc[] = [
    {
      type: 'static',
      x: 0,
      y: -0.5,
      shapes: [{ kind: 'box', hw: 20, hh: 0.5, cx: 0, cy: 0, angle: 0 }],
    },
  ];
  if (ball) bodies.push(BALL, block(0.5, masses[1]!));
  else masses.forEach((mass, i) => bodies.push(block(i, mass)));
  return {
    name,
    steps: 600,
    // A slope of `slope` degrees, as gravity tilted by that much over flat ground.
    gravity: {
      x: 10 * Math.sin((slope * Math.PI) / 180),
      y: -10 * Math.cos((slope * Math.PI) / 180),
    },
    sleep: true,
    material: { density: 1, friction: 0.6, restitution: 0 },
    bodies,
    quality: { kind: 'none' },
  };
}

const SCENES = [
  stack('1000 kg on 1 kg', [1, 1000]),
  stack('100 kg on 1 kg', [1, 100]),
  stack('10 kg on 1 kg', [1, 10]),
  stack('1000 kg box on a 1 kg ball', [1, 1000], true),
  stack('1 kg between two 1000 kg', [1000, 1, 1000]),
  stack('3 boxes of 1 kg (control)', [1, 1, 1]),
  // Friction 0.6 holds up to 31 degrees: nothing should slide.
  stack('100 kg on 1 kg, 10 degree slope', [1, 100], false, 10),
  stack('1000 kg on 1 kg, 20 degree slope', [1, 1000], false, 20),
];

const engineIds = (process.argv[2] ?? 'physical,box2d3-wasm,rapier2d-simd').split(',');
const rows: string[] = [];
for (const scene of SCENES) {
  for (const id of engineIds) {
    const engine = await ENGINES[id]!();
    const world = engine.create(scene);
    const count = scene.bodies.length - 1;
    let worstSink = 0;
    let worstDrift = 0;
    for (let step = 0; step < scene.steps; step++) {
      world.step();
      for (let i = 1; i <= count; i++) {
        const pose = world.pose(i);
        // Every metre below its resting height is sinking.
        worstSink = Math.max(worstSink, scene.bodies[i]!.y - pose.y);
        worstDrift = Math.max(worstDrift, Math.abs(pose.x));
      }
    }
    const sinks: string[] = [];
    // Overlap with the body below: how much lower each body sits than at rest, less the body
    // below's own sinking.
    let belowSink = 0;
    for (let i = 1; i <= count; i++) {
      const sink = scene.bodies[i]!.y - world.pose(i).y;
      sinks.push((sink - belowSink).toFixed(4));
      belowSink = sink;
    }
    rows.push(
      `| ${scene.name} | ${id} | ${sinks.join(' / ')} | ${worstSink.toFixed(4)} | ${worstDrift.toExponential(1)} |`,
    );
  }
}
process.stdout.write(
  '| scene | engine | overlap with the body below at 10 s, bottom up (m) | worst sink of any box (m) | worst sideways drift (m) |\n|---|---|---|---|---|\n',
);
process.stdout.write(`${rows.join('\n')}\n`);
