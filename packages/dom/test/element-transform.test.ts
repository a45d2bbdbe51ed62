import { describe, expect, it } from 'vitest';
import { formatTransform, snap } from '../src/element-transform.ts';

describe('formatTransform', () => {
  it('translates the centre and turns about it, in CSS px and rad', () => {
    expect(formatTransform(12.5, -3, 0.25)).toBe('translate(12.5px, -3px) rotate(0.25rad)');
  });

  it('leaves out a negligible turn and never writes -0', () => {
    expect(formatTransform(-0.0001, 4, 1e-6)).toBe('translate(0px, 4px)');
  });
});

describe('snap', () => {
  it('rounds to whole device pixels: halves at devicePixelRatio 2, thirds at 3', () => {
    expect(snap(10.3, 1 / 2)).toBe(10.5);
    expect(snap(10.2, 1 / 3)).toBeCloseTo(10 + 1 / 3, 12);
    expect(snap(10.4, 1)).toBe(10);
  });
});
