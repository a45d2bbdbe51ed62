// The benchmark's physics worker.
import { serveWorld } from '@physical/worker';

serveWorld();
