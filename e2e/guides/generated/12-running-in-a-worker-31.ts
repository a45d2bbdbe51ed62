import { define } from '@physical/canvas';
import { WorkerWorld } from '@physical/worker';

define();
const world = new WorkerWorld(
  new Worker(new URL('./physics.worker.ts', import.meta.url), { type: 'module' }),
);
world.add({ kind: 'wall', from: { x: 0, y: 7 }, to: { x: 10, y: 7 } });
const crate = world.add({ kind: 'box', width: 1, height: 1, position: { x: 5, y: 2 } });
const hinge = world.add({
  kind: 'box',
  type: 'static',
  width: 0.2,
  height: 0.2,
  position: { x: 2, y: 2 },
});
const arm = world.add({ kind: 'capsule', length: 1.5, radius: 0.1, position: { x: 2.75, y: 2 } });
world.addJoint({ kind: 'revolute', bodyA: hinge, bodyB: arm, anchor: { x: 2, y: 2 } });

world.applyForce(crate, { x: 20, y: 0 }, { duration: 0.5 }); // 20 N for half a second
world.applyImpulse(arm, { x: 0, y: -1 });
world.setLinearVelocity(crate, { x: 0, y: -3 });
world.gravity = { x: 0, y: 4 };

document.querySelector('physical-canvas')!.world = world; // drawn, stepped, draggable