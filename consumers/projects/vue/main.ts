// Vue 3: the tag with a property (`world`) and an event (`bodytap`), typed by `@physical/canvas/vue`.
import '@physical/canvas/define';
import '@physical/canvas/vue';
import { worldToScreen } from '@physical/canvas';
import { World, box, wall } from '@physical/engine';
import { createApp, h, type GlobalComponents } from 'vue';
import { expose } from '../shared/expose.ts';

type CanvasProps = InstanceType<GlobalComponents['physical-canvas']>['$props'];

const world = new World();
world.add(wall({ from: { x: 0, y: 5 }, to: { x: 16, y: 5 } }));
const crate = world.add(box({ position: { x: 4, y: 1 }, width: 1, height: 1 }));
let taps = 0;
const props: CanvasProps = {
  world,
  onBodytap: (event) => {
    if (event.detail.body === crate) taps++;
  },
};

createApp({
  render: () => h('physical-canvas', { ...props, style: { width: '800px', height: '300px' } }),
}).mount('#app');
expose(world, crate, () => {
  const canvas = document.querySelector('physical-canvas')!;
  const rect = canvas.getBoundingClientRect();
  const point = worldToScreen(canvas.viewport, crate.position);
  return { x: rect.left + point.x, y: rect.top + point.y, taps };
});
