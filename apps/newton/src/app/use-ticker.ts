import { useEffect, useReducer, useRef } from 'react';

/**
 * Re-renders the component every `ms` while `active`: live readouts without 60 renders a second.
 * With `key`, only when the key changed since the last render (nothing renders at rest).
 */
export function useTicker(active: boolean, ms = 100, key?: () => string): void {
  const [, tick] = useReducer((count: number) => count + 1, 0);
  const keyRef = useRef(key);
  keyRef.current = key;
  useEffect(() => {
    if (!active) return;
    let last = keyRef.current?.() ?? '';
    const id = setInterval(() => {
      const read = keyRef.current;
      if (read === undefined) {
        tick();
        return;
      }
      const next = read();
      if (next !== last) {
        last = next;
        tick();
      }
    }, ms);
    return () => clearInterval(id);
  }, [active, ms]);
}
