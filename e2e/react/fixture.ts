// Mounts <PhysicalCanvas> under StrictMode (effects mount, unmount and mount again).
import { World, box } from '@physical/engine';
import { PhysicalCanvas } from '@physical/react';
import { StrictMode, createElement } from 'react';
import { createRoot } from 'react-dom/client';

const world = new World();
const target = world.add(box({ type: 'static', position: { x: 3, y: 2 }, width: 2, height: 1 }));
const taps: unknown[] = [];
const background: { x: number; y: number }[] = [];
Object.assign(window, { world, target, taps, background });
createRoot(document.getElementById('root')!).render(
  createElement(
    StrictMode,
    null,
    createElement(PhysicalCanvas, {
      world,
      pixelsPerMeter: 40,
      style: { width: '400px', height: '300px' },
      onBodyTap: ({ body }) => taps.push(body === target),
      onBackgroundTap: ({ point }) => background.push(point),
    }),
  ),
);
requestAnimationFrame(() => {
  document.documentElement.dataset['ready'] = 'true';
});
