import { describe, expect, it } from 'vitest';
import { World, particle } from '@physical/engine';
import { ParticleColumns } from '../src/screens/reactions/particle-columns.ts';
import { MeasurementLog } from '../src/lab/measurement-log.ts';

describe('the Reactions log row of every particle', () => {
  const world = new World({ gravity: { x: 0, y: 0 } });
  const a = world.add(particle({ position: { x: 1, y: 2 }, radius: 0.2 }));
  const b = world.add(particle({ position: { x: -1, y: 0.5 }, radius: 0.1 }));
  a.linearVelocity = { x: 3, y: -4 };
  b.linearVelocity = { x: -2, y: 0 };
  const particles = new Map([
    [a, { label: 'A' }],
    [b, { label: 'B' }],
  ]);

  it('holds x, y, v, p = m v and KE = m v^2 / 2 of each particle, named after it', () => {
    const row = new ParticleColumns().fill(particles);
    expect(row.map((cell) => `${cell.name} (${cell.unit})`)).toEqual([
      'A x (m)',
      'A y (m)',
      'A vx (m/s)',
      'A vy (m/s)',
      'A px (kg m/s)',
      'A py (kg m/s)',
      'A KE (J)',
      'B x (m)',
      'B y (m)',
      'B vx (m/s)',
      'B vy (m/s)',
      'B px (kg m/s)',
      'B py (kg m/s)',
      'B KE (J)',
    ]);
    const values = row.map((cell) => cell.value);
    // A at (3, -4) m/s: |v|^2 = 25; B at (-2, 0) m/s: |v|^2 = 4.
    const [ma, mb] = [a.mass, b.mass];
    const expected = [1, 2, 3, -4, 3 * ma, -4 * ma, 12.5 * ma, -1, 0.5, -2, 0, -2 * mb, 0, 2 * mb];
    values.forEach((value, i) => expect(value).toBeCloseTo(expected[i]!, 12));
  });

  it("makes no new cells from one step to the next, and the log keeps each step's values", () => {
    const columns = new ParticleColumns();
    const log = new MeasurementLog();
    const first = [...columns.fill(particles)];
    log.add(0, first);
    a.linearVelocity = { x: 1, y: 0 };
    const second = columns.fill(particles);
    log.add(1 / 60, second);
    second.forEach((cell, i) => expect(cell).toBe(first[i]));
    const lines = log.toCsv().trim().split(/\r?\n/);
    expect(lines[1]!.split(',')[3]).toBe('3');
    expect(lines[2]!.split(',')[3]).toBe('1');
  });
});
