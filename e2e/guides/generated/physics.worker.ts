// physics.worker.ts
import { serveWorld } from '@physical/worker';

serveWorld();