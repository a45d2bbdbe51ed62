// Whether the contact passes solve pairs of independent constraints in f64x2 lanes (see
// contact-kernel.ts). This file is the JavaScript build's value: wasm2js cannot translate SIMD.
// scripts/contact-kernel-build.ts compiles the WebAssembly build with LANES true in its place.
export const LANES: bool = false;
