import { describe, expect, it } from 'vitest';
import { CanvasSettingError } from '../../src/element/attribute-parsers.ts';
import { CanvasSettings, SETTING_DEFAULTS } from '../../src/element/canvas-settings.ts';

describe('canvas settings', () => {
  it('parse attribute text and go back to the default when the attribute is removed', () => {
    const settings = new CanvasSettings();
    settings.apply('pixels-per-meter', '40');
    settings.apply('origin', '1 -2');
    settings.apply('debug', 'contacts velocities');
    settings.apply('paused', '');
    expect(settings.pixelsPerMeter).toBe(40);
    expect(settings.origin).toEqual({ x: 1, y: -2 });
    expect(settings.debug.contacts && settings.debug.velocities && !settings.debug.aabbs).toBe(
      true,
    );
    expect(settings.paused).toBe(true);
    settings.apply('pixels-per-meter', null);
    settings.apply('paused', null);
    expect(settings.pixelsPerMeter).toBe(SETTING_DEFAULTS.pixelsPerMeter);
    expect(settings.paused).toBe(false);
  });

  it('keep the last good value when a value is rejected', () => {
    const settings = new CanvasSettings();
    settings.apply('max-steps-per-frame', '6');
    expect(() => settings.apply('max-steps-per-frame', '2.5')).toThrow(CanvasSettingError);
    expect(() => settings.apply('background', ' ')).toThrow(/background: expected a CSS colour/);
    expect(settings.maxStepsPerFrame).toBe(6);
  });

  it('cap the pixel ratio only when max-pixel-ratio is set, to a positive number', () => {
    const settings = new CanvasSettings();
    expect(settings.maxPixelRatio).toBe(Infinity);
    settings.apply('max-pixel-ratio', '1.5');
    expect(settings.maxPixelRatio).toBe(1.5);
    expect(() => settings.apply('max-pixel-ratio', '0')).toThrow(CanvasSettingError);
    expect(() => settings.apply('max-pixel-ratio', 'sharp')).toThrow(/max-pixel-ratio/);
    expect(settings.maxPixelRatio).toBe(1.5);
    settings.apply('max-pixel-ratio', null);
    expect(settings.maxPixelRatio).toBe(Infinity);
  });
});
