// A pile of 160 boxes and particles in a bin, and beside it a chain of three links on hinges,
// stepped 240 times, for kernel.spec.ts: the world runs the WebAssembly contact kernel and the
// joints' module where the page allows it, else their JavaScript builds.
// `?kernel=javascript` creates the world with that option; `?entry=none` leaves out the
// JavaScript build's entry (@physical/engine/javascript-kernel), which the page otherwise loads
// first. The page counts the Content-Security-Policy violations it reports.
import { PhysicalError, World, box, particle, revoluteJoint, wall } from '@physical/engine';

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
  /**
   * Whether a one-box world ran WebAssembly on its first step (compiled synchronously on the main
   * thread, from the module's bytes inside the engine).
   */
  smallWorldKernel: boolean;
  /** The message of the PhysicalError `new World()` threw, or null. */
  error: string | null;
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
const search = new URLSearchParams(location.search);
const kernel = search.get('kernel') === 'javascript' ? 'javascript' : 'auto';
if (search.get('entry') !== 'none') await import('@physical/engine/javascript-kernel');
const usesWebAssembly = (of: World): boolean =>
  (of as unknown as { solver: { memory: { usesWebAssembly: boolean } } }).solver.memory
    .usesWebAssembly;
let error: string | null = null;
let world: World;
try {
  world = new World({ gravity: { x: 0, y: 9.81 }, kernel });
} catch (caught) {
  if (!(caught instanceof PhysicalError)) throw caught;
  error = caught.message;
  // What the message says to do: load the JavaScript build, and the same world runs.
  await import('@physical/engine/javascript-kernel');
  world = new World({ gravity: { x: 0, y: 9.81 }, kernel });
}
let smallWorldKernel = false;
if (error === null) {
  const small = new World({ kernel });
  small.add(box({ width: 1, height: 1 }));
  small.step(1 / 60);
  smallWorldKernel = usesWebAssembly(small);
}
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
// The chain, in a world of its own (its links' poses are compared too: the joints' passes, as
// WebAssembly or as the entry's JavaScript), so the pile's numbers do not depend on it. (A hinge
// in the pile's world once let a particle through the floor: the impact rounds' lone-bounce
// check, fixed and tested in packages/engine/test/fidelity/pile-beside-a-joint.test.ts.)
const chainWorld = new World({ gravity: { x: 0, y: 9.81 }, kernel });
let anchor = chainWorld.add(
  box({ type: 'static', position: { x: 10, y: -8 }, width: 0.2, height: 0.2 }),
);
for (let k = 0; k < 3; k++) {
  const link = chainWorld.add(box({ position: { x: 10.5 + k, y: -8 }, width: 1, height: 0.2 }));
  chainWorld.addJoint(revoluteJoint({ bodyA: anchor, bodyB: link, anchor: { x: 10 + k, y: -8 } }));
  bodies.push(link);
  anchor = link;
}
for (let i = 0; i < 240; i++) {
  world.step(1 / 60);
  chainWorld.step(1 / 60);
}

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
// The pile's bodies (the first 160; the chain hangs apart).
const ys = bodies.slice(0, 160).map((b) => b.position.y);
// The browser reports a violation in a task of its own: give it time to arrive.
setTimeout(() => {
  window.pileResult = {
    kernel: usesWebAssembly(world),
    bits,
    minY: Math.min(...ys),
    maxY: Math.max(...ys),
    violations,
    smallWorldKernel,
    error,
  };
  document.documentElement.dataset['ready'] = 'true';
}, 300);
