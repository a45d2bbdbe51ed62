import { describe, expect, it } from 'vitest';
import {
  MIN_PIXEL_RATIO,
  PixelRatioGovernor,
  SLOW_FRAME_RATE,
  SAMPLE_MS,
  SLOW_SAMPLES,
} from '../src/app/pixel-ratio-governor.ts';
import { CANVAS_PIXEL_RATIO } from '../src/app/theme.ts';

describe('the simulation canvas draws fewer pixels when it runs too slowly', () => {
  it('starts at the canvas pixel ratio and keeps it at 60 frames a second', () => {
    const governor = new PixelRatioGovernor();
    expect(governor.ratio).toBe(CANVAS_PIXEL_RATIO);
    for (let i = 0; i < 10; i++) expect(governor.sample(60, 1000, true)).toBe(CANVAS_PIXEL_RATIO);
  });

  it(`drops to one device px per CSS px after ${SLOW_SAMPLES} slow looks in a row`, () => {
    const governor = new PixelRatioGovernor();
    const slowFrames = SLOW_FRAME_RATE - 5;
    for (let i = 1; i < SLOW_SAMPLES; i++) {
      expect(governor.sample((slowFrames * SAMPLE_MS) / 1000, SAMPLE_MS, true)).toBe(
        CANVAS_PIXEL_RATIO,
      );
    }
    expect(governor.sample((slowFrames * SAMPLE_MS) / 1000, SAMPLE_MS, true)).toBe(MIN_PIXEL_RATIO);
    // And stays there when fast again.
    expect(governor.sample(60, 1000, true)).toBe(MIN_PIXEL_RATIO);
  });

  it('ignores a single slow second, and seconds at rest or hidden', () => {
    const governor = new PixelRatioGovernor();
    for (let i = 0; i < 6; i++) {
      governor.sample(10, 1000, true);
      governor.sample(60, 1000, true);
      // At rest: no frames, and not slow.
      governor.sample(0, 1000, false);
    }
    expect(governor.ratio).toBe(CANVAS_PIXEL_RATIO);
  });

  it(`decides within ${(SLOW_SAMPLES * SAMPLE_MS) / 1000} s, and a hiccup of fewer looks does not count`, () => {
    expect(SLOW_SAMPLES * SAMPLE_MS).toBeLessThanOrEqual(1000);
    const governor = new PixelRatioGovernor();
    const slow = ((SLOW_FRAME_RATE - 15) * SAMPLE_MS) / 1000;
    const fast = (60 * SAMPLE_MS) / 1000;
    for (let i = 0; i < 8; i++) {
      for (let k = 1; k < SLOW_SAMPLES; k++) governor.sample(slow, SAMPLE_MS, true);
      governor.sample(fast, SAMPLE_MS, true);
    }
    expect(governor.ratio).toBe(CANVAS_PIXEL_RATIO);
  });

  it('measures the rate over the time that passed (a late timer is not a slow canvas)', () => {
    const governor = new PixelRatioGovernor();
    // 90 frames in 1.5 s is 60 frames a second.
    for (let i = 0; i < 5; i++) governor.sample(90, 1500, true);
    expect(governor.ratio).toBe(CANVAS_PIXEL_RATIO);
  });
});
