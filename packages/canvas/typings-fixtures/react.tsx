// Compile test: <physical-canvas> in React 19 JSX through `@physical/canvas/jsx`.
import '@physical/canvas/jsx';
import { World } from '@physical/engine';

const world = new World();

export const ok = (
  <physical-canvas
    world={world}
    fit="contain"
    viewBox={{ x: 0, y: 0, width: 10, height: 6 }}
    drag={false}
    time-scale={0.5}
    style={{ height: 240 }}
    onbodytap={(event) => {
      const x: number = event.detail.point.x;
      void x;
    }}
  />
);

// @ts-expect-error: not a fit mode
export const badFit = <physical-canvas world={world} fit="sideways" />;

// @ts-expect-error: a world, not a number
export const badWorld = <physical-canvas world={3} />;
