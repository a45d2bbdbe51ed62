import { describe, expect, it } from 'vitest';
import {
  forcesPreset,
  parsePreset,
  presetFor,
  presetLink,
  presetNumber,
} from '../src/app/presets.ts';
import { screenFromHash } from '../src/app/screens.ts';

describe('preset links', () => {
  it('open the named screen with exactly the values of the link', () => {
    expect(parsePreset('#forces?mA=1&mB=2&F=3')).toEqual({
      screen: 'forces',
      values: { mA: 1, mB: 2, F: 3 },
      problems: [],
    });
    expect(parsePreset('#reactions?mA=0.5&vA=2&vB=-1.5&e=1&walls=0&arrows=force&dt=0.01')).toEqual({
      screen: 'reactions',
      values: { mA: 0.5, vA: 2, vB: -1.5, e: 1, walls: '0', arrows: 'force', dt: '0.01' },
      problems: [],
    });
    expect(parsePreset('#inertia?F=2,5&surface=wood').values).toEqual({ F: 2.5, surface: 'wood' });
  });

  it('leave out, and report, names a screen does not take and values outside their range', () => {
    const preset = parsePreset('#forces?mA=abc&mB=99&speed=3&F=1e3&FA=-1&FB=2');
    expect(preset.values).toEqual({ FB: 2 });
    expect(preset.problems).toEqual([
      'mA=abc: not a number',
      'mB=99: outside 0.5 to 5',
      'speed: not a setting of forces',
      'F=1e3: not a number',
      'FA=-1: outside 0 to 10',
    ]);
    expect(parsePreset('#reactions?walls=yes').problems).toEqual(['walls=yes: one of 0, 1']);
    // Object's own names are not settings.
    expect(parsePreset('#reactions?constructor=1&__proto__=2').values).toEqual({});
  });

  it('name no screen for an unknown hash, and take no values without a query', () => {
    expect(parsePreset('#nowhere?mA=1')).toEqual({ screen: null, values: {}, problems: [] });
    expect(parsePreset('')).toEqual({ screen: null, values: {}, problems: [] });
    expect(parsePreset('#reactions')).toEqual({ screen: 'reactions', values: {}, problems: [] });
  });

  it('apply only to the screen they name; the app opens that screen', () => {
    expect(presetFor('forces', '#forces?F=2')).toEqual({ F: 2 });
    expect(presetFor('inertia', '#forces?F=2')).toEqual({});
    expect(screenFromHash('#forces?mA=1&mB=2&F=3')).toBe('forces');
    expect(screenFromHash('#reactions?vA=1')).toBe('reactions');
    expect(presetNumber({ F: 2 }, 'F', 1)).toBe(2);
    expect(presetNumber({ F: 'x' }, 'F', 1)).toBe(1);
    expect(presetNumber({}, 'F', 1)).toBe(1);
  });

  it('are written back by presetLink into a link that parses to the same values', () => {
    const values = { mA: 1, mB: 2, vA: 1.5, vB: -0.5, e: 0, walls: '0' };
    const link = presetLink('reactions', values);
    expect(link).toBe('#reactions?mA=1&mB=2&vA=1.5&vB=-0.5&e=0&walls=0');
    expect(parsePreset(link).values).toEqual(values);
    expect(presetLink('inertia', {})).toBe('#inertia');
  });

  it('give Forces each square its mass and force (F for both, FA and FB for one)', () => {
    expect(forcesPreset(parsePreset('#forces?mA=1&mB=2&F=3').values)).toEqual({
      masses: [1, 2],
      forces: [3, 3],
    });
    expect(forcesPreset(parsePreset('#forces?F=3&FB=1').values)).toEqual({
      masses: [undefined, undefined],
      forces: [3, 1],
    });
  });
});
