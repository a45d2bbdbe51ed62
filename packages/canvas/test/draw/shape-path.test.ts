import { describe, expect, it } from 'vitest';
import { capsule, polygon } from '@physical/engine';
import { appendAreaPath } from '../../src/draw/shape-path.ts';

/** Records the path calls of a canvas context and samples the outline they trace. */
class PathRecorder {
  readonly points: { x: number; y: number }[] = [];
  arcs = 0;
  closed = 0;
  moveTo(x: number, y: number): void {
    this.points.push({ x, y });
  }
  lineTo(x: number, y: number): void {
    this.points.push({ x, y });
  }
  arc(x: number, y: number, r: number, from: number, to: number): void {
    this.arcs++;
    for (let k = 0; k <= 8; k++) {
      const angle = from + ((to - from) * k) / 8;
      this.points.push({ x: x + r * Math.cos(angle), y: y + r * Math.sin(angle) });
    }
  }
  closePath(): void {
    this.closed++;
  }
}

describe('appendAreaPath', () => {
  it('traces a turned capsule: two half circles whose points all lie on its outline', () => {
    const body = capsule({ length: 2, radius: 0.5 });
    const recorder = new PathRecorder();
    const angle = 0.6;
    const pose = { x: 3, y: -1, angle };
    const drawn = appendAreaPath(
      recorder as unknown as CanvasRenderingContext2D,
      body.shapes[0]!.geometry,
      pose,
      Math.cos(angle),
      Math.sin(angle),
    );
    expect(drawn).toBe(true);
    expect(recorder.arcs).toBe(2);
    expect(recorder.closed).toBe(1);
    // Each point is at distance r from the core segment, in world coordinates.
    const ux = Math.cos(angle);
    const uy = Math.sin(angle);
    for (const p of recorder.points) {
      const dx = p.x - 3;
      const dy = p.y + 1;
      const along = Math.max(-1, Math.min(1, dx * ux + dy * uy));
      expect(Math.hypot(dx - along * ux, dy - along * uy)).toBeCloseTo(0.5, 12);
    }
    // Both sides are reached: the half circles turn opposite ways round the ends.
    const across = recorder.points.map((p) => -(p.x - 3) * uy + (p.y + 1) * ux);
    expect(Math.min(...across)).toBeCloseTo(-0.5, 12);
    expect(Math.max(...across)).toBeCloseTo(0.5, 12);
  });

  it('traces each convex part of a concave body', () => {
    const body = polygon({
      vertices: [
        { x: 0, y: 0 },
        { x: 2, y: 0 },
        { x: 2, y: 1 },
        { x: 1, y: 1 },
        { x: 1, y: 2 },
        { x: 0, y: 2 },
      ],
    });
    const recorder = new PathRecorder();
    for (const shape of body.shapes) {
      appendAreaPath(
        recorder as unknown as CanvasRenderingContext2D,
        shape.geometry,
        { x: 0, y: 0, angle: 0 },
        1,
        0,
      );
    }
    expect(recorder.closed).toBe(body.shapes.length);
    expect(recorder.points.length).toBe(6 + 2);
  });
});
