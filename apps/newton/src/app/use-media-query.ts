import { useSyncExternalStore } from 'react';

/**
 * Whether a media query matches now, re-rendering when that changes (the first screen's own
 * hook: MUI's `useMediaQuery` would bring its styling engine).
 */
export function useMediaQuery(query: string): boolean {
  return useSyncExternalStore(
    (changed) => {
      const list = matchMedia(query);
      list.addEventListener('change', changed);
      return () => list.removeEventListener('change', changed);
    },
    () => matchMedia(query).matches,
  );
}
