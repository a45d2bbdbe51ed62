// Compile test: <physical-canvas> in Vue templates through `@physical/canvas/vue`: the props
// vue-tsc checks a template against.
import '@physical/canvas/vue';
import { World } from '@physical/engine';
import type { GlobalComponents } from 'vue';

type Props = InstanceType<GlobalComponents['physical-canvas']>['$props'];

export const ok: Props = {
  world: new World(),
  fit: 'cover',
  'pixels-per-meter': 40,
  onBodytap: (event) => {
    const y: number = event.detail.point.y;
    void y;
  },
};

// @ts-expect-error: not a fit mode
export const badFit: Props = { fit: 'sideways' };

// @ts-expect-error: a boolean
export const badPaused: Props = { paused: 'yes please' };
