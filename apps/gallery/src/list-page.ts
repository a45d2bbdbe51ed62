import type { PhysicalCanvasElement } from '@physical/canvas';
import { STEP, type Scene, type SceneView, sceneValues, sceneView, scenes } from '@physical/scenes';
import { h } from './dom.ts';
import { sceneStyleFor } from './scene-styles.ts';

/** Steps a thumbnail's world before it is drawn: the scene well under way. */
const THUMBNAIL_STEPS = 150;

/** The home page: every sample as a card with a still picture of it. */
export function renderList(root: HTMLElement): () => void {
  document.title = 'Physical samples';
  const bar = h('header', { class: 'app-bar' }, h('h1', {}, 'Physical samples'));
  const grid = h('ul', { class: 'grid' });
  const pending: { scene: Scene; canvas: PhysicalCanvasElement }[] = [];
  for (const scene of scenes) {
    const canvas = h('physical-canvas', {
      paused: '',
      fit: 'contain',
      'view-box': cameraAttribute(scene),
      background: '#1e1e1e',
      'aria-label': `${scene.title}: a still picture`,
      tabindex: '-1',
    });
    pending.push({ scene, canvas });
    grid.append(
      h(
        'li',
        {},
        h(
          'a',
          { class: 'card', href: `#/${scene.id}`, 'data-sample': scene.id },
          canvas,
          h('h2', {}, scene.title),
        ),
      ),
    );
  }
  root.replaceChildren(
    bar,
    h(
      'div',
      { class: 'content' },
      h(
        'p',
        { class: 'intro' },
        'Each sample is a small module built on Physical\u2019s public API. Open one to run it, ' +
          'change its parameters, turn on the debug overlays and read its source.',
      ),
      h(
        'a',
        { class: 'card page-card', href: '#/worker', 'data-page': 'worker' },
        h('h2', {}, 'A world in a Web Worker: 2,000 boxes beside a busy page'),
      ),
      h(
        'a',
        { class: 'card page-card', href: '#/physical-ui', 'data-page': 'physical-ui' },
        h('h2', {}, 'Physical UI: a page\u2019s own buttons, falling, thrown, still buttons'),
      ),
      grid,
    ),
  );
  // Pictures one per task, so the page answers taps while they are made.
  let cancelled = false;
  const next = (index: number): void => {
    if (cancelled || index >= pending.length) return;
    const { scene, canvas } = pending[index]!;
    const world = scene.build(sceneValues(scene));
    for (let i = 0; i < Math.min(THUMBNAIL_STEPS, scene.steps); i++) world.step(STEP);
    canvas.styleFor = sceneStyleFor(scene);
    // A camera that follows a body frames the picture where that body has gone.
    canvas.setAttribute('view-box', viewBoxAttribute(sceneView(scene, world)));
    canvas.world = world;
    setTimeout(() => next(index + 1), 0);
  };
  setTimeout(() => next(0), 0);
  return () => {
    cancelled = true;
  };
}

/** A scene's camera as a `view-box` attribute. */
export function cameraAttribute(scene: Scene): string {
  return viewBoxAttribute(scene.camera);
}

/** A world rectangle as a `view-box` attribute. */
export function viewBoxAttribute({ x, y, width, height }: SceneView): string {
  return `${x} ${y} ${width} ${height}`;
}
