import { useMemo } from 'react';
import { World, box, wall } from '@physical/engine';
import { PhysicalCanvas } from '@physical/react';

export function Pile() {
  const world = useMemo(() => {
    const w = new World();
    w.add(wall({ from: { x: 0, y: -40 }, to: { x: 0, y: 7 } }));
    w.add(wall({ from: { x: 0, y: 7 }, to: { x: 8, y: 7 } }));
    w.add(wall({ from: { x: 8, y: 7 }, to: { x: 8, y: -40 } }));
    for (let i = 0; i < 40; i++)
      w.add(box({ position: { x: 1 + (i % 6), y: -i }, width: 0.6, height: 0.6 }));
    return w;
  }, []);
  return (
    <PhysicalCanvas
      world={world}
      fit="contain"
      viewBox={{ x: 0, y: 0, width: 8, height: 8 }}
      style={{ height: '100vh' }}
      onBodyTap={({ body }) => body?.applyImpulse({ x: 0, y: -5 })}
    />
  );
}