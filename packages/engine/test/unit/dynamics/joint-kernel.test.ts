import { afterEach, describe, expect, it } from 'vitest';
import {
  World,
  box,
  distanceJoint,
  mouseJoint,
  particle,
  prismaticJoint,
  revoluteJoint,
  weldJoint,
  type Joint,
} from '@physical/engine';
import { hashWorld, runScene, sceneValues, scenes } from '@physical/scenes';
import { kernelSettings } from '../../../src/dynamics/solver-memory.ts';
import { exportJointState } from '../../../src/dynamics/joints/joint-state.ts';
// The JavaScript build of the kernel, compared here with the WebAssembly one.
import '@physical/engine/javascript-kernel';
import { bodyStates, differingBits } from './body-states.ts';

// The joints' passes (wasm/joint-passes.ts) have one source, built to WebAssembly and by wasm2js
// to JavaScript: every world with joints must come out bit for bit the same whichever build runs
// it. (That the passes give the numbers the TypeScript passes they replaced gave: the regression
// hashes, packages/scenes/baselines.json, unchanged.)

const DT = 1 / 60;
const DEFAULT_THRESHOLD = kernelSettings.minConstraints;
afterEach(() => {
  kernelSettings.minConstraints = DEFAULT_THRESHOLD;
});

/** Every kind, with its springs, motors and limits on, on a ground and on each other. */
function everyKind(kernel: 'auto' | 'javascript'): { world: World; joints: Joint[] } {
  const world = new World({ kernel, enableSleep: false });
  const ground = world.add(
    box({ type: 'static', position: { x: 0, y: 3 }, width: 20, height: 0.2 }),
  );
  const at = (x: number, y: number) =>
    world.add(box({ position: { x, y }, width: 0.5, height: 0.3, angle: 0.1 * x }));
  const joints: Joint[] = [];
  for (let k = 0; k < 3; k++) {
    const x = -6 + 6 * k;
    const a = at(x, 0);
    const b = at(x + 1, 0);
    const c = at(x + 2, 0.5);
    const d = at(x - 1, -1);
    const e = world.add(particle({ position: { x: x + 0.5, y: -2 }, radius: 0.2 }));
    joints.push(
      world.addJoint(
        revoluteJoint({
          bodyA: ground,
          bodyB: a,
          anchor: { x, y: 0.5 },
          enableLimit: true,
          lowerAngle: -0.25 * (k + 1),
          upperAngle: 0.5,
          enableMotor: k !== 1,
          motorSpeed: 2 - k,
          maxMotorTorque: 15,
          enableSpring: k !== 2,
          hertz: 2.5,
          dampingRatio: 0.125 * k,
        }),
      ),
      world.addJoint(revoluteJoint({ bodyA: a, bodyB: b, anchor: { x: x + 0.5, y: 0 } })),
      world.addJoint(
        prismaticJoint({
          bodyA: b,
          bodyB: c,
          anchor: { x: x + 1.5, y: 0.25 },
          axis: { x: 0.6, y: 0.8 },
          enableLimit: k !== 0,
          lower: -0.375,
          upper: 0.625,
          enableMotor: true,
          motorSpeed: 0.875 - k,
          maxMotorForce: 30,
          enableSpring: k !== 1,
          hertz: 1.25,
          dampingRatio: 0.0625,
        }),
      ),
      world.addJoint(
        distanceJoint({
          bodyA: ground,
          bodyB: d,
          anchorA: { x: x - 1, y: 3 },
          anchorB: { x: x - 1, y: -1 },
          length: 3.5,
          minLength: 3,
          maxLength: 4,
          enableSpring: k !== 0,
          hertz: 3.25,
          dampingRatio: 0.3125,
        }),
      ),
      world.addJoint(
        weldJoint({
          bodyA: d,
          bodyB: e,
          anchor: { x: x - 0.25, y: -1.5 },
          linearHertz: k === 0 ? 0 : 4.5,
          angularHertz: k === 2 ? 0 : 5.5,
          dampingRatio: 0.4375,
        }),
      ),
      world.addJoint(
        mouseJoint({
          body: c,
          target: { x: x + 2.5, y: -1.5 },
          maxForce: 60,
          hertz: 7.5,
          dampingRatio: 0.5625,
        }),
      ),
    );
  }
  return { world, joints };
}

/** The bodies' states and every joint's saved numbers (settings and impulses). */
function state(world: World, joints: readonly Joint[]): { bodies: Float64Array; joints: string } {
  return {
    bodies: bodyStates(world.bodies),
    joints: JSON.stringify(joints.map((j) => [exportJointState(j), j.reactionForce])),
  };
}

describe('the two builds of the joint passes', () => {
  it('solve a world of every kind, with springs, motors and limits, to the same bits', () => {
    const wasm = everyKind('auto');
    const js = everyKind('javascript');
    for (let i = 0; i < 180; i++) {
      wasm.world.step(DT);
      js.world.step(DT);
    }
    const a = state(wasm.world, wasm.joints);
    const b = state(js.world, js.joints);
    expect(differingBits(a.bodies, b.bodies)).toBe(0);
    expect(b.joints).toBe(a.joints);
    // The joints acted: motors turned, limits and springs pushed.
    expect(wasm.joints.every((j) => j.reactionForce.x !== 0 || j.reactionForce.y !== 0)).toBe(true);
  });

  const jointed = scenes.filter((scene) => scene.build(sceneValues(scene)).joints.length > 0);

  it('finds the samples with joints', () => {
    expect(jointed.map((scene) => scene.id)).toEqual(
      expect.arrayContaining(['bridge', 'car', 'ragdoll', 'newtons-cradle', 'drag-and-throw']),
    );
  });

  for (const scene of jointed) {
    it(`${scene.id}: the same state hash with WebAssembly and with JavaScript only`, () => {
      const values = sceneValues(scene);
      kernelSettings.minConstraints = 0;
      const wasm = runScene(scene, values);
      kernelSettings.minConstraints = Infinity;
      const js = runScene(scene, values);
      expect(hashWorld(js)).toBe(hashWorld(wasm));
    });
  }
});
