import { useEffect, useReducer, useRef } from 'react';

/**
 * Re-renders the component every `ms` while `active`: live readouts without 60 renders a second.
 * With `key`, only when the key differs from the one its last render saw (nothing renders at
 * rest).
 */
export function useTicker(active: boolean, ms = 100, key?: () => string): void {
  const [, tick] = useReducer((count: number) => count + 1, 0);
  const keyRef = useRef(key);
  keyRef.current = key;
  // The key as the last render saw it. Compared with the key at the interval's start instead, a
  // screen whose scene is built just after its first render (the key then '') re-rendered whole
  // once for nothing: on a slow phone, a fifth of the first screen's work before its first tap.
  const renderedRef = useRef<string | undefined>(undefined);
  renderedRef.current = key?.();
  useEffect(() => {
    if (!active) return;
    const id = setInterval(() => {
      const read = keyRef.current;
      if (read === undefined || read() !== renderedRef.current) tick();
    }, ms);
    return () => clearInterval(id);
  }, [active, ms]);
}
