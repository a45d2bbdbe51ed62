// A worker that serves a world, then dies of an uncaught error: the page must hear of it.
import { serveWorld } from '@physical/worker';

serveWorld();
setTimeout(() => {
  throw new Error('the physics crashed');
}, 100);
