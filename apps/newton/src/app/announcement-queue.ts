/**
 * What an announcer is given: the sentence, or a function that writes it when its turn comes.
 * The function form is for messages sent far more often than spoken (a crowd's collisions, one a
 * step): only the two newest wait, so formatting each one when sent wasted the step's time.
 */
export type Announcement = string | (() => string);

/** Messages waiting to be spoken at most this many per list: a burst becomes one sentence. */
const KEPT = 2;

/**
 * The messages an announcer has not spoken yet: urgent ones (the answer to the user's own
 * action) before the others, the newest {@link KEPT} of each list, a text sent again moved to
 * the end rather than kept twice. Written in place: a crowd sends one a step.
 */
export class AnnouncementQueue {
  private readonly urgent: Announcement[] = [];
  private readonly others: Announcement[] = [];

  /** Whether nothing waits. */
  get empty(): boolean {
    return this.urgent.length === 0 && this.others.length === 0;
  }

  /** Adds `message`; the oldest of its list goes when more than {@link KEPT} wait. */
  push(message: Announcement, urgent = false): void {
    const list = urgent ? this.urgent : this.others;
    const same = list.indexOf(message);
    if (same >= 0) list.splice(same, 1);
    list.push(message);
    if (list.length > KEPT) list.shift();
  }

  /** The next sentence to speak, written now if it was sent as a function; null if none waits. */
  next(): string | null {
    const waiting = this.urgent.shift() ?? this.others.shift();
    if (waiting === undefined) return null;
    return typeof waiting === 'string' ? waiting : waiting();
  }
}
