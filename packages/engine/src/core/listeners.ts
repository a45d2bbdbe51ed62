/**
 * A list of listeners per event name. Listeners are called in the order they were added; removing
 * a listener while its event is being dispatched is safe (the list is copied on write, not on emit,
 * so emitting allocates nothing).
 */
export class Listeners<Events extends { [K in keyof Events]: (event: never) => void }> {
  private readonly lists = new Map<keyof Events, readonly ((event: never) => void)[]>();
  /** Listeners of every type together: 0 lets hot loops skip an object without a map lookup. */
  total = 0;

  on<K extends keyof Events>(type: K, listener: Events[K]): () => void {
    if (typeof listener !== 'function') {
      throw new TypeError(`on('${String(type)}', listener): listener must be a function.`);
    }
    const list = this.lists.get(type);
    this.lists.set(type, list === undefined ? [listener] : [...list, listener]);
    this.total++;
    return () => this.off(type, listener);
  }

  off<K extends keyof Events>(type: K, listener: Events[K]): void {
    const list = this.lists.get(type);
    if (list === undefined) return;
    const index = list.indexOf(listener);
    if (index < 0) return;
    const next = list.slice();
    next.splice(index, 1);
    this.total--;
    if (next.length === 0) this.lists.delete(type);
    else this.lists.set(type, next);
  }

  /** The current listeners of a type, or undefined when there are none (a cheap check in hot code). */
  get<K extends keyof Events>(type: K): readonly Events[K][] | undefined {
    return this.lists.get(type) as readonly Events[K][] | undefined;
  }
}
