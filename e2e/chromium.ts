// How every browser run in this repository launches Chromium: Debian's build (Playwright cannot
// download its own here; CHROMIUM_PATH overrides), no sandbox (CI runs as root), no GPU, and none of
// the background traffic that would add noise to timings. One place for the browser tests, the
// frame-time benches, `npm run bench -- --browser` and the consumer test.
export const CHROMIUM_LAUNCH = {
  executablePath: process.env['CHROMIUM_PATH'] ?? '/usr/bin/chromium',
  args: [
    '--no-sandbox',
    '--disable-gpu',
    '--disable-background-networking',
    '--disable-component-update',
    '--disable-sync',
    '--no-first-run',
  ],
};
