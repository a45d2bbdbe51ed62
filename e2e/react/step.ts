// A paused <PhysicalCanvas> whose ref steps it: the React side of `canvas.step()`.
import type { PhysicalCanvasElement } from '@physical/canvas';
import { World, box } from '@physical/engine';
import { PhysicalCanvas } from '@physical/react';
import { StrictMode, createElement, createRef } from 'react';
import { createRoot } from 'react-dom/client';

const world = new World();
const crate = world.add(box({ position: { x: 3, y: 1 }, width: 1, height: 1 }));
const canvas = createRef<PhysicalCanvasElement>();
Object.assign(window, { crate, canvas });
createRoot(document.getElementById('root')!).render(
  createElement(
    StrictMode,
    null,
    createElement(PhysicalCanvas, {
      ref: canvas,
      world,
      paused: true,
      style: { width: '400px', height: '300px' },
    }),
  ),
);
requestAnimationFrame(() => {
  document.documentElement.dataset['ready'] = 'true';
});
