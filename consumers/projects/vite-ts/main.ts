// Vite + strict TypeScript: the element registered by its side-effect entry and typed through it
// alone (no other import of @physical/canvas, so nothing else brings the tag's typings in).
import '@physical/canvas/define';
import { World, box, wall } from '@physical/engine';
import { expose } from '../shared/expose.ts';

const world = new World();
world.add(wall({ from: { x: 0, y: 5 }, to: { x: 16, y: 5 } }));
const crate = world.add(box({ position: { x: 4, y: 1 }, width: 1, height: 1 }));

const canvas = document.querySelector('physical-canvas')!;
canvas.world = world;
let taps = 0;
canvas.addEventListener('bodytap', (event) => {
  if (event.detail.body === crate) taps++;
});
expose(world, crate, () => {
  const rect = canvas.getBoundingClientRect();
  const { originX, originY, scale } = canvas.viewport;
  const x = rect.left + (crate.position.x - originX) * scale;
  return { x, y: rect.top + (crate.position.y - originY) * scale, taps };
});
