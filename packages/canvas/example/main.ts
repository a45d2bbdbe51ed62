// A falling pile with the overlays: `npm run example -w @physical/canvas`.
import { World, box, particle, wall } from '@physical/engine';
import { define, drawArrow } from '@physical/canvas';

define();
const canvas = document.querySelector('physical-canvas')!;
const world = new World();
world.add(wall({ from: { x: 0, y: 10 }, to: { x: 16, y: 10 } }));
world.add(wall({ from: { x: 0, y: 0 }, to: { x: 0, y: 10 } }));
world.add(wall({ from: { x: 16, y: 0 }, to: { x: 16, y: 10 } }));
for (let i = 0; i < 60; i++) {
  const position = { x: 3 + (i % 10) * 1.05, y: 1 + Math.floor(i / 10) * 1.1 };
  world.add(
    i % 3 === 0
      ? particle({ position, radius: 0.4, restitution: 0.3 })
      : box({ position, width: 0.8, height: 0.8, angle: i * 0.3 }),
  );
}
canvas.world = world;

canvas.addEventListener('bodytap', ({ detail }) => {
  detail.body!.applyImpulse({ x: 0, y: -8 * detail.body!.mass });
});
canvas.addEventListener('backgroundtap', ({ detail }) => {
  const body = world.add(box({ position: detail.point, width: 0.8, height: 0.8 }));
  canvas.setStyle(body, { fill: '#ff8a65', label: 'new' });
});
// An app overlay: the weight of every awake body, as a force arrow.
canvas.drawOverlay = (context, element) => {
  for (const body of world.bodies) {
    if (!body.isAwake) continue;
    drawArrow(
      context,
      element.viewport.scale,
      body.centerOfMass,
      { x: 0, y: body.mass * 9.81 * 0.05 },
      { kind: 'force', width: 1.5, opacity: 0.6 },
    );
  }
};
document.querySelector<HTMLInputElement>('#debug')!.onchange = (event) => {
  canvas.debug = (event.target as HTMLInputElement).checked ? 'all' : '';
};
document.querySelector<HTMLInputElement>('#slow')!.onchange = (event) => {
  canvas.timeScale = (event.target as HTMLInputElement).checked ? 0.2 : 1;
};
const pausedBox = document.querySelector<HTMLInputElement>('#paused')!;
pausedBox.onchange = () => {
  canvas.paused = pausedBox.checked;
};
canvas.addEventListener('pausechange', ({ detail }) => {
  pausedBox.checked = detail.paused;
});
