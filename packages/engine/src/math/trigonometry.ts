// The engine's own sine, cosine and arc tangent, built only from + - * / and Math.floor/abs, which
// IEEE 754 makes every JavaScript engine (and WebAssembly) round the same way. Math.sin, cos and
// atan2 are left to each engine's math library, and those differ in the last bit (V8 and QuickJS
// disagree on Math.sin for about 1 % of arguments), so a world stepped in two engines drifted
// apart. Box2D v3 computes its own (b2ComputeCosSin, b2Atan2) for the same reason; it trades
// accuracy for speed, these keep Math.sin's accuracy (within 1 ulp, test/unit/math/trigonometry).
//
// Method: Cody and Waite's argument reduction by multiples of pi/2, with pi/2 split in three
// parts of 33, 33 and 53 bits so each product n * part is exact, and Sun's fdlibm minimax
// polynomials for sine (degree 13) and cosine (degree 14) on [-pi/4, pi/4], with the reduced
// argument's rounding error carried as a second number (K. C. Ng, "Argument reduction for huge
// arguments: good to the last bit", 1992; fdlibm k_sin.c, k_cos.c and e_rem_pio2.c; the cosine's
// exact 1 - z/2 splitting is FreeBSD msun's). The arc tangent is fdlibm's s_atan.c scheme: four
// reduction intervals with atan(1/2), atan(1), atan(3/2) and pi/2 kept in two parts, then an
// odd polynomial of degree 23.
//
// One source for TypeScript and the kernel: AssemblyScript compiles this very file into the
// kernel's module (scripts/contact-kernel-build.ts; wasm/body-passes.ts turns each body with
// cosSin), so it keeps to what both languages mean alike: `number` (AssemblyScript's f64), + - * /,
// comparisons, Math.floor, abs and sqrt (f64.floor, abs, sqrt), no allocation, no imports. The
// pair cosSin writes is generic (`Out`): a Float64Array here; in the kernel, the two doubles at an
// address of its memory (`DoublesAt`, wasm/doubles-at.ts), so it writes a body's c and s in place.

// pi/2 = PIO2_1 + PIO2_1T = PIO2_1 + PIO2_2 + PIO2_2T = PIO2_1 + PIO2_2 + PIO2_3 + PIO2_3T.
const PIO2_1 = 1.57079632673412561417; // first 33 bits of pi/2
const PIO2_1T = 6.07710050650619224932e-11; // pi/2 - PIO2_1
const PIO2_2 = 6.0771005063039659766e-11; // second 33 bits
const PIO2_2T = 2.02226624879595063154e-21; // pi/2 - (PIO2_1 + PIO2_2)
const PIO2_3 = 2.0222662487111664558e-21; // third 33 bits
const PIO2_3T = 8.47842766036889956997e-32; // pi/2 - (PIO2_1 + PIO2_2 + PIO2_3)
const INV_PIO2 = 6.36619772367581382433e-1; // 2/pi
const PIO4 = 7.85398163397448278999e-1; // pi/4 rounded down: no reduction at or below it
// Below this n = round(x 2/pi) < 2^20, so n * PIO2_k (33 bits each) is exact.
const MEDIUM = 1647099.3291652855; // 2^20 pi/2
// 2 pi rounded to a double, for the exact remainder of a huge angle.
const TAU = 6.283185307179586;

// Sine: sin(x) ~ x + S1 x^3 + ... + S6 x^13 on [-pi/4, pi/4] (fdlibm, error below 2^-58).
const S1 = -1.66666666666666324348e-1;
const S2 = 8.33333333332248946124e-3;
const S3 = -1.98412698298579493134e-4;
const S4 = 2.75573137070700676789e-6;
const S5 = -2.50507602534068634195e-8;
const S6 = 1.58969099521155010221e-10;
// Cosine: cos(x) ~ 1 - x^2/2 + C1 x^4 + ... + C6 x^14 (fdlibm, error below 2^-58).
const C1 = 4.16666666666666019037e-2;
const C2 = -1.38888888888741095749e-3;
const C3 = 2.48015872894767294178e-5;
const C4 = -2.75573143513906633035e-7;
const C5 = 2.0875723212981748279e-9;
const C6 = -1.13596475577881948265e-11;

/**
 * Writes cos(angle) into `out[0]` and sin(angle) into `out[1]` (angle in rad). The same bits in
 * every JavaScript engine and in WebAssembly.
 *
 * Accuracy (test/unit/math/trigonometry.test.ts): within 1 ulp of the exact values for |angle| <
 * 2^20 pi/2 (1.6e6 rad); beyond that the angle is first reduced modulo the double nearest 2 pi,
 * which adds at most half an ulp of the angle itself (below the angle's own precision). The
 * result is a rotation: |c^2 + s^2 - 1| stays within a few ulp of 1. NaN or an infinite angle
 * gives NaN in both. Writes through `out` so that hot loops allocate nothing; `out` is any
 * Float64Array (generic only so the kernel can pass its own pair of doubles, see above).
 */
