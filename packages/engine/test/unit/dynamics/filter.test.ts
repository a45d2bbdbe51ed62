import { describe, expect, it } from 'vitest';
import { filtersCollide, resolveFilter } from '../../../src/dynamics/filter.ts';

function f(category: number, mask: number, group = 0) {
  return { categoryBits: category, maskBits: mask, groupIndex: group };
}

describe('filtersCollide', () => {
  it('needs each category in the other mask', () => {
    expect(filtersCollide(f(1, 0xffffffff), f(1, 0xffffffff))).toBe(true);
    expect(filtersCollide(f(2, 0xffffffff), f(1, 1))).toBe(false);
    expect(filtersCollide(f(1, 1), f(2, 0xffffffff))).toBe(false);
    expect(filtersCollide(f(0x80000000, 0x80000000), f(0x80000000, 0x80000000))).toBe(true);
  });

  it('lets a shared group override the bits: positive collides, negative never', () => {
    expect(filtersCollide(f(2, 0, 5), f(4, 0, 5))).toBe(true);
    expect(filtersCollide(f(1, 0xffffffff, -5), f(1, 0xffffffff, -5))).toBe(false);
    expect(filtersCollide(f(1, 0xffffffff, -5), f(1, 0xffffffff, -6))).toBe(true);
    expect(filtersCollide(f(1, 0xffffffff, 0), f(1, 0xffffffff, 0))).toBe(true);
  });
});

describe('resolveFilter', () => {
  it('fills Box2D defaults', () => {
    expect(resolveFilter('filter', undefined)).toEqual({ category: 1, mask: 0xffffffff, group: 0 });
    expect(resolveFilter('filter', { group: -3 })).toEqual({
      category: 1,
      mask: 0xffffffff,
      group: -3,
    });
  });

  it('names the bad field', () => {
    expect(() => resolveFilter('f', { category: 0.5 })).toThrow(/f\.category/);
    expect(() => resolveFilter('f', { mask: -1 })).toThrow(/f\.mask/);
    expect(() => resolveFilter('f', { group: 2 ** 31 })).toThrow(/f\.group/);
    expect(() => resolveFilter('f', 3 as never)).toThrow(/^f: /);
  });
});
