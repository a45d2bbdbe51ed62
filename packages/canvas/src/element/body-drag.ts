import type { Body, Vec2, World } from '@physical/engine';
import type { HeldPoint } from '../draw/scene.ts';

/** Fastest throw (m/s): a flick is fast, not ballistic. */
const MAX_THROW_SPEED = 50;

// The pull's tuning: the engine's mouse joint defaults (Box2D v3's): a 5 Hz spring at damping
// ratio 0.7, at most 1000 N per kg of the body (about 100 g), and a light brake on the spin
// (0.5 Hz, ratio 0.1) so that a body held off-centre settles instead of swinging for ever.
const PULL_HERTZ = 5;
const PULL_DAMPING_RATIO = 0.7;
const MAX_FORCE_PER_KG = 1000;
const SPIN_HERTZ = 0.5;
const SPIN_DAMPING_RATIO = 0.1;

interface Hold extends HeldPoint {
  readonly pointerId: number;
  readonly world: World;
  readonly target: Vec2;
  /** The strongest pull (N): fixed when grabbed, as the engine's mouse joint fixes it. */
  readonly maxForce: number;
}

// Scratch, so that a step's pull allocates nothing.
const point: Vec2 = { x: 0, y: 0 };
const velocity: Vec2 = { x: 0, y: 0 };

/**
 * Bodies held by pointers, several at once (several fingers drag several bodies). Each pulls its
 * pressed point to its pointer with a damped spring of bounded force, the soft step of Catto's
 * soft constraints (as Box2D v3's mouse joint), applied as an impulse before each step the canvas
 * runs ({@link pull}): the engine's mouse joint's tuning and feel (its pull solved once a step
 * instead of once a sub-step; the grabbed point keeps within 3 cm of where the mouse joint takes
 * it: test/element/body-drag.test.ts) without bundling the engine's joints for every page.
 * Releasing sets the body's velocity to the finger's: a throw.
 */
export class BodyDrag {
  private readonly holds: Hold[] = [];

  /** Number of bodies held now. */
  get size(): number {
    return this.holds.length;
  }

  /** The held points, in the order they were grabbed (read-only; drawn as joints are). */
  get held(): readonly HeldPoint[] {
    return this.holds;
  }

  /**
   * Grabs `body` at the world point (x, y) where the pointer pressed, and pulls that point to
   * (toX, toY). Only dynamic bodies in `world` can be dragged; returns false for others.
   */
  start(
    world: World,
    pointerId: number,
    body: Body,
    x: number,
    y: number,
    toX: number,
    toY: number,
  ): boolean {
    if (body.type !== 'dynamic' || !world.has(body)) return false;
    this.end(pointerId, 0, 0, false);
    const local = body.getLocalPoint({ x, y });
    const maxForce = MAX_FORCE_PER_KG * body.mass;
    this.holds.push({ pointerId, world, body, local, target: { x: toX, y: toY }, maxForce });
    body.wake();
    return true;
  }

  /** Moves the pointer's target (m); wakes the held body, as moving a mouse joint does. */
  move(pointerId: number, x: number, y: number): void {
    const hold = this.find(pointerId);
    if (hold === undefined) return;
    hold.target.x = x;
    hold.target.y = y;
    if (hold.world.has(hold.body)) hold.body.wake();
  }

  /**
   * Lets go: the body leaves with the finger's velocity (vx, vy) (m/s, capped) when `isThrow`,
   * or with its own (a cancelled pointer).
   */
  end(pointerId: number, vx: number, vy: number, isThrow: boolean): void {
    const hold = this.find(pointerId);
    if (hold === undefined) return;
    this.holds.splice(this.holds.indexOf(hold), 1);
    // The body left the world (or stopped being dynamic): nothing to throw.
    if (!isThrow || !this.holding(hold)) return;
    const speed = Math.hypot(vx, vy);
    const cap = speed > MAX_THROW_SPEED ? MAX_THROW_SPEED / speed : 1;
    hold.body.linearVelocity = { x: vx * cap, y: vy * cap };
  }

  /** Lets go of everything, without throwing (drag turned off, world replaced, detached). */
  clear(): void {
    this.holds.length = 0;
  }

