// React 19: the binding's <PhysicalCanvas> (no @physical/dom installed is needed for it), and
// the bare tag typed by `@physical/canvas/jsx`.
import '@physical/canvas/jsx';
import { worldToScreen, type PhysicalCanvasElement } from '@physical/canvas';
import { World, box, wall } from '@physical/engine';
import { PhysicalCanvas } from '@physical/react';
import { useRef } from 'react';
import { createRoot } from 'react-dom/client';
import { expose } from '../shared/expose.ts';

const world = new World();
world.add(wall({ from: { x: 0, y: 5 }, to: { x: 16, y: 5 } }));
const crate = world.add(box({ position: { x: 4, y: 1 }, width: 1, height: 1 }));
const still = new World();

let taps = 0;
function App() {
  const ref = useRef<PhysicalCanvasElement>(null);
  expose(world, crate, () => {
    const canvas = ref.current!;
    const rect = canvas.getBoundingClientRect();
    const point = worldToScreen(canvas.viewport, crate.position);
    return { x: rect.left + point.x, y: rect.top + point.y, taps };
  });
  return (
    <>
      <PhysicalCanvas
        ref={ref}
        world={world}
        style={{ width: 800, height: 300 }}
        onBodyTap={(detail) => {
          if (detail.body === crate) taps++;
        }}
      />
      <physical-canvas world={still} paused style={{ width: 100, height: 50 }} />
    </>
  );
}

createRoot(document.getElementById('root')!).render(<App />);
