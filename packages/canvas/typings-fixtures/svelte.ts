// Compile test: <physical-canvas> in Svelte 5 templates through `@physical/canvas/svelte`: the
// attributes svelte-check checks a template against.
import '@physical/canvas/svelte';
import { World } from '@physical/engine';
import type { SvelteHTMLElements } from 'svelte/elements';

type Props = SvelteHTMLElements['physical-canvas'];

export const ok: Props = {
  world: new World(),
  fit: 'contain',
  class: 'stage',
  onbodytap: (event) => {
    const body = event.detail.body;
    void body;
  },
};

// @ts-expect-error: not a fit mode
export const badFit: Props = { fit: 'sideways' };
