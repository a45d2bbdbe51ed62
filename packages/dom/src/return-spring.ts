/**
 * One step of a critically damped spring, in closed form: the error e (distance from rest) and
 * its rate v obey e'' + 2 w e' + w^2 e = 0, whose solution is
 * e(t) = (e0 + (v0 + w e0) t) exp(-w t) (any ODE text, e.g. Kreyszig, Advanced Engineering
 * Mathematics, 2.4). Exact for any step, so it never overshoots from rest and is stable at any
 * frequency. Writes the new error and rate into `out` [error, rate] and returns it.
 */
export function springStep(
  error: number,
  rate: number,
  omega: number,
  dt: number,
  out: [number, number],
): [number, number] {
  const decay = Math.exp(-omega * dt);
  const b = rate + omega * error;
  out[0] = (error + b * dt) * decay;
  out[1] = (rate - omega * b * dt) * decay;
  return out;
}