  /**
   * Pulls each held point toward its target for a step of `dt` seconds: call it before the step.
   * Holds whose body left the world are let go. A body asleep is left asleep (a sleeping body's
   * mouse joint does nothing either); moving the target wakes it.
   */
  pull(dt: number): void {
    for (let i = this.holds.length - 1; i >= 0; i--) {
      const hold = this.holds[i]!;
      if (!this.holding(hold)) this.holds.splice(i, 1);
      else if (hold.body.isAwake) pullOnce(hold, dt);
    }
  }

  private find(pointerId: number): Hold | undefined {
    for (const hold of this.holds) if (hold.pointerId === pointerId) return hold;
    return undefined;
  }

  /** Whether the hold's body is still a dynamic body of its world. */
  private holding(hold: Hold): boolean {
    return hold.world.has(hold.body) && hold.body.type === 'dynamic';
  }
}

/**
 * The soft step (Catto, "Soft Step", Box2D v3's b2MakeSoft) for a spring of `hertz` and damping
 * ratio `zeta` over `h` seconds: the bias rate (1/s) that turns the point's offset into a speed to
 * remove, and the mass scale (the share of the rigid impulse to apply).
 */
function softness(hertz: number, zeta: number, h: number, out: Vec2): Vec2 {
  const omega = 2 * Math.PI * hertz;
  const a1 = 2 * zeta + h * omega;
  const a2 = h * omega * a1;
  out.x = omega / a1;
  out.y = a2 / (1 + a2);
  return out;
}

const soft: Vec2 = { x: 0, y: 0 };

/** One step's pull on a held body: the spin brake, then the spring, as the mouse joint solves. */
function pullOnce(hold: Hold, h: number): void {
  const body = hold.body;
  const invMass = 1 / body.mass;
  const invInertia = body.inertia > 0 ? 1 / body.inertia : 0;
  let w = body.angularVelocity;
  // The brake is solved once per sub-step in the world's solver: the same here, sub-step by
  // sub-step (it has no target, so each removes the same share of the spin).
  const subSteps = hold.world.subSteps;
  const brake = softness(SPIN_HERTZ, SPIN_DAMPING_RATIO, h / subSteps, soft).y;
  w *= (1 - brake) ** subSteps;

  // The lever from the centre of mass to the held point, and that point's velocity.
  const center = body.centerOfMass;
  body.getWorldPoint(hold.local, point);
  const rx = point.x - center.x;
  const ry = point.y - center.y;
  // The solver integrates gravity before it solves a joint: the pull answers the velocity gravity
  // gives the body in the step, as the mouse joint does (else a held body sags a step's gravity).
  // Applied before the step, it cannot cancel gravity within it: a body held still ends its steps
  // at 3/8 of a step's gravity (0.06 m/s at 60 Hz), so it stays awake while held, where a mouse
  // joint lets it sleep.
  const v = body.linearVelocity;
  const gravity = hold.world.gravity;
  const vx = v.x + gravity.x * body.gravityScale * h;
  const vy = v.y + gravity.y * body.gravityScale * h;
  const { x: biasRate, y: massScale } = softness(PULL_HERTZ, PULL_DAMPING_RATIO, h, soft);
  const bx = vx - w * ry + biasRate * (point.x - hold.target.x);
  const by = vy + w * rx + biasRate * (point.y - hold.target.y);
  // The point's effective mass, K = [1/m + r_y^2/I, -r_x r_y/I; -r_x r_y/I, 1/m + r_x^2/I].
  const k11 = invMass + ry * ry * invInertia;
  const k12 = -rx * ry * invInertia;
  const k22 = invMass + rx * rx * invInertia;
  const det = k11 * k22 - k12 * k12;
  const inverse = det !== 0 ? 1 / det : 0;
  let px = -massScale * inverse * (k22 * bx - k12 * by);
  let py = -massScale * inverse * (k11 * by - k12 * bx);
  const maxImpulse = hold.maxForce * h;
  const magnitude = Math.sqrt(px * px + py * py);
  if (magnitude > maxImpulse) {
    px *= maxImpulse / magnitude;
    py *= maxImpulse / magnitude;
  }
  velocity.x = v.x + invMass * px;
  velocity.y = v.y + invMass * py;
  body.linearVelocity = velocity;
  body.angularVelocity = w + invInertia * (rx * py - ry * px);
}
