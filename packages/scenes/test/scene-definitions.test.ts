import { describe, expect, it } from 'vitest';
import { readdirSync } from 'node:fs';
import { sceneValues, scenes } from '@physical/scenes';

describe('scene definitions', () => {
  it('lists every module in src/samples, each under its file name', () => {
    const files = readdirSync(new URL('../src/samples/', import.meta.url))
      .filter((name) => name.endsWith('.ts'))
      .map((name) => name.slice(0, -3))
      .sort();
    expect(scenes.map((scene) => scene.id).sort()).toEqual(files);
  });

  for (const scene of scenes) {
    it(`${scene.id}: parameters have defaults inside their ranges, on their step grid`, () => {
      for (const p of scene.parameters) {
        expect(p.min).toBeLessThan(p.max);
        expect(p.default).toBeGreaterThanOrEqual(p.min);
        expect(p.default).toBeLessThanOrEqual(p.max);
        const steps = (p.default - p.min) / p.step;
        expect(Math.abs(steps - Math.round(steps))).toBeLessThan(1e-9);
      }
      expect(scene.steps).toBeGreaterThan(0);
      expect(scene.camera.width).toBeGreaterThan(0);
    });

    it(`${scene.id}: builds at the extremes of every parameter without error`, () => {
      for (const p of scene.parameters) {
        for (const value of [p.min, p.max]) {
          const world = scene.build(sceneValues(scene, { [p.name]: value }));
          for (let i = 0; i < 10; i++) world.step(1 / 60);
          for (const body of world.bodies) expect(Number.isFinite(body.position.x)).toBe(true);
        }
      }
    });
  }

  it('sceneValues fills defaults and clamps to the range', () => {
    const stack = scenes.find((scene) => scene.id === 'vertical-stack')!;
    expect(sceneValues(stack, { count: 1000 })['count']).toBe(20);
    expect(sceneValues(stack)['friction']).toBe(0.6);
  });
});
