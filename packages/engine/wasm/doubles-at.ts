// Two (or more) doubles at an address of the kernel's memory, indexed as a Float64Array is:
// what the engine's own math (src/math/trigonometry.ts, compiled into the kernel as it is) writes
// its results through. Unmanaged: no object is allocated; a pointer is cast to it
// (changetype<DoublesAt>(p)), and the indexing is inlined to plain loads and stores.
@unmanaged
export class DoublesAt {
  @inline
  @operator('[]')
  get(k: i32): f64 {
    return load<f64>(changetype<usize>(this) + ((<usize>k) << 3));
  }

  @inline
  @operator('[]=')
  set(k: i32, v: f64): void {
    store<f64>(changetype<usize>(this) + ((<usize>k) << 3), v);
  }
}
