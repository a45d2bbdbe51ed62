// The contact constraints' layout in the solver's memory (solver-memory.ts), and the two numbers
// of the contact passes that are not physics constants. One definition: the contact kernel
// (wasm/contact-kernel.ts) reads a mirror of this file that `npm run build:kernel -w
// @physical/engine` generates (wasm/contact-layout.ts), so a change here reaches both builds of
// the passes (WebAssembly and JavaScript) and the JavaScript that reads constraints
// (ShockPropagation and refreshCirclePairs in contact-solver.ts). See the kernel for what each
// number means to the passes (prepare, warmStart, solve, storeImpulses).

// Per-constraint layout (doubles).
export const NORMAL_X = 0;
export const NORMAL_Y = 1;
export const FRICTION = 2;
export const RESTITUTION = 3;
export const INV_MASS_A = 4;
export const INV_I_A = 5;
export const INV_MASS_B = 6;
export const INV_I_B = 7;
export const BIAS_RATE = 8;
export const MASS_SCALE = 9;
export const IMPULSE_SCALE = 10;
export const POINT_COUNT = 11;
// Where the common point of application lives (see prepareContacts), and the motion since the
// lever arms were set.
export const SHIFT_WEIGHT_A = 12;
export const SHIFT_WEIGHT_B = 13;
export const REF_DP_AX = 14;
export const REF_DP_AY = 15;
export const REF_DP_BX = 16;
export const REF_DP_BY = 17;
// Circle pairs: radii and the centre difference cB - cA at the step's start.
export const RADIUS_A = 18;
export const RADIUS_B = 19;
export const CENTER_DX = 20;
export const CENTER_DY = 21;
// Two-point manifolds: the normal block K (see solveContacts), and 1 when it is well-conditioned
// enough to be solved as a block.
export const BLOCK_K11 = 22;
export const BLOCK_K12 = 23;
export const BLOCK_K22 = 24;
export const BLOCK = 25;
export const POINTS = 26;
// Per-point layout, relative to POINTS + j * POINT_STRIDE.
export const R_AX = 0;
export const R_AY = 1;
export const R_BX = 2;
export const R_BY = 3;
export const BASE_SEPARATION = 4;
export const NORMAL_IMPULSE = 5;
export const TANGENT_IMPULSE = 6;
export const MAX_NORMAL_IMPULSE = 7;
export const NORMAL_MASS = 8;
export const TANGENT_MASS = 9;
export const RELATIVE_VELOCITY = 10;
export const TOTAL_NORMAL_IMPULSE = 11;
export const TOTAL_TANGENT_IMPULSE = 12;
// Impact state of a point: 0 none; 1 an impact found in this sub-step's solve pass, to bounce in
// its relax pass; 2 bounced in this sub-step (the bounce is not warm-started); 3 bounced in an
// earlier sub-step of this step; 4 no bounce in this step (pressed, see prepareContacts); 5 an
// impact of the impact round under way, 6 an impact of an earlier round of this sub-step (see
// the kernel's impacts: not warm-started either, and not a bounce that makes a contact pressed).
// A point may bounce in states 0, 1 and 3.
export const IMPACT = 15;
// The lever arms' cross products with the normal when they were set (rA x n, rB x n): a pass
// adds only the common point's shift to them. Those with the tangent t = (ny, -nx) are computed
// where they are needed, r x t = -(r . n): two more stored numbers per point made the stride
// longer, and a 58,000-contact pile slower (its constraints outgrow the cache).
export const RN_A = 13;
export const RN_B = 14;
export const POINT_STRIDE = 16;
export const STRIDE: number = POINTS + 2 * POINT_STRIDE;
/**
 * Where constraint `i` starts in the constraint region (in doubles). Constraints are stored in
 * pairs, their numbers interleaved: number k of constraint i is element constraintBase(i) + 2 k,
 * number k of its point j element constraintBase(i) + 2 (POINTS + j POINT_STRIDE + k). So
 * constraints 2m and 2m + 1 have each number side by side, and the WebAssembly kernel's lanes
 * load both with one v128.load (Box2D v3's b2ContactConstraintSIMD is laid out the same way).
 * The last constraint of an odd count still takes a pair's room: the region holds an even number
 * of constraints (its capacity is a power of two from 256, solver-memory.ts).
 */
export function constraintBase(i: number): number {
  return (i >> 1) * 2 * STRIDE + (i & 1);
}
// A contact that bounced in each of its last three steps and still overlaps is pressed together
// by a load (a pile on a bouncy particle), not colliding. Bouncing it again would skip its push-out
// each sub-step (an impact is not pushed out, see solveContacts), so its overlap would grow and the
// load would pass through it: a particle under 12 rows of a pile went through the floor. Such a
// point is a contact for one step; from then on it is warm-started and never counts as an impact.
// Not after one or two steps: in an elastic gas a light particle squeezed between a heavy one and
// a wall bounces in consecutive steps while overlapping, and holding it loses energy (4 % in
// test/fidelity/heavy-on-light.test.ts's gas).
export const PRESSED_AFTER_BOUNCING_STEPS = 3;
// The impact rounds' modes (the kernel's impacts, run by Solver.impactRounds): start a round
// (closing the last one's impacts), move the open impacts on towards their targets between joint
// passes, open the relax pass's bounces for that, close all and clear the marks; count the relax
// pass's bounces and change nothing (whether a lone bounce is solved with the joints).
export const IMPACT_ROUND = 0;
export const IMPACT_CONTINUE = 1;
export const IMPACT_OPEN = 2;
export const IMPACT_CLOSE = 3;
export const IMPACT_COUNT = 4;
/** Largest condition number (max K_jj^2 / det K) of a two-point block solved as a block. */
export const MAX_CONDITION_NUMBER = 1000;
