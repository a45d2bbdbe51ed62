/**
 * Rounds a length (CSS px) to the device pixel grid: `step` is one device pixel in the element's
 * own CSS px (1 / (devicePixelRatio * zoom)), so text at rest lands on whole device pixels and
 * stays sharp.
 */
export function snap(value: number, step: number): number {
  return Math.round(value / step) * step;
}

/**
 * The CSS transform that moves an element from its layout slot to its body's pose: a
 * translation of its centre by (dx, dy) CSS px and a turn by `angle` rad about its centre (the
 * element's transform-origin is set to its centre, which is also the body's centre of mass).
 * Angles below a thousandth of a degree are left out, so a resting element is only translated.
 */
export function formatTransform(dx: number, dy: number, angle: number): string {
  const x = round3(dx);
  const y = round3(dy);
  if (Math.abs(angle) < 2e-5) return `translate(${x}px, ${y}px)`;
  return `translate(${x}px, ${y}px) rotate(${round5(angle)}rad)`;
}

function round3(value: number): number {
  const rounded = Math.round(value * 1000) / 1000;
  return rounded === 0 ? 0 : rounded; // never "-0px"
}

function round5(value: number): number {
  return Math.round(value * 100000) / 100000;
}
