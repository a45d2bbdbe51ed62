// Starts the Vite test server once for the whole run; workers read its address from the
// environment (Playwright forks them after the global setup).
import { BASE_URL_VARIABLE } from './harness.ts';
import { startServer } from './server.ts';

export default async function globalSetup(): Promise<() => Promise<void>> {
  const server = await startServer();
  process.env[BASE_URL_VARIABLE] = server.url;
  return () => server.close();
}
