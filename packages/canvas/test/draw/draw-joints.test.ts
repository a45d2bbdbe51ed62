import { describe, expect, it } from 'vitest';
import {
  type Body,
  World,
  box,
  distanceJoint,
  mouseJoint,
  particle,
  revoluteJoint,
} from '@physical/engine';
import { defaultBodyStyle, resolveBodyStyle } from '../../src/draw/body-style.ts';
import { jointAnchors } from '../../src/draw/draw-joints.ts';
import type { Pose } from '../../src/draw/pose.ts';
import type { Scene } from '../../src/draw/scene.ts';
import { noDebugOverlays } from '../../src/draw/debug-overlays.ts';
import { computeViewport } from '../../src/draw/viewport.ts';

/** A scene over `world` whose drawn poses come from `poseOf` (default: the current poses). */
function sceneOf(
  world: World,
  poseOf: (body: Body, out: Pose) => Pose = (body, out) => {
    out.x = body.position.x;
    out.y = body.position.y;
    out.angle = body.angle;
    return out;
  },
  hidden: Body | null = null,
): Scene {
  return {
    viewport: computeViewport({
      width: 100,
      height: 100,
      devicePixelRatio: 1,
      fit: 'none',
      pixelsPerMeter: 50,
      origin: { x: 0, y: 0 },
      viewBox: null,
    }),
    background: '#000',
    world,
    bodies: world.bodies,
    poseOf: (body, _index, out) => poseOf(body, out),
    styleOf: (body) =>
      resolveBodyStyle(body === hidden ? { visible: false } : null, defaultBodyStyle(body, 0)),
    debug: noDebugOverlays(),
    collisionArrows: [],
    forceScale: 0.01,
    velocityScale: 0.25,
    reducedMotion: false,
  };
}

function hingedBar() {
  const world = new World({ enableSleep: false });
  const pin = world.add(box({ type: 'static', width: 0.2, height: 0.2 }));
  const bar = world.add(box({ position: { x: 1, y: 0 }, width: 2, height: 0.1 }));
  world.addJoint(revoluteJoint({ bodyA: pin, bodyB: bar, anchor: { x: 0, y: 0 } }));
  world.addJoint(
    distanceJoint({ bodyA: pin, bodyB: bar, anchorA: { x: 0, y: -1 }, anchorB: { x: 2, y: 0 } }),
  );
  return { world, pin, bar };
}

describe('joint drawing reads world.joints and the drawn poses', () => {
  it('at the current poses, the points are the joints’ own anchors', () => {
    const { world } = hingedBar();
    for (let i = 0; i < 10; i++) world.step(1 / 60);
    const out = new Float64Array(8);
    expect(jointAnchors(sceneOf(world), out)).toBe(2);
    world.joints.forEach((joint, j) => {
      expect(out[4 * j]).toBeCloseTo(joint.anchorA.x, 12);
      expect(out[4 * j + 1]).toBeCloseTo(joint.anchorA.y, 12);
      expect(out[4 * j + 2]).toBeCloseTo(joint.anchorB.x, 12);
      expect(out[4 * j + 3]).toBeCloseTo(joint.anchorB.y, 12);
    });
  });

  it('follows a body drawn elsewhere: shifted 1 m and turned a quarter turn', () => {
    const { world, bar } = hingedBar();
    const out = new Float64Array(8);
    const drawn = sceneOf(world, (body, pose) => {
      pose.x = body.position.x + (body === bar ? 1 : 0);
      pose.y = body.position.y;
      pose.angle = body.angle + (body === bar ? Math.PI / 2 : 0);
      return pose;
    });
    expect(jointAnchors(drawn, out)).toBe(2);
    // The rod's end on the bar is 1 m along +x from its centre (1, 0): turned, along +y from (2, 0).
    expect(out[6]).toBeCloseTo(2, 12);
    expect(out[7]).toBeCloseTo(1, 12);
    // The pin's end does not move.
    expect(out[4]).toBeCloseTo(0, 12);
    expect(out[5]).toBeCloseTo(-1, 12);
  });

  it('draws a mouse joint from the target to the pulled point', () => {
    const world = new World();
    const ball = world.add(particle({ radius: 0.5 }));
    const drag = world.addJoint(mouseJoint({ body: ball, target: { x: 0.2, y: 0 } }));
    drag.target = { x: 3, y: 4 };
    const out = new Float64Array(4);
    expect(jointAnchors(sceneOf(world), out)).toBe(1);
    expect([...out]).toEqual([3, 4, 0.2, 0]);
  });

  it("draws a held point (the canvas's drag) after the joints, from the pointer to the point", () => {
    const { world, bar } = hingedBar();
    // The bar's point 0.5 m right of its centre, drawn shifted 1 m right, pulled to (3, 4).
    const held = [{ body: bar, local: { x: 0.5, y: 0 }, target: { x: 3, y: 4 } }];
    const drawn = sceneOf(world, (body, pose) => {
      pose.x = body.position.x + (body === bar ? 1 : 0);
      pose.y = body.position.y;
      pose.angle = body.angle;
      return pose;
    });
    const out = new Float64Array(12);
    expect(jointAnchors({ ...drawn, held }, out)).toBe(3);
    expect([...out.subarray(8)]).toEqual([3, 4, 2.5, 0]);
    expect(jointAnchors({ ...sceneOf(world, undefined, bar), held }, out)).toBe(0);
  });

  it('leaves out a joint whose body is hidden', () => {
    const { world, bar } = hingedBar();
    expect(jointAnchors(sceneOf(world, undefined, bar), new Float64Array(8))).toBe(0);
  });
});
