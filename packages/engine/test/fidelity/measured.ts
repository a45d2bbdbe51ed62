// The fidelity run doubles as the report of how exact the engine is: each law prints what it
// measured beside its tolerance (`npx vitest run packages/engine/test/fidelity`).

/** Prints one measured error of a law, with its tolerance. */
export function reportMeasured(law: string, measured: number, tolerance: number): void {
  // eslint-disable-next-line no-console
  console.log(`[fidelity] ${law}: ${measured.toExponential(2)} (tolerance ${tolerance})`);
}