export function cosSin<Out extends Float64Array>(angle: number, out: Out): void {
  // The angle goes in through out[0], not as an argument: this wrapper is small enough for V8 to
  // inline everywhere, while cosSinInPlace may not be, and V8 boxes (allocates) a fractional
  // argument of a call it does not inline (dynamics/README.md).
  out[0] = angle;
  cosSinInPlace<Out>(out);
}

/** cosSin of the angle in out[0]. */
function cosSinInPlace<Out extends Float64Array>(out: Out): void {
  const angle = out[0]!;
  const x = Math.abs(angle);
  if (!(x <= PIO4)) {
    out[0] = x;
    if (!(x < MEDIUM)) {
      if (!(x < Infinity)) {
        out[0] = NaN;
        out[1] = NaN;
        return;
      }
      remainderTau<Out>(out);
    }
    cosSinReduced<Out>(out);
    if (angle < 0) out[1] = -out[1];
    return;
  }
  // Bodies that never turned: cos 1, sin keeps the sign of the zero (as Math.sin does).
  if (angle === 0) {
    out[0] = 1;
    out[1] = angle;
    return;
  }
  // |angle| <= pi/4: the polynomials directly, no tail; the sine's is odd, so it keeps the
  // sign of angle.
  const z = angle * angle;
  const v = z * angle;
  const r = S2 + z * (S3 + z * (S4 + z * (S5 + z * S6)));
  const cr = z * (C1 + z * (C2 + z * (C3 + z * (C4 + z * (C5 + z * C6)))));
  const hz = 0.5 * z;
  const w = 1 - hz;
  out[0] = w + (1 - w - hz + z * cr);
  out[1] = angle + v * (S1 + z * r);
}

/**
 * cos and sin of x = out[0], 0 <= x < 2^20 pi/2, into out[0] and out[1]: x = n pi/2 + (y0 + y1),
 * then the polynomials at y0 with its tail y1, turned by the quadrant n mod 4.
 */
function cosSinReduced<Out extends Float64Array>(out: Out): void {
  const x = out[0]!;
  // n < 2^20 and each PIO2_k has 33 bits, so n * PIO2_k is exact; x - n PIO2_1 is exact too
  // (Sterbenz: the two are within a factor of 2).
  const n = Math.floor(x * INV_PIO2 + 0.5);
  let r = x - n * PIO2_1;
  let w = n * PIO2_1T;
  let y0 = r - w;
  // Cancellation (x near a multiple of pi/2): the first 86 bits of pi/2 are not enough, take
  // 33 more, and if need be 33 more again (fdlibm's second and third rounds, which it starts
  // when the exponent of y0 is 16 or 49 below that of x).
  if (Math.abs(y0) < x * 3.0517578125e-5) {
    let t = r;
    w = n * PIO2_2;
    r = t - w;
    w = n * PIO2_2T - (t - r - w);
    y0 = r - w;
    if (Math.abs(y0) < x * 3.552713678800501e-15) {
      t = r;
      w = n * PIO2_3;
      r = t - w;
      w = n * PIO2_3T - (t - r - w);
      y0 = r - w;
    }
  }
  const y1 = r - y0 - w;

  // sin(y0 + y1) ~ y0 + y0^3 (S1 + ...) + y1 cos(y0), the tail folded in as fdlibm does.
  const z = y0 * y0;
  const v = z * y0;
  const sr = S2 + z * (S3 + z * (S4 + z * (S5 + z * S6)));
  const sine = y0 - (z * (0.5 * y1 - v * sr) - y1 - v * S1);
  // cos(y0 + y1) ~ cos(y0) - y0 y1; 1 - z/2 is split as w + ((1 - w) - z/2) so no bit is lost.
  const cr = z * (C1 + z * (C2 + z * (C3 + z * (C4 + z * (C5 + z * C6)))));
  const hz = 0.5 * z;
  const cw = 1 - hz;
  const cosine = cw + (1 - cw - hz + (z * cr - y0 * y1));

  const quadrant = n - 4 * Math.floor(n * 0.25);
  if (quadrant === 0) {
    out[0] = cosine;
    out[1] = sine;
  } else if (quadrant === 1) {
    out[0] = -sine;
    out[1] = cosine;
  } else if (quadrant === 2) {
    out[0] = -cosine;
    out[1] = -sine;
  } else {
    out[0] = sine;
    out[1] = -cosine;
  }
}

/**
 * Replaces x = out[0], finite and >= 2^20 pi/2, by x modulo TAU (the double nearest 2 pi),
 * computed exactly: binary long division, each subtraction exact since TAU 2^k <= r <
 * TAU 2^(k+1) (Sterbenz). The difference of TAU from 2 pi makes the result differ from
 * x mod 2 pi by at most |x| 2^-53.
 */
function remainderTau<Out extends Float64Array>(out: Out): void {
  const x = out[0]!;
  let m = TAU;
  while (m <= x * 0.5) m *= 2;
  let r = x;
  while (m >= TAU) {
    if (r >= m) r -= m;
    m *= 0.5;
  }
  out[0] = r;
}

