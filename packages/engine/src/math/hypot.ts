/**
 * The length of the vector (x, y): sqrt(x^2 + y^2), from operations IEEE 754 rounds the same way
 * in every JavaScript engine (Math.hypot is not: V8 and QuickJS disagree on a third of
 * arguments). No scaling against overflow: the engine's inputs are bounded (coordinates 1e7 m,
 * sizes 1e5 m, speeds 1e6 m/s, `core/validate.ts`), so the squares stay far from 1e308, and a
 * vector too long or too short to square comes out as Infinity or 0, which every caller refuses
 * or treats as no direction.
 */
export function hypot(x: number, y: number): number {
  return Math.sqrt(x * x + y * y);
}
