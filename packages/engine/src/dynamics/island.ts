import { releaseFrom } from '../core/release.ts';
import type { Body } from './body.ts';
import type { ContactEdges } from './contact-edges.ts';

/**
 * Sleep by islands: bodies that touch or are joined (through dynamic or kinematic bodies, never
 * through static ones) rest or move together, so a pile falls asleep only as a whole and one touch wakes all of
 * it (Box2D's islands). Islands are found by a depth-first search when needed rather than kept
 * persistent: the search starts only from bodies that have rested long enough, and gives up as
 * soon as it reaches one that has not, so a moving scene pays almost nothing.
 */
export class Islands {
  /** Called for every body that wakes up (the world turns it into its 'wake' event). */
  onWake: ((body: Body) => void) | null = null;
  /** @internal Last island-search stamp (saved by world snapshots). */
  stamp = 0;
  private readonly stack: Body[] = [];
  private readonly woken: Body[] = [];
  private readonly members: Body[] = [];
  /** Bodies of the last collected island (the first of `members`). */
  private memberCount = 0;
  /** Whether the last collected island touches something or is joined to something. */
  private held = false;
  /** collect's rest threshold (s); a double from the start, so V8 keeps the field unboxed. */
  private minimumRest = 0.5;

  /**
   * `edges`: each body's contact list, walked by key; `bodies`: the world's bodies by world index
   * (what an edge's other side names).
   */
  constructor(
    private readonly edges: ContactEdges,
    private readonly bodies: readonly Body[],
  ) {}

  /** Drops the references its search lists hold (a removed body must not stay reachable). */
  releaseReferences(): void {
    releaseFrom(this.stack, 0);
    releaseFrom(this.woken, 0);
    releaseFrom(this.members, 0);
    this.wokenCount = 0;
    this.wokenUsed = 0;
    this.memberCount = 0;
  }

  /**
   * Drops what wakes wrote since the last release (a removal wakes the removed body's island,
   * the body itself included): as much as they wrote, so each removal pays for its own wake.
   */
  releaseWoken(): void {
    const stack = this.stack;
    const woken = this.woken;
    for (let i = 0; i < this.wokenUsed; i++) {
      stack[i] = null as unknown as Body;
      woken[i] = null as unknown as Body;
    }
    this.wokenUsed = 0;
    this.wokenCount = 0;
  }

  /** Puts to sleep every island of `awake` bodies that has rested for `timeToSleep` seconds. */
  sleepRestingIslands(awake: readonly Body[], count: number, timeToSleep: number): void {
    // Stamps above passStart mark bodies already searched in this pass: their island either slept
    // or cannot sleep, so they are not searched again.
    const passStart = this.stamp;
    for (let i = 0; i < count; i++) {
      const body = awake[i]!;
      if (!body.awake || body.sleepTime < timeToSleep || body.islandStamp > passStart) continue;
      this.minimumRest = timeToSleep;
      if (!this.collect(body, passStart)) continue;
      const members = this.members;
      const memberCount = this.memberCount;
      if (!this.held && !allStill(members, memberCount)) {
        // Newton's first law: a body that touches nothing keeps its velocity, however small
        // (Box2D would stop a body drifting in zero gravity below its sleep speed). It rests only
        // at exactly zero velocity; otherwise it tries again after another timeToSleep.
        for (let j = 0; j < memberCount; j++) members[j]!.sleepTime = 0;
        continue;
      }
      for (let j = 0; j < memberCount; j++) putToSleep(members[j]!);
    }
  }

  /** The bodies the last {@link wake} woke: the first {@link wokenCount} (none if it found its body awake). */
  get lastWoken(): readonly Body[] {
    return this.woken;
  }

  /** How many bodies the last {@link wake} woke. */
  wokenCount = 0;
  /** Entries of `stack` and `woken` that wakes wrote since the last release. */
  private wokenUsed = 0;

