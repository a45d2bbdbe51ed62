import { define } from '@physical/canvas';
import { findScene } from '@physical/scenes';
import { renderList } from './list-page.ts';
import { renderSample } from './sample-page.ts';

define();
const root = document.getElementById('app')!;
let leave: () => void = () => {};

/** `#/` is the list, `#/<sample id>` a sample. */
function route(): void {
  leave();
  const id = decodeURIComponent(location.hash.replace(/^#\/?/, ''));
  const scene = id === '' ? undefined : findScene(id);
  leave = scene === undefined ? renderList(root) : renderSample(root, scene);
  window.scrollTo(0, 0);
  document.documentElement.dataset['ready'] = 'true';
}

window.addEventListener('hashchange', route);
route();
