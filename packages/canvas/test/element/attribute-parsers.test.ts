import { describe, expect, it } from 'vitest';
import {
  parseDebug,
  parseDrag,
  parsePoint,
  parsePositive,
  parseViewBox,
} from '../../src/element/attribute-parsers.ts';

describe('attribute parsers', () => {
  it('reject negative, zero, NaN and empty pixels-per-meter with a message naming the value', () => {
    for (const value of ['-3', '0', 'NaN', '', 'abc', Number.POSITIVE_INFINITY]) {
      expect(() => parsePositive('pixels-per-meter', value)).toThrow(
        /<physical-canvas> pixels-per-meter: expected a finite number greater than 0, got/,
      );
    }
    expect(parsePositive('pixels-per-meter', ' 42.5 ')).toBe(42.5);
  });

  it('read points and view boxes from attribute text or objects', () => {
    expect(parsePoint('origin', '1.5 -2')).toEqual({ x: 1.5, y: -2 });
    expect(parsePoint('origin', '1.5, -2')).toEqual({ x: 1.5, y: -2 });
    expect(() => parsePoint('origin', '1')).toThrow(/origin/);
    expect(parseViewBox('view-box', '0 0 10 5')).toEqual({ x: 0, y: 0, width: 10, height: 5 });
    expect(parseViewBox('view-box', null)).toBeNull();
    expect(() => parseViewBox('view-box', '0 0 -1 5')).toThrow(/width and height/);
  });

  it('read debug overlays from a list, "all", an array or flags', () => {
    expect(parseDebug('debug', 'contacts normals')).toMatchObject({
      contacts: true,
      normals: true,
      aabbs: false,
    });
    expect(Object.values(parseDebug('debug', 'all')).every(Boolean)).toBe(true);
    expect(parseDebug('debug', ['aabbs']).aabbs).toBe(true);
    expect(parseDebug('debug', { velocities: true }).velocities).toBe(true);
    expect(() => parseDebug('debug', 'sparkles')).toThrow(/overlay names/);
  });

  it('read drag as on unless "off" or "false", and reject anything else by name', () => {
    for (const on of [null, '', 'on', 'TRUE', true]) expect(parseDrag('drag', on)).toBe(true);
    for (const off of ['off', ' Off ', 'false', false]) expect(parseDrag('drag', off)).toBe(false);
    expect(() => parseDrag('drag', 'sometimes')).toThrow(
      /<physical-canvas> drag: expected "on" or "off" \(or true \/ false\), got "sometimes"/,
    );
  });
});
