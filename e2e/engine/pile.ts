// A pile of 160 boxes and particles in a bin, stepped 240 times, for kernel.spec.ts: enough
// contacts that the world moves to the WebAssembly contact kernel where the page allows it.
// `?kernel=javascript` creates the world with that option. The page counts the
// Content-Security-Policy violations it reports.
import { World, box, particle, wall } from '@physical/engine';

/** What the page leaves for the spec. */
export interface PileResult {
  /** Whether the world ran its contact passes as WebAssembly (an internal the spec checks). */
  kernel: boolean;
  /** Every body's x, y, angle and velocities, as bit patterns in hex. */
  bits: string;
  /** Lowest and highest body y (m): the pile settled in the bin. */
  minY: number;
  maxY: number;
  /** The `securitypolicyviolation` events the page received, by violated directive. */
  violations: string[];
}

declare global {
  interface Window {
    pileResult?: PileResult;
  }
}

const violations: string[] = [];
document.addEventListener('securitypolicyviolation', (event) => {
  violations.push(event.effectiveDirective);
});
const kernel =
  new URLSearchParams(location.search).get('kernel') === 'javascript' ? 'javascript' : 'auto';
const world = new World({ gravity: { x: 0, y: 9.81 }, kernel });
world.add(wall({ from: { x: -6, y: 0 }, to: { x: 6, y: 0 } }));
world.add(wall({ from: { x: -6, y: 0 }, to: { x: -6, y: -30 } }));
world.add(wall({ from: { x: 6, y: 0 }, to: { x: 6, y: -30 } }));
const bodies = [];
for (let i = 0; i < 160; i++) {
  const position = { x: -5 + (i % 20) * 0.5, y: -1 - Math.floor(i / 20) * 0.6 };
  bodies.push(
    world.add(
      i % 4 === 0
        ? particle({ position, radius: 0.2, restitution: 0.3 })
        : box({ position, angle: 0.05 * (i % 7), width: 0.4, height: 0.35, friction: 0.6 }),
    ),
  );
}
for (let i = 0; i < 240; i++) world.step(1 / 60);

const numbers = new Float64Array(bodies.length * 6);
bodies.forEach((b, i) => {
  numbers.set(
    [
      b.position.x,
      b.position.y,
      b.angle,
      b.linearVelocity.x,
      b.linearVelocity.y,
      b.angularVelocity,
    ],
    6 * i,
  );
});
const words = new Uint32Array(numbers.buffer);
let bits = '';
for (const word of words) bits += word.toString(16).padStart(8, '0');
const ys = bodies.map((b) => b.position.y);
const solver = (world as unknown as { solver: { memory: { usesWebAssembly: boolean } } }).solver;
// The browser reports a violation in a task of its own: give it time to arrive.
setTimeout(() => {
  window.pileResult = {
    kernel: solver.memory.usesWebAssembly,
    bits,
    minY: Math.min(...ys),
    maxY: Math.max(...ys),
    violations,
  };
  document.documentElement.dataset['ready'] = 'true';
}, 300);
