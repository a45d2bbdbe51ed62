// Vite + strict TypeScript: the element registered by its side-effect entry, typed through it.
import '@physical/canvas/define';
import { worldToScreen } from '@physical/canvas';
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
  const point = worldToScreen(canvas.viewport, crate.position);
  return { x: rect.left + point.x, y: rect.top + point.y, taps };
});
