// The worker of the fixture: serves a world to the page's WorkerWorld.
import { serveWorld } from '@physical/worker';

serveWorld();
