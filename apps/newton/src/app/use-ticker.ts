import { useEffect, useReducer } from 'react';

/** Re-renders the component every `ms` while `active`: live readouts without 60 renders a second. */
export function useTicker(active: boolean, ms = 100): void {
  const [, tick] = useReducer((count: number) => count + 1, 0);
  useEffect(() => {
    if (!active) return;
    const id = setInterval(tick, ms);
    return () => clearInterval(id);
  }, [active, ms]);
}