  /** Wakes a body and every sleeping body its island touches. */
  wake(body: Body): void {
    // Counts, not `length = 0`: emptying an array that way drops its backing store, and the next
    // wake would allocate a new one.
    this.wokenCount = 0;
    if (body.type === 'static') return;
    body.sleepTime = 0;
    if (body.awake) return;
    const stack = this.stack;
    const woken = this.woken;
    let top = 0;
    let count = 0;
    body.awake = true;
    stack[top++] = body;
    while (top > 0) {
      const current = stack[--top]!;
      current.sleepTime = 0;
      woken[count++] = current;
      if (current.type === 'kinematic') continue;
      const edges = this.edges;
      for (let key = edges.first(current.worldIndex); key >= 0; key = edges.next[key]!) {
        if (!edges.touching(key)) continue;
        const other = this.bodies[edges.other(key)]!;
        if (other.type === 'static' || other.awake) continue;
        other.awake = true;
        stack[top++] = other;
      }
      for (let i = 0; i < current.jointList.length; i++) {
        const joint = current.jointList[i]!;
        const other = joint.bodyA === current ? joint.bodyB : joint.bodyA;
        if (other.type === 'static' || other.awake) continue;
        other.awake = true;
        stack[top++] = other;
      }
    }
    this.wokenCount = count;
    if (count > this.wokenUsed) this.wokenUsed = count;
    const onWake = this.onWake;
    if (onWake !== null) for (let i = 0; i < count; i++) onWake(woken[i]!);
  }

  /** Puts a body and its whole island to sleep now. */
  sleep(body: Body): void {
    if (body.type === 'static') return;
    this.minimumRest = -1;
    this.collect(body, this.stamp);
    for (let j = 0; j < this.memberCount; j++) putToSleep(this.members[j]!);
  }

  /**
   * Collects the island of `start` into `members`. Returns false as soon as a member has rested
   * less than `minimumRest` seconds or belongs to an island already found restless in this pass.
   * (`minimumRest` is a field, not an argument: V8 boxes a fractional argument of a call it does
   * not inline, and this runs for every resting body each step.)
   */
  private collect(start: Body, passStart: number): boolean {
    const minimumRest = this.minimumRest;
    const stamp = ++this.stamp;
    const stack = this.stack;
    const members = this.members;
    // Counts, not `length = 0`: emptying an array that way drops its backing store, and every
    // island searched in every step would allocate a new one.
    let top = 0;
    let memberCount = 0;
    this.held = false;
    start.islandStamp = stamp;
    stack[top++] = start;
    while (top > 0) {
      const body = stack[--top]!;
      members[memberCount++] = body;
      // A kinematic body does not join islands together: what touches it is not connected through it.
      if (body.type === 'kinematic') continue;
      const edges = this.edges;
      for (let key = edges.first(body.worldIndex); key >= 0; key = edges.next[key]!) {
        if (!edges.touching(key)) continue;
        this.held = true;
        const other = this.bodies[edges.other(key)]!;
        if (other.type === 'static' || other.islandStamp === stamp) continue;
        if (other.sleepTime < minimumRest || other.islandStamp > passStart) return false;
        // A moving kinematic body keeps what it touches awake (checked above); a resting one is
        // left as it is.
        if (other.type === 'kinematic') continue;
        other.islandStamp = stamp;
        stack[top++] = other;
      }
      // Joined bodies rest or move together too.
      for (let i = 0; i < body.jointList.length; i++) {
        const joint = body.jointList[i]!;
        this.held = true;
        const other = joint.bodyA === body ? joint.bodyB : joint.bodyA;
        if (other.type === 'static' || other.islandStamp === stamp) continue;
        if (other.sleepTime < minimumRest || other.islandStamp > passStart) return false;
        if (other.type === 'kinematic') continue;
        other.islandStamp = stamp;
        stack[top++] = other;
      }
    }
    this.memberCount = memberCount;
    return true;
  }
}

/** True if no body of the list moves at all. */
function allStill(bodies: readonly Body[], count: number): boolean {
  for (let i = 0; i < count; i++) {
    const body = bodies[i]!;
    if (body.velocityX !== 0 || body.velocityY !== 0 || body.angularVelocityValue !== 0) {
      return false;
    }
  }
  return true;
}

function putToSleep(body: Body): void {
  body.awake = false;
  body.sleepTime = 0;
  body.velocityX = 0;
  body.velocityY = 0;
  body.angularVelocityValue = 0;
}
