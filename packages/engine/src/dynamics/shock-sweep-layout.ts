// The heavy-on-light sweep's list (the kernel's prepareShockSweep writes it once a step, its
// shockSweep reads it each sub-step: wasm/shock-propagation.ts): SWEEP_STRIDE doubles per
// swept contact in the solver memory's SHOCK_SWEEP region, listed from the top down. The one
// definition: the build writes the kernel's mirror (wasm/contact-layout.ts).

/** Doubles per entry. */
export const SWEEP_STRIDE = 3;
/** The constraint's index (a whole number). */
export const SWEEP_CONSTRAINT = 0;
/** 1 where the constraint's body A is the lower one, else 0. */
export const SWEEP_LOWER_IS_A = 1;
/** The contact's restitution while its bounce is due (at first touch); 0 once it touched. */
export const SWEEP_RESTITUTION = 2;
/** Slip (m/s) the sweep's friction leaves to the ordinary passes. */
export const SWEEP_SLIP = 1e-3;
