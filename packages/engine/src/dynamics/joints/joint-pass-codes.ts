// The codes the kernel's joint passes take (wasm/joint-passes.ts: jointPass): the joint's kind and
// the pass. The build script generates them into the kernel's layout (J_KIND_..., J_PASS_...);
// JointBatch passes them.
/** A joint kind, as the kernel's passes tell them apart. */
export const KIND_REVOLUTE = 0;
export const KIND_PRISMATIC = 1;
export const KIND_WELD = 2;
export const KIND_DISTANCE = 3;
export const KIND_MOUSE = 4;
/** The warm start with last step's impulses. */
export const PASS_WARM_START = 0;
/** A solve with the position bias. */
export const PASS_SOLVE = 1;
/** A relax pass (no bias), which also sums the step's impulses. */
export const PASS_RELAX = 2;
