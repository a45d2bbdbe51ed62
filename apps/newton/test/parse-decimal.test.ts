import { describe, expect, it } from 'vitest';
import { parseDecimal } from '../src/app/parse-decimal.ts';

describe('parseDecimal', () => {
  it('accepts plain decimals with a point or a comma inside the range', () => {
    expect(parseDecimal('2', 0.5, 5)).toEqual({ ok: true, value: 2 });
    expect(parseDecimal(' 2,5 ', 0.5, 5)).toEqual({ ok: true, value: 2.5 });
    expect(parseDecimal('.5', 0.5, 5)).toEqual({ ok: true, value: 0.5 });
    expect(parseDecimal('5', 0.5, 5)).toEqual({ ok: true, value: 5 });
  });

  it('refuses what is not a plain number instead of reinterpreting it', () => {
    for (const text of ['abc', '-', '0x10', '1e9', '2..5', '1 2', '+2', 'Infinity', '--3']) {
      expect(parseDecimal(text, 0, 5)).toEqual({ ok: false, reason: 'notANumber' });
    }
    expect(parseDecimal('   ', 0, 5)).toEqual({ ok: false, reason: 'empty' });
  });

  it('refuses numbers outside the range instead of clamping them', () => {
    expect(parseDecimal('0', 0.5, 5)).toEqual({ ok: false, reason: 'outOfRange' });
    expect(parseDecimal('9', 0.5, 5)).toEqual({ ok: false, reason: 'outOfRange' });
  });

  it('reads a negative number as a number out of the range, not as "not a number"', () => {
    expect(parseDecimal('-3', 0.5, 5)).toEqual({ ok: false, reason: 'outOfRange' });
    expect(parseDecimal('\u22122,5', 0.5, 5)).toEqual({ ok: false, reason: 'outOfRange' });
    expect(parseDecimal('-0,5', -1, 5)).toEqual({ ok: true, value: -0.5 });
  });
});
