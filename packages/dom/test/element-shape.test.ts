import { describe, expect, it } from 'vitest';
import { Body } from '@physical/engine';
import { cornerRadius, parseCornerRadius, shapeForBox } from '../src/element-shape.ts';

const material = { density: 1, friction: 0.5, restitution: 0.2 };

describe('parseCornerRadius', () => {
  it('reads px, percentages of each axis, and elliptical pairs (the smaller)', () => {
    expect(parseCornerRadius('12px', 100, 40)).toBe(12);
    expect(parseCornerRadius('50%', 100, 40)).toBe(20); // 50 % of 100 wide, 50 % of 40 high
    expect(parseCornerRadius('10px 6px', 100, 40)).toBe(6);
    expect(parseCornerRadius('0px', 100, 40)).toBe(0);
    expect(parseCornerRadius('', 100, 40)).toBe(0);
  });

  it('clamps the smallest corner to half the smaller side, as CSS does', () => {
    expect(cornerRadius([999, 999, 999, 999], 100, 40)).toBe(20);
    expect(cornerRadius([4, 12, 12, 12], 100, 40)).toBe(4);
    expect(cornerRadius([], 100, 40)).toBe(0);
  });
});

describe('shapeForBox', () => {
  it('makes a round element a circle of its radius (m)', () => {
    expect(shapeForBox({ width: 50, height: 50, radius: 25 }, 100, material)).toEqual({
      type: 'circle',
      radius: 0.25,
      ...material,
    });
  });

  it('makes a rounded rectangle a rounded box whose outline is the element box', () => {
    const shape = shapeForBox({ width: 120, height: 40, radius: 8 }, 100, material);
    expect(shape).toEqual({ type: 'box', width: 1.04, height: 0.24, radius: 0.08, ...material });
    // The body's bounds are exactly the element's box: 1.2 m x 0.4 m around its centre.
    const body = new Body({ position: { x: 2, y: 1 }, shapes: [shape] });
    const bounds = body.shapes[0]!.getBounds();
    expect(bounds.minX).toBeCloseTo(1.4, 12);
    expect(bounds.maxX).toBeCloseTo(2.6, 12);
    expect(bounds.minY).toBeCloseTo(0.8, 12);
    expect(bounds.maxY).toBeCloseTo(1.2, 12);
    // Centre of mass at the box's centre: the CSS transform turns the element about it.
    expect(body.centerOfMass.x).toBeCloseTo(2, 12);
    expect(body.centerOfMass.y).toBeCloseTo(1, 12);
  });

  it('makes a pill a capsule along its long side, with the outline of the pill', () => {
    const wide = shapeForBox({ width: 100, height: 30, radius: 15 }, 100, material);
    expect(wide).toEqual({
      type: 'capsule',
      center1: { x: -0.35, y: 0 },
      center2: { x: 0.35, y: 0 },
      radius: 0.15,
      ...material,
    });
    const tall = shapeForBox({ width: 30, height: 100, radius: 999 }, 100, material);
    expect(tall).toMatchObject({ center1: { x: 0, y: -0.35 }, center2: { x: 0, y: 0.35 } });
    const body = new Body({ position: { x: 1, y: 1 }, shapes: [wide] });
    const bounds = body.shapes[0]!.getBounds();
    expect([bounds.minX, bounds.maxX, bounds.minY, bounds.maxY]).toEqual([
      expect.closeTo(0.5, 12),
      expect.closeTo(1.5, 12),
      expect.closeTo(0.85, 12),
      expect.closeTo(1.15, 12),
    ]);
  });

  it('makes an almost round pill a circle: capsule ends must be 5 mm apart', () => {
    expect(shapeForBox({ width: 30.4, height: 30, radius: 15 }, 100, material)).toMatchObject({
      type: 'circle',
    });
  });

  it('keeps sharp corners sharp and a square that is not round a box', () => {
    expect(shapeForBox({ width: 40, height: 40, radius: 0 }, 50, material)).toEqual({
      type: 'box',
      width: 0.8,
      height: 0.8,
      radius: 0,
      ...material,
    });
  });
});
