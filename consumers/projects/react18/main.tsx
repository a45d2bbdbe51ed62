// React 18 (with @types/react@18): the binding's <PhysicalCanvas>. React 18 sets a custom
// element's props as attributes only, so a page on React 18 uses the binding, not the bare tag.
import { worldToScreen, type PhysicalCanvasElement } from '@physical/canvas';
import { World, box, wall } from '@physical/engine';
import { PhysicalCanvas } from '@physical/react';
import { StrictMode, useEffect, useRef } from 'react';
import { createRoot } from 'react-dom/client';
import { expose } from '../shared/expose.ts';

const world = new World();
world.add(wall({ from: { x: 0, y: 5 }, to: { x: 16, y: 5 } }));
const crate = world.add(box({ position: { x: 4, y: 1 }, width: 1, height: 1 }));

let taps = 0;
function App() {
  const ref = useRef<PhysicalCanvasElement>(null);
  // Exposed once mounted: React 18's StrictMode renders twice and commits one render's ref, so a
  // closure made during render may hold the other one (still null).
  useEffect(() => {
    expose(world, crate, () => {
      const canvas = ref.current!;
      const rect = canvas.getBoundingClientRect();
      const point = worldToScreen(canvas.viewport, crate.position);
      return { x: rect.left + point.x, y: rect.top + point.y, taps };
    });
  }, []);
  return (
    <PhysicalCanvas
      ref={ref}
      world={world}
      origin={{ x: 0, y: 0 }}
      paused={false}
      style={{ width: 800, height: 300 }}
      onBodyTap={(detail) => {
        if (detail.body === crate) taps++;
      }}
    />
  );
}

createRoot(document.getElementById('root')!).render(
  <StrictMode>
    <App />
  </StrictMode>,
);
