import { requireFunction, requireOneOf } from './validate.ts';

/** @internal One registered listener; `active` turns false the moment it is removed. */
export interface ListenerEntry<F> {
  readonly listener: F;
  active: boolean;
}

/** @internal A count of listeners shared by many lists (see {@link Listeners}). */
export interface ListenerCount {
  total: number;
}

/**
 * @internal A list of listeners per event name. Listeners are called in the order they were
 * added. The list is copied on write, not on emit, so emitting allocates nothing; a dispatch that
 * holds the old list still skips a listener removed meanwhile (its entry is marked inactive at
 * once), so a listener removed during dispatch, by itself or by another, is never called again.
 * A listener added during a dispatch joins from the next one.
 */
export class Listeners<Events extends { [K in keyof Events]: (event: never) => void }> {
  private readonly lists = new Map<keyof Events, readonly ListenerEntry<unknown>[]>();
  /** Listeners of every type together: 0 lets hot loops skip an object without a map lookup. */
  total = 0;

  /**
   * `names`: the event names this list accepts (a typo is an error, not a silent no-op).
   * `shared`: a count that every list of a kind adds its listeners to, so a dispatch can skip all
   * of them at once when there are none (see World's event dispatch).
   */
  constructor(
    private readonly names: readonly (keyof Events & string)[],
    private readonly shared: ListenerCount = { total: 0 },
  ) {}

  on<K extends keyof Events>(type: K, listener: Events[K]): () => void {
    requireOneOf('type', type, this.names);
    requireFunction('listener', listener);
    const list = this.lists.get(type);
    const entry: ListenerEntry<unknown> = { listener, active: true };
    this.lists.set(type, list === undefined ? [entry] : [...list, entry]);
    this.total++;
    this.shared.total++;
    return () => this.remove(type, entry);
  }

  off<K extends keyof Events>(type: K, listener: Events[K]): void {
    requireOneOf('type', type, this.names);
    requireFunction('listener', listener);
    const list = this.lists.get(type);
    if (list === undefined) return;
    const entry = list.find((e) => e.listener === listener && e.active);
    if (entry !== undefined) this.remove(type, entry);
  }

  private remove(type: keyof Events, entry: ListenerEntry<unknown>): void {
    if (!entry.active) return;
    entry.active = false;
    const list = this.lists.get(type)!;
    const next = list.filter((e) => e !== entry);
    this.total--;
    this.shared.total--;
    if (next.length === 0) this.lists.delete(type);
    else this.lists.set(type, next);
  }

  /** The current listeners of a type, or undefined when there are none (a cheap check in hot code). */
  get<K extends keyof Events>(type: K): readonly ListenerEntry<Events[K]>[] | undefined {
    return this.lists.get(type) as readonly ListenerEntry<Events[K]>[] | undefined;
  }
}

/** @internal Calls every listener of a list still registered, in order. */
export function callAll<E>(
  listeners: readonly ListenerEntry<(event: E) => void>[] | undefined,
  event: E,
): void {
  if (listeners === undefined) return;
  for (let i = 0; i < listeners.length; i++) {
    const entry = listeners[i]!;
    if (entry.active) entry.listener(event);
  }
}
