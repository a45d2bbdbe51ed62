// The showcase is the dom package's own example module, mounted here as it is (not a copy).
import { mountShowcase } from '../../../packages/dom/examples/showcase.ts';
import { h } from './dom.ts';
import { icon } from './icons.ts';

/** The route of the Physical UI page. */
export const PHYSICAL_UI_ROUTE = 'physical-ui';

/**
 * Physical UI: the page's own chips and buttons as bodies (@physical/dom). Tap a chip and it
 * falls; drag and throw anything; the buttons still count; "Back to layout" springs them home.
 */
export function renderPhysicalUI(root: HTMLElement): () => void {
  document.title = 'Physical UI';
  const back = h('a', { class: 'icon-button back', href: '#/', 'aria-label': 'All samples' });
  back.innerHTML = icon('back');
  const stage = h('div', { class: 'physical-ui' });
  root.replaceChildren(
    h('header', { class: 'app-bar' }, back, h('h1', {}, 'Physical UI')),
    h(
      'div',
      { class: 'content' },
      h(
        'p',
        { class: 'intro' },
        'These are ordinary buttons: only their CSS transform moves. Tap a chip and it falls ' +
          'into the box, drag anything and throw it, and the buttons still count their clicks.',
      ),
      stage,
    ),
  );
  const ui = mountShowcase(stage);
  return () => ui.destroy();
}
