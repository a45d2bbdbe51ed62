// `process` as a bundler or Node provides it: declared here, since the engine uses no Node types.
declare const process: { env: { NODE_ENV?: string } };

/**
 * True in a development build, where the engine adds checks that cost a little and help a lot
 * (see world/size-warning.ts). A library cannot know how the app is built, so it asks as React
 * does: `process.env.NODE_ENV`, which Vite, webpack, Rollup, Parcel and esbuild (`--define`)
 * replace with the build's mode (`"production"` in a production build: silent), and which Node,
 * Vitest and Jest read at run time (unset or `"test"`: development). In a browser without a
 * bundler (a `<script type="module">` from a CDN) `process` does not exist: silent, as in
 * production. Written as the bare `process.env.NODE_ENV` on purpose: bundlers replace that
 * exact expression.
 */
export function isDevelopment(): boolean {
  try {
    return process.env.NODE_ENV !== 'production';
  } catch {
    return false;
  }
}
