import { describe, expect, it } from 'vitest';
import {
  computeViewport,
  screenToWorld,
  worldToScreen,
  type ViewportInput,
} from '../../src/index.ts';

const base: ViewportInput = {
  width: 400,
  height: 300,
  devicePixelRatio: 2,
  fit: 'none',
  pixelsPerMeter: 40,
  origin: { x: 1, y: 2 },
  viewBox: null,
};

describe('computeViewport', () => {
  it('fit none: the origin at the top-left corner, pixelsPerMeter as the scale, at any size', () => {
    for (const [width, height] of [
      [400, 300],
      [1000, 50],
    ] as const) {
      const viewport = computeViewport({ ...base, width, height });
      expect(viewport).toMatchObject({ scale: 40, originX: 1, originY: 2, width, height });
    }
  });

  it('contain: the view box whole and centred', () => {
    const viewBox = { x: 0, y: 0, width: 10, height: 5 };
    const viewport = computeViewport({ ...base, fit: 'contain', viewBox, width: 900, height: 300 });
    expect(viewport.scale).toBe(60);
    expect(worldToScreen(viewport, { x: 5, y: 2.5 })).toEqual({ x: 450, y: 150 });
    expect(worldToScreen(viewport, { x: 0, y: 0 })).toEqual({ x: 150, y: 0 });
  });

  it('cover: the view box fills the element, cropped on one axis', () => {
    const viewBox = { x: 0, y: 0, width: 10, height: 5 };
    const viewport = computeViewport({ ...base, fit: 'cover', viewBox, width: 900, height: 300 });
    expect(viewport.scale).toBe(90);
    expect(worldToScreen(viewport, { x: 5, y: 2.5 })).toEqual({ x: 450, y: 150 });
  });

  it('falls back to fit none without a view box', () => {
    expect(computeViewport({ ...base, fit: 'contain' }).scale).toBe(40);
  });
});

describe('screenToWorld and worldToScreen', () => {
  it('are inverse and y-down', () => {
    const viewport = computeViewport(base);
    expect(screenToWorld(viewport, { x: 80, y: 40 })).toEqual({ x: 3, y: 3 });
    expect(worldToScreen(viewport, { x: 3, y: 3 })).toEqual({ x: 80, y: 40 });
    for (const point of [
      { x: 0.125, y: -7.5 },
      { x: 123.25, y: 4.75 },
    ]) {
      expect(screenToWorld(viewport, worldToScreen(viewport, point))).toEqual(point);
    }
  });
});
