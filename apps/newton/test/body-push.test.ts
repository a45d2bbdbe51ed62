import { describe, expect, it } from 'vitest';
import {
  KEY_PUSH,
  PUSH_PER_METRE,
  PUSH_REACH,
  pushFromDrag,
  pushFromKeys,
  startsPush,
} from '../src/screens/inertia/body-push.ts';
import { MAX_FORCE } from '../src/screens/inertia/inertia-scene.ts';

describe('push by hand', () => {
  it('pushes the way the finger moved, PUSH_PER_METRE newtons per metre', () => {
    const push = pushFromDrag({ x: 3, y: 4 }, { x: 3.6, y: 3.2 });
    expect(push.x).toBeCloseTo(0.6 * PUSH_PER_METRE, 12);
    expect(push.y).toBeCloseTo(-0.8 * PUSH_PER_METRE, 12);
    expect(pushFromDrag({ x: 1, y: 1 }, { x: 1, y: 1 })).toEqual({ x: 0, y: 0 });
  });

  it('stops growing at the largest force, in the same direction', () => {
    const push = pushFromDrag({ x: 0, y: 0 }, { x: 30, y: 40 });
    expect(Math.hypot(push.x, push.y)).toBeCloseTo(MAX_FORCE, 12);
    expect(push.y / push.x).toBeCloseTo(4 / 3, 12);
  });

  it('starts on a press on the body or a finger width around it, not elsewhere', () => {
    expect(startsPush({ x: 2, y: 2 }, { x: 2.1, y: 2.2 })).toBe(true);
    expect(startsPush({ x: 2, y: 2 }, { x: 2 + PUSH_REACH * 0.99, y: 2 })).toBe(true);
    expect(startsPush({ x: 2, y: 2 }, { x: 2 + PUSH_REACH * 1.01, y: 2 })).toBe(false);
  });

  it('pushes KEY_PUSH newtons along the held arrow keys, none for none or opposite keys', () => {
    expect(pushFromKeys(new Set(['ArrowUp']))).toEqual({ x: 0, y: -KEY_PUSH });
    const diagonal = pushFromKeys(new Set(['ArrowRight', 'ArrowDown']));
    expect(Math.hypot(diagonal.x, diagonal.y)).toBeCloseTo(KEY_PUSH, 12);
    expect(diagonal.x).toBeCloseTo(diagonal.y, 12);
    expect(pushFromKeys(new Set(['ArrowLeft', 'ArrowRight']))).toEqual({ x: 0, y: 0 });
    expect(pushFromKeys(new Set())).toEqual({ x: 0, y: 0 });
    expect(pushFromKeys(new Set(['Enter']))).toEqual({ x: 0, y: 0 });
  });
});
