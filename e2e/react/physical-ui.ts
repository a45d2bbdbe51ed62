// Mounts <PhysicalContainer> under StrictMode (effects mount, unmount and mount again), with
// controls the test drives: release all, add a chip, unmount.
import type { PhysicalUI } from '@physical/dom';
// The e2e server aliases only package entries; Physical UI is the `@physical/react/ui` entry.
import { PhysicalContainer } from '../../packages/react/src/ui.ts';
import { StrictMode, createElement, useRef, useState } from 'react';
import { createRoot } from 'react-dom/client';

const state = { clicks: 0, ready: [] as boolean[], ui: null as PhysicalUI | null };
let setChips: (update: (chips: string[]) => string[]) => void = () => undefined;
let setMounted: (mounted: boolean) => void = () => undefined;

function App() {
  const [chips, updateChips] = useState(['One', 'Two']);
  const [mounted, updateMounted] = useState(true);
  const ui = useRef<PhysicalUI | null>(null);
  setChips = updateChips;
  setMounted = updateMounted;
  if (!mounted) return null;
  return createElement(
    PhysicalContainer,
    {
      ref: ui,
      className: 'box',
      onReady: (value: PhysicalUI | null) => {
        state.ready.push(value !== null);
        state.ui = value;
      },
    },
    createElement(
      'button',
      { id: 'counter', type: 'button', onClick: () => state.clicks++ },
      'Count',
    ),
    ...chips.map((name) => createElement('button', { key: name, type: 'button' }, name)),
  );
}

createRoot(document.getElementById('root')!).render(
  createElement(StrictMode, null, createElement(App)),
);
Object.assign(window, {
  state,
  addChip: (name: string) => setChips((chips) => [...chips, name]),
  removeChip: (name: string) => setChips((chips) => chips.filter((c) => c !== name)),
  unmount: () => setMounted(false),
});
requestAnimationFrame(() => {
  document.documentElement.dataset['ready'] = 'true';
});
