// The physics worker of the gallery's "2,000 bodies off the main thread" page.
import { serveWorld } from '@physical/worker';

serveWorld();
