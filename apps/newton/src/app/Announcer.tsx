import { Box } from '@mui/material';
import { useCallback, useEffect, useRef, useState, type ReactElement } from 'react';

/** Shortest time between two announcements (ms): a screen reader finishes a short sentence. */
export const ANNOUNCE_GAP_MS = 1500;

/**
 * A polite live region that speaks at a human pace: messages wait their turn, at least
 * {@link ANNOUNCE_GAP_MS} apart, and only the newest two waiting are kept (a burst of
 * collisions becomes one sentence, not a stream).
 */
export function useAnnouncer(name: string): {
  announce: (message: string) => void;
  region: ReactElement;
} {
  const [text, setText] = useState('');
  const queue = useRef<string[]>([]);
  const lastAt = useRef(-Infinity);
  const timer = useRef<ReturnType<typeof setTimeout> | null>(null);

  const flush = useCallback((): void => {
    timer.current = null;
    const next = queue.current.shift();
    if (next === undefined) return;
    lastAt.current = performance.now();
    setText(next);
    if (queue.current.length > 0) timer.current = setTimeout(flush, ANNOUNCE_GAP_MS);
  }, []);

  const announce = useCallback(
    (message: string): void => {
      queue.current = [...queue.current.filter((item) => item !== message), message].slice(-2);
      if (timer.current !== null) return;
      const wait = Math.max(0, lastAt.current + ANNOUNCE_GAP_MS - performance.now());
      timer.current = setTimeout(flush, wait);
    },
    [flush],
  );

  useEffect(
    () => () => {
      if (timer.current !== null) clearTimeout(timer.current);
    },
    [],
  );

  const region = (
    <Box
      role="status"
      aria-live="polite"
      aria-atomic="true"
      data-announcer={name}
      sx={{
        position: 'absolute',
        width: 1,
        height: 1,
        overflow: 'hidden',
        clip: 'rect(0 0 0 0)',
        whiteSpace: 'nowrap',
      }}
    >
      {text}
    </Box>
  );
  return { announce, region };
}
