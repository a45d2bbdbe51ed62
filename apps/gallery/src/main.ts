import { define } from '@physical/canvas';
import { findScene } from '@physical/scenes';
import { renderList } from './list-page.ts';
import { PHYSICAL_UI_ROUTE, renderPhysicalUI } from './physical-ui-page.ts';
import { renderSample } from './sample-page.ts';
import { WORKER_ROUTE, renderWorkerPage } from './worker-page.ts';

define();
const root = document.getElementById('app')!;
let leave: () => void = () => {};

/** `#/` is the list, `#/<sample id>` a sample, `#/physical-ui` the Physical UI showcase. */
function route(): void {
  leave();
  const id = decodeURIComponent(location.hash.replace(/^#\/?/, ''));
  const scene = id === '' ? undefined : findScene(id);
  if (id === PHYSICAL_UI_ROUTE) leave = renderPhysicalUI(root);
  else if (id === WORKER_ROUTE) leave = renderWorkerPage(root);
  else leave = scene === undefined ? renderList(root) : renderSample(root, scene);
  window.scrollTo(0, 0);
  document.documentElement.dataset['ready'] = 'true';
}

window.addEventListener('hashchange', route);
route();
