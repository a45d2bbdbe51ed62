// Compile test: `import '@physical/canvas/define'` alone types the tag and its events.
import '@physical/canvas/define';
import { World } from '@physical/engine';

const canvas = document.querySelector('physical-canvas')!;
canvas.world = new World();
canvas.fit = 'contain';
// @ts-expect-error: not a fit mode
canvas.fit = 'sideways';

const created = document.createElement('physical-canvas');
created.paused = true;

canvas.addEventListener('bodytap', (event) => {
  const mass: number | undefined = event.detail.body?.mass;
  void mass;
});
// The events bubble: typed on any element, through HTMLElementEventMap.
document.body.addEventListener('attributeerror', (event) => {
  const message: string = event.detail.error.message;
  void message;
});
document.body.addEventListener('pausechange', (event) => {
  // @ts-expect-error: `paused` is a boolean
  const wrong: string = event.detail.paused;
  void wrong;
});
