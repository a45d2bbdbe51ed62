// One source for TypeScript and the kernel: AssemblyScript compiles this very file into the
// kernel's module (scripts/contact-kernel-build.ts), so it keeps to what both languages mean alike
// (`number` is AssemblyScript's f64; Math.sqrt and abs are f64.sqrt and abs; no imports).

// x^2 + y^2 below this has lost bits to underflow (2^-969: squares under 2^-1022 are
// subnormal, 53 bits below is where that shows); above it, sqrt(x^2 + y^2) is as good as it gets.
const TINY = 2.004168360008973e-292;
// Exact scalings by powers of two for the rare vectors outside that range.
const UP = 4.149515568880993e180; // 2^600
const DOWN = 2.409919865102884e-181; // 2^-600

/**
 * The length of the vector (x, y): sqrt(x^2 + y^2), from operations IEEE 754 rounds the same way
 * in every JavaScript engine (Math.hypot is not: V8 and QuickJS disagree on a third of
 * arguments). Within 2 ulp of the exact length. A vector so short that its squares underflow,
 * or so long that they overflow, is first scaled by a power of two (exact), so such lengths are
 * right too (a distance joint between bodies 1e-323 m apart has that length, not 0).
 */
export function hypot(x: number, y: number): number {
  const sum = x * x + y * y;
  if (sum >= TINY && sum < Infinity) return Math.sqrt(sum);
  return scaledHypot(x, y, sum);
}

/** hypot for the rare sums out of range, zero and NaN. */
function scaledHypot(x: number, y: number, sum: number): number {
  if (sum !== sum) return Math.abs(x) === Infinity || Math.abs(y) === Infinity ? Infinity : NaN;
  if (sum < TINY) {
    const a = x * UP;
    const b = y * UP;
    return Math.sqrt(a * a + b * b) * DOWN;
  }
  if (Math.abs(x) === Infinity || Math.abs(y) === Infinity) return Infinity;
  const a = x * DOWN;
  const b = y * DOWN;
  return Math.sqrt(a * a + b * b) * UP;
}
