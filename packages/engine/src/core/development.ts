// `process` as a bundler or Node provides it: declared here, since the engine uses no Node types.
declare const process: { env: { NODE_ENV?: string } | undefined };

/**
 * True in a development build, where the engine adds checks that cost a little and help a lot
 * (see world/size-warning.ts). A library cannot know how the app is built, so it asks as React
 * does: `process.env.NODE_ENV`, which Vite, webpack, Rollup, Parcel and esbuild (`--define`)
 * replace with the build's mode (`"production"` in a production build: silent), and which Node,
 * Vitest and Jest read at run time (unset or `"test"`: development). In a browser without a
 * bundler (a `<script type="module">` from a CDN) `process` does not exist: silent, as in
 * production. Written as the bare `process.env.NODE_ENV` on purpose: bundlers replace that
 * exact expression.
 *
 * Where a production bundle should drop the development-only code itself (not only skip it), the
 * call site writes this test inline, as `if (typeof process !== 'undefined' && process.env !==
 * undefined && process.env.NODE_ENV !== 'production')`: a bundler folds it to false there
 * (esbuild drops a branch whose condition is `typeof process < "u" && ... && false`), but not
 * through a function's result or a constant of another module that is not a literal.
 * world.ts's size warning does (test/api/tree-shaking.test.ts checks it).
 */
export function isDevelopment(): boolean {
  try {
    return (
      typeof process !== 'undefined' &&
      process.env !== undefined &&
      process.env.NODE_ENV !== 'production'
    );
  } catch {
    return false;
  }
}
