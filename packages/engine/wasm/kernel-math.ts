// The engine's deterministic math as the kernel computes it: src/math/trigonometry.ts and
// hypot.ts, compiled into the module as they are (one source; see their headers). Exported for the
// tests that compare both builds of the kernel with TypeScript bit for bit
// (test/unit/math/kernel-math.test.ts); the passes import the functions themselves.
// AssemblyScript has no `import type`, and DoublesAt is only a type here (pointers cast to it).
// eslint-disable-next-line @typescript-eslint/consistent-type-imports
import { DoublesAt } from './doubles-at';
import { cosSin as turn } from '../src/math/trigonometry';
export { hypot } from '../src/math/hypot';

/** cos(angle) at byte `out` of the memory, sin(angle) 8 bytes on. */
export function cosSin(angle: f64, out: usize): void {
  turn<DoublesAt>(angle, changetype<DoublesAt>(out));
}
