// Per-step lists keep their length and a count (truncating would free the backing store, and the
// next step's pushes would allocate again), so their entries past the count, and all of them
// between steps, still point at the objects of the last step. A removed body must not stay
// reachable through them (its userData with it): removal overwrites them with null, in place.

/** @internal Overwrites `list[from..]` with null, keeping its length (no allocation). */
export function releaseFrom(list: unknown[], from: number): void {
  for (let i = from; i < list.length; i++) list[i] = null;
}