// atan(x) = ATAN_HI[i] + ATAN_LO[i] + atan(reduced) at x = 1/2, 1, 3/2 and infinity.
const ATAN_HI_0 = 4.63647609000806093515e-1;
const ATAN_HI_1 = 7.85398163397448278999e-1;
const ATAN_HI_2 = 9.82793723247329054082e-1;
const ATAN_HI_3 = 1.570796326794896558;
const ATAN_LO_0 = 2.26987774529616870924e-17;
const ATAN_LO_1 = 3.06161699786838301793e-17;
const ATAN_LO_2 = 1.39033110312309984516e-17;
const ATAN_LO_3 = 6.12323399573676603587e-17;
// atan(x) ~ x - x^3 (T0 + T1 x^2 + ... + T10 x^20) for |x| < 7/16 (fdlibm).
const T0 = 3.33333333333329318027e-1;
const T1 = -1.99999999998764832476e-1;
const T2 = 1.42857142725034663711e-1;
const T3 = -1.1111110405462355788e-1;
const T4 = 9.09088713343650656196e-2;
const T5 = -7.69187620504482999495e-2;
const T6 = 6.66107313738753120669e-2;
const T7 = -5.83357013379057348645e-2;
const T8 = 4.97687799461593236017e-2;
const T9 = -3.6531572744216915527e-2;
const T10 = 1.62858201153657823623e-2;
const PI = 3.141592653589793; // pi rounded to a double
const PI_LO = 1.2246467991473532e-16; // pi - PI

/** atan(x) for x >= 0 (within 1 ulp). */
function atanNonNegative(x: number): number {
  if (x >= 7.378697629483821e19) return ATAN_HI_3 + ATAN_LO_3; // 2^66: pi/2 to the last bit
  let t = x;
  let hi = 0;
  let lo = 0;
  let reduced = true;
  if (x < 0.4375) {
    reduced = false;
  } else if (x < 0.6875) {
    t = (2 * x - 1) / (2 + x); // atan(x) = atan(1/2) + atan(t)
    hi = ATAN_HI_0;
    lo = ATAN_LO_0;
  } else if (x < 1.1875) {
    t = (x - 1) / (x + 1); // atan(x) = pi/4 + atan(t)
    hi = ATAN_HI_1;
    lo = ATAN_LO_1;
  } else if (x < 2.4375) {
    t = (x - 1.5) / (1 + 1.5 * x); // atan(x) = atan(3/2) + atan(t)
    hi = ATAN_HI_2;
    lo = ATAN_LO_2;
  } else {
    t = -1 / x; // atan(x) = pi/2 - atan(1/x)
    hi = ATAN_HI_3;
    lo = ATAN_LO_3;
  }
  const z = t * t;
  const w = z * z;
  // Odd and even coefficients apart, two shorter chains (fdlibm's split).
  const s1 = z * (T0 + w * (T2 + w * (T4 + w * (T6 + w * (T8 + w * T10)))));
  const s2 = w * (T1 + w * (T3 + w * (T5 + w * (T7 + w * T9))));
  if (!reduced) return t - t * (s1 + s2);
  return hi - (t * (s1 + s2) - lo - t);
}

/**
 * The angle of the point (x, y) from the positive x axis, in (-pi, pi] (rad), as Math.atan2
 * defines it for finite arguments and signed zeros. Within 2 ulp of the exact value; the same
 * bits in every JavaScript engine.
 */
export function atan2(y: number, x: number): number {
  if (y !== y || x !== x) return NaN;
  const ay = Math.abs(y);
  const ax = Math.abs(x);
  const negativeX = x < 0 || (x === 0 && 1 / x < 0);
  if (ay === 0) {
    // atan2(+-0, +x or +0) = +-0; atan2(+-0, -x or -0) = +-pi.
    if (!negativeX) return y;
    return y === 0 && 1 / y < 0 ? -PI : PI;
  }
  if (ax === 0) return y > 0 ? ATAN_HI_3 : -ATAN_HI_3;
  if (ax === Infinity || ay === Infinity) {
    // Only the infinite cases left: the limits Math.atan2 defines.
    let a: number;
    if (ax === Infinity && ay === Infinity) a = negativeX ? 3 * ATAN_HI_1 : ATAN_HI_1;
    else if (ax === Infinity) a = negativeX ? PI : 0;
    else a = ATAN_HI_3;
    return y < 0 ? -a : a;
  }
  // |y/x| beyond 2^60: +-pi/2 whatever the sign of x; for x < 0, |y/x| below 2^-60: +-pi
  // (fdlibm's guards against the quotient's overflow and underflow).
  if (ay > ax * 1.152921504606846976e18) {
    const z = ATAN_HI_3 + 0.5 * PI_LO;
    return y < 0 ? -z : z;
  }
  let z: number;
  if (negativeX && ay < ax * 8.673617379884035e-19) z = 0;
  else z = atanNonNegative(ay / ax);
  let a: number;
  if (!negativeX) a = z;
  else a = PI - (z - PI_LO);
  return y < 0 ? -a : a;
}
