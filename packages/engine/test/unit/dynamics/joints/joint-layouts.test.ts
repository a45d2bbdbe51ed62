import { describe, expect, it } from 'vitest';
import {
  World,
  box,
  particle,
  distanceJoint,
  mouseJoint,
  prismaticJoint,
  revoluteJoint,
  weldJoint,
  type Joint,
} from '@physical/engine';
import { JOINT_HEAD, JOINT_RECORD_STRIDE } from '../../../../src/dynamics/joints/joint-record.ts';
import { exportJointState } from '../../../../src/dynamics/joints/joint-state.ts';
import type { JointLayout } from '../../../../src/dynamics/joints/joint.ts';
import {
  LOCAL_AXIS_X,
  STRIDE as PRISMATIC_STRIDE,
  ANGULAR_IMPULSE as PRISMATIC_LAST,
} from '../../../../src/dynamics/joints/prismatic-joint-solver.ts';
import {
  LINEAR_IMPULSE_X,
  MAX_BIAS_SPEED,
  STRIDE as REVOLUTE_STRIDE,
} from '../../../../src/dynamics/joints/revolute-joint-solver.ts';
import {
  SPRING_ENABLED,
  SPRING_MOTOR_LIMIT_END,
  UPPER_IMPULSE,
} from '../../../../src/dynamics/joints/spring-motor-limit.ts';

// Each joint kind's record is the shared head (joint-record.ts), then, for revolute and
// prismatic, the spring/motor/limit block (spring-motor-limit.ts), then the kind's own numbers.
// The offsets are literals (the passes read literals best), so this checks that each part
// follows on from the one before and that no two numbers share a place: a setting overwritten by
// a step's preparation would change it here.

const layoutOf = (joint: Joint): JointLayout =>
  (joint as unknown as { layout: JointLayout }).layout;

function kinds(): Joint[] {
  const world = new World({ enableSleep: false });
  const ground = world.add(box({ type: 'static', width: 4, height: 0.2 }));
  const a = world.add(particle({ position: { x: 1, y: 1 }, radius: 0.2 }));
  const b = world.add(particle({ position: { x: 2, y: 1 }, radius: 0.2 }));
  const c = world.add(particle({ position: { x: 3, y: 1 }, radius: 0.2 }));
  const d = world.add(particle({ position: { x: -1, y: 1 }, radius: 0.2 }));
  const e = world.add(particle({ position: { x: -2, y: 1 }, radius: 0.2 }));
  const joints: Joint[] = [
    revoluteJoint({
      bodyA: ground,
      bodyB: a,
      anchor: { x: 1, y: 0 },
      enableLimit: true,
      lowerAngle: -0.25,
      upperAngle: 0.5,
      enableMotor: true,
      motorSpeed: 0.75,
      maxMotorTorque: 1.5,
      enableSpring: true,
      hertz: 2.5,
      dampingRatio: 0.125,
    }),
    prismaticJoint({
      bodyA: ground,
      bodyB: b,
      anchor: { x: 2, y: 1 },
      axis: { x: 0, y: 1 },
      enableLimit: true,
      lower: -0.375,
      upper: 0.625,
      enableMotor: true,
      motorSpeed: 0.875,
      maxMotorForce: 3.5,
      enableSpring: true,
      hertz: 1.25,
      dampingRatio: 0.0625,
    }),
    distanceJoint({
      bodyA: ground,
      bodyB: c,
      anchorA: { x: 3, y: 0 },
      anchorB: { x: 3, y: 1 },
      length: 1.125,
      minLength: 0.5,
      maxLength: 1.75,
      enableSpring: true,
      hertz: 3.25,
      dampingRatio: 0.3125,
    }),
    weldJoint({
      bodyA: ground,
      bodyB: d,
      anchor: { x: -1, y: 0.5 },
      linearHertz: 4.5,
      angularHertz: 5.5,
      dampingRatio: 0.4375,
    }),
    mouseJoint({
      body: e,
      target: { x: -2.5, y: 1.5 },
      maxForce: 6.5,
      hertz: 7.5,
      dampingRatio: 0.5625,
    }),
  ];
  for (const joint of joints) world.addJoint(joint);
  return joints;
}

describe('joint record layouts', () => {
  it('follow on: the spring/motor/limit block after the head, each kind after what it shares', () => {
    expect(SPRING_ENABLED).toBe(JOINT_HEAD);
    expect(UPPER_IMPULSE).toBe(SPRING_MOTOR_LIMIT_END - 1);
    expect(LINEAR_IMPULSE_X).toBe(SPRING_MOTOR_LIMIT_END);
    expect(REVOLUTE_STRIDE).toBe(MAX_BIAS_SPEED + 1);
    expect(LOCAL_AXIS_X).toBe(SPRING_MOTOR_LIMIT_END);
    expect(PRISMATIC_STRIDE).toBe(PRISMATIC_LAST + 1);
  });

  it("fit every kind's record in the world store's stride, the largest kind's", () => {
    const strides = kinds().map((joint) => layoutOf(joint).stride);
    for (const stride of strides) expect(stride).toBeLessThanOrEqual(JOINT_RECORD_STRIDE);
    expect(Math.max(...strides)).toBe(JOINT_RECORD_STRIDE);
  });

  it('give every saved number its own place inside the record', () => {
    for (const joint of kinds()) {
      const { stride, saved, impulses } = layoutOf(joint);
      const taken = new Map<number, string>();
      for (const [name, [kind, offset]] of Object.entries(saved)) {
        const size = kind === 'vector' || kind === 'unitVector' ? 2 : 1;
        for (let i = 0; i < size; i++) {
          expect(taken.get(offset + i), `${joint.type}.${name}`).toBeUndefined();
          taken.set(offset + i, name);
          expect(offset + i).toBeLessThan(stride);
        }
      }
      // Every warm-started impulse is saved (a snapshot keeps it).
      for (const offset of impulses)
        expect(taken.has(offset), `${joint.type} ${offset}`).toBe(true);
    }
  });

  it("keep every setting through steps: no step number shares a setting's place", () => {
    const joints = kinds();
    const world = joints[0]!.world!;
    const settings = (joint: Joint): Record<string, unknown> => {
      const state = exportJointState(joint);
      const kept: Record<string, unknown> = {};
      for (const [key, value] of Object.entries(state)) {
        if (/impulse|reaction|subStepDuration/i.test(key)) continue;
        kept[key] = value;
      }
      return kept;
    };
    const before = joints.map(settings);
    for (let i = 0; i < 10; i++) world.step(1 / 60);
    expect(joints.map(settings)).toEqual(before);
  });
});
