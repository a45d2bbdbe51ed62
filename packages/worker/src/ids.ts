/** A body of a worker world, as the page knows it: a plain number, typed. */
export type BodyId = number & { readonly __brand: 'BodyId' };
/** A joint of a worker world. */
export type JointId = number & { readonly __brand: 'JointId' };
/** A force with a duration acting on a body of a worker world. */
export type ForceId = number & { readonly __brand: 'ForceId' };
