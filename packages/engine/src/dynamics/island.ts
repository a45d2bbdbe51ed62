import type { Body } from './body.ts';

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
  private stamp = 0;
  private readonly stack: Body[] = [];
  private readonly woken: Body[] = [];
  private readonly members: Body[] = [];

  /** Puts to sleep every island of `awake` bodies that has rested for `timeToSleep` seconds. */
  sleepRestingIslands(awake: readonly Body[], count: number, timeToSleep: number): void {
    // Stamps above passStart mark bodies already searched in this pass: their island either slept
    // or cannot sleep, so they are not searched again.
    const passStart = this.stamp;
    for (let i = 0; i < count; i++) {
      const body = awake[i]!;
      if (!body.awake || body.sleepTime < timeToSleep || body.islandStamp > passStart) continue;
      if (this.collect(body, timeToSleep, passStart)) {
        for (let j = 0; j < this.members.length; j++) putToSleep(this.members[j]!);
      }
    }
  }

  /** Wakes a body and every sleeping body its island touches. */
  wake(body: Body): void {
    if (body.type === 'static') return;
    body.sleepTime = 0;
    if (body.awake) return;
    const stack = this.stack;
    const woken = this.woken;
    stack.length = 0;
    woken.length = 0;
    body.awake = true;
    stack.push(body);
    while (stack.length > 0) {
      const current = stack.pop()!;
      current.sleepTime = 0;
      woken.push(current);
      if (current.type === 'kinematic') continue;
      for (let i = 0; i < current.contacts.length; i++) {
        const contact = current.contacts[i]!;
        if (!contact.touching) continue;
        const other = contact.other(current);
        if (other.type === 'static' || other.awake) continue;
        other.awake = true;
        stack.push(other);
      }
      for (let i = 0; i < current.jointList.length; i++) {
        const joint = current.jointList[i]!;
        const other = joint.bodyA === current ? joint.bodyB : joint.bodyA;
        if (other.type === 'static' || other.awake) continue;
        other.awake = true;
        stack.push(other);
      }
    }
    const onWake = this.onWake;
    if (onWake !== null) for (let i = 0; i < woken.length; i++) onWake(woken[i]!);
  }

  /** Puts a body and its whole island to sleep now. */
  sleep(body: Body): void {
    if (body.type === 'static') return;
    this.collect(body, -1, this.stamp);
    for (let j = 0; j < this.members.length; j++) putToSleep(this.members[j]!);
  }

  /**
   * Collects the island of `start` into `members`. Returns false as soon as a member has rested
   * less than `minimumRest` seconds or belongs to an island already found restless in this pass.
   */
  private collect(start: Body, minimumRest: number, passStart: number): boolean {
    const stamp = ++this.stamp;
    const stack = this.stack;
    const members = this.members;
    stack.length = 0;
    members.length = 0;
    start.islandStamp = stamp;
    stack.push(start);
    while (stack.length > 0) {
      const body = stack.pop()!;
      members.push(body);
      // A kinematic body does not join islands together: what touches it is not connected through it.
      if (body.type === 'kinematic') continue;
      for (let i = 0; i < body.contacts.length; i++) {
        const contact = body.contacts[i]!;
        if (!contact.touching) continue;
        const other = contact.other(body);
        if (other.type === 'static' || other.islandStamp === stamp) continue;
        if (other.sleepTime < minimumRest || other.islandStamp > passStart) return false;
        // A moving kinematic body keeps what it touches awake (checked above); a resting one is
        // left as it is.
        if (other.type === 'kinematic') continue;
        other.islandStamp = stamp;
        stack.push(other);
      }
      // Joined bodies rest or move together too.
      for (let i = 0; i < body.jointList.length; i++) {
        const joint = body.jointList[i]!;
        const other = joint.bodyA === body ? joint.bodyB : joint.bodyA;
        if (other.type === 'static' || other.islandStamp === stamp) continue;
        if (other.sleepTime < minimumRest || other.islandStamp > passStart) return false;
        if (other.type === 'kinematic') continue;
        other.islandStamp = stamp;
        stack.push(other);
      }
    }
    return true;
  }
}

function putToSleep(body: Body): void {
  body.awake = false;
  body.sleepTime = 0;
  body.velocityX = 0;
  body.velocityY = 0;
  body.angularVelocityValue = 0;
}
