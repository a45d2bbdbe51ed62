import type { PhysicalCanvasElement } from '@physical/canvas';
import { World, box } from '@physical/engine';
import { WorkerWorld } from '@physical/worker';
import { h } from './dom.ts';
import { icon } from './icons.ts';

/** The route of the worker page. */
export const WORKER_ROUTE = 'worker';

/** 2,000 boxes of 0.25 m fall into a 20 m x 15 m box. */
const COUNT = 2000;
const WALLS = [
  { type: 'static' as const, position: { x: 10, y: 15.25 }, width: 20, height: 0.5 },
  { type: 'static' as const, position: { x: -0.25, y: 7.5 }, width: 0.5, height: 15 },
  { type: 'static' as const, position: { x: 20.25, y: 7.5 }, width: 0.5, height: 15 },
];
const boxAt = (i: number) => ({
  width: 0.25,
  height: 0.25,
  position: { x: 0.6 + (i % 50) * 0.38, y: 13.5 - Math.floor(i / 50) * 0.34 },
});

/**
 * 2,000 bodies off the main thread: a pile stepped in a Web Worker (`@physical/worker`) and drawn
 * by `<physical-canvas>`, beside a deliberately busy UI (a table rewritten every frame, a text
 * field, and a slider that burns main-thread time). Switch the world to the page to compare.
 */
export function renderWorkerPage(root: HTMLElement): () => void {
  document.title = '2,000 bodies in a worker';
  const back = h('a', { class: 'icon-button back', href: '#/', 'aria-label': 'All samples' });
  back.innerHTML = icon('back');
  const canvas = h('physical-canvas', {
    'pixels-per-meter': '30',
    fit: 'contain',
    'view-box': '0 0 20 15.5',
  }) as PhysicalCanvasElement;
  canvas.style.cssText = 'height: min(60vh, 480px); flex: 2 1 360px;';
  const where = h('select', { 'aria-label': 'Where the world runs' });
  where.append(
    h('option', { value: 'worker' }, 'World in a worker'),
    h('option', { value: 'page' }, 'World on the page'),
  );
  const burn = h('input', {
    type: 'range',
    min: '0',
    max: '12',
    value: '4',
    'aria-label': 'Busy work per frame (ms)',
  }) as HTMLInputElement;
  const stats = h('output', {});
  const rows = Array.from({ length: 40 }, () => h('td', {}));
  const table = h(
    'table',
    {},
    ...rows.map((cell, i) => h('tr', {}, h('td', {}, `row ${i + 1}`), cell)),
  );
  const panel = h(
    'div',
    { class: 'busy-ui' },
    where,
    h('label', {}, 'Busy work per frame (ms) ', burn),
    h('input', { type: 'text', placeholder: 'Type here while it falls' }),
    stats,
    table,
  );
  panel.style.cssText =
    'flex: 1 1 240px; display: flex; flex-direction: column; gap: 8px; max-height: min(60vh, 480px); overflow: auto;';
  root.replaceChildren(
    h('header', { class: 'app-bar' }, back, h('h1', {}, '2,000 bodies in a worker')),
    h(
      'div',
      { class: 'content' },
      h(
        'p',
        { class: 'intro' },
        'The pile steps in a Web Worker; the page only draws it, so the busy panel stays responsive. Drag the boxes; switch the world to the page to feel the difference.',
      ),
      h('div', { style: 'display: flex; flex-wrap: wrap; gap: 16px;' }, canvas, panel),
    ),
  );

  let worker: WorkerWorld | null = null;
  const build = (): void => {
    worker?.terminate();
    worker = null;
    if (where.value === 'worker') {
      const world = new WorkerWorld(
        new Worker(new URL('./pile.worker.ts', import.meta.url), { type: 'module' }),
      );
      for (const wall of WALLS) world.add({ kind: 'box', ...wall });
      for (let i = 0; i < COUNT; i++) world.add({ kind: 'box', ...boxAt(i) });
      world.on('error', (error) => (stats.textContent = error.message));
      worker = world;
      canvas.world = world;
    } else {
      const world = new World();
      for (const wall of WALLS) world.add(box(wall));
      for (let i = 0; i < COUNT; i++) world.add(box(boxAt(i)));
      canvas.world = world;
    }
  };
  where.addEventListener('change', build);
  build();

  // The busy UI: every frame, burn the chosen time and rewrite the table; show the frame rate.
  let frame = 0;
  let last = performance.now();
  let frames = 0;
  const tick = (now: number): void => {
    const until = performance.now() + Number(burn.value);
    let x = 0;
    while (performance.now() < until) x += Math.random();
    for (let i = 0; i < rows.length; i++) rows[i]!.textContent = ((x * (i + 1)) % 1000).toFixed(3);
    frames++;
    if (now - last >= 1000) {
      stats.textContent = `${Math.round((frames * 1000) / (now - last))} fps, ${canvas.stepCount} steps`;
      frames = 0;
      last = now;
    }
    frame = requestAnimationFrame(tick);
  };
  frame = requestAnimationFrame(tick);
  return () => {
    cancelAnimationFrame(frame);
    worker?.terminate();
    canvas.world = null;
  };
}
