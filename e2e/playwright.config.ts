// Browser tests: @playwright/test on Debian's Chromium (Playwright downloads no browser here).
// Specs keep the harness API (harness.ts). `npm run test:e2e` runs them all;
// `npm run test:e2e -- -g <part of a name>` some; `-- --trace on` records every test's trace.
import { defineConfig } from '@playwright/test';
import { CHROMIUM_LAUNCH } from './chromium.ts';

export default defineConfig({
  testDir: '.',
  testMatch: '**/*.spec.ts',
  outputDir: '../test-results/playwright',
  globalSetup: './global-setup.ts',
  // A hung test fails instead of stalling the run. The slowest (every gallery sample in turn)
  // takes about 20 s on a quiet 2-core machine, and over a minute on a loaded one.
  timeout: 180_000,
  // The guide forbids focused tests; the harness has no test.only, but a spec could import it.
  forbidOnly: true,
  // A failed test runs once more, recording a trace (below): a real failure fails twice and
  // leaves its trace; a flaky one is reported as "flaky". Recording every test's trace instead
  // doubles the CPU time and itself upsets the frame-timing tests on 2 cores.
  retries: 1,
  // Two cores: most tests wait on frames and timers, so two workers overlap their waits.
  workers: 2,
  fullyParallel: true,
  reporter: [['list']],
  use: {
    browserName: 'chromium',
    launchOptions: CHROMIUM_LAUNCH,
    // Every failure leaves a screenshot of each page it had open, its retry also a trace
    // (npx playwright show-trace test-results/playwright/<test>-retry1/trace.zip): actions,
    // console, network and a screencast. DOM snapshots are left out: they made a retry take
    // twice as long as the test.
    trace: { mode: 'on-first-retry', screenshots: true, snapshots: false, sources: true },
    screenshot: 'only-on-failure',
  },
});
