// The shapes whose broad-phase box left its fat box in a step's finalize (the ESCAPED_SHAPES region
// of the solver memory, solver-memory.ts), listed by the kernel's shapeBounds (wasm/shape-bounds.ts)
// in the order the proxies are to move: per shape ESCAPE_STRIDE doubles, the shape id and the grown
// box (min x, min y, max x, max y, m). This file is the one definition of the row's layout: the
// kernel build writes its mirror into wasm/contact-layout.ts.

export const ESCAPE_ID = 0;
export const ESCAPE_MIN_X = 1;
export const ESCAPE_MIN_Y = 2;
export const ESCAPE_MAX_X = 3;
export const ESCAPE_MAX_Y = 4;
export const ESCAPE_STRIDE = 5;
