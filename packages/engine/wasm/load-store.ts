// Number k of a row of doubles at byte offset p: the one way the kernel's passes read and write
// the solver memory's double regions (src/dynamics/solver-memory.ts), shared by the contact
// passes (contact-kernel.ts) and the body passes (body-passes.ts).

export function ld(p: usize, k: i32): f64 {
  return load<f64>(p + ((<usize>k) << 3));
}

export function st(p: usize, k: i32, v: f64): void {
  store<f64>(p + ((<usize>k) << 3), v);
}
