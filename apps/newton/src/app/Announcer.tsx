import { useCallback, useEffect, useMemo, useRef, useState, type ReactElement } from 'react';
import { AnnouncementQueue, type Announcement } from './announcement-queue.ts';
import { playEventTone } from './sound.ts';

/** Shortest time between two announcements (ms): a screen reader finishes a short sentence. */
export const ANNOUNCE_GAP_MS = 1500;

/**
 * A polite live region that speaks at a human pace: messages wait their turn, at least
 * {@link ANNOUNCE_GAP_MS} apart, and only the newest two waiting are kept (a burst of
 * collisions becomes one sentence, not a stream). An `urgent` message (the answer to the user's
 * own action, such as "the box is full") goes before the others and is not pushed out by them.
 */
export function useAnnouncer(name: string): {
  announce: (message: Announcement, urgent?: boolean) => void;
  region: ReactElement;
} {
  const state = useRef({
    /** The region's setter, while it is on the page. */
    show: null as ((text: string) => void) | null,
    waiting: new AnnouncementQueue(),
    lastAt: -Infinity,
    timer: null as ReturnType<typeof setTimeout> | null,
    /** The text last set, and whether it has reached the page yet. */
    shown: '',
    pending: false,
  });

  // Speaks the next message once the gap since the last one (as it reached the page) is over.
  const pump = useCallback((): void => {
    const current = state.current;
    current.timer = null;
    if (current.waiting.empty) return;
    // The last message has not reached the page yet (a busy frame delays the commit): its gap
    // has not started.
    if (current.pending) {
      current.timer = setTimeout(pump, 50);
      return;
    }
    const wait = current.lastAt + ANNOUNCE_GAP_MS - performance.now();
    if (wait > 0) {
      current.timer = setTimeout(pump, wait);
      return;
    }
    const next = current.waiting.next()!;
    current.lastAt = performance.now();
    // The same text again changes nothing on the page: nothing to wait for.
    current.pending = next !== current.shown && current.show !== null;
    current.shown = next;
    current.show?.(next);
    if (!current.waiting.empty) {
      current.timer = setTimeout(pump, ANNOUNCE_GAP_MS);
    }
  }, []);

  const announce = useCallback(
    (message: Announcement, urgent = false): void => {
      playEventTone();
      const current = state.current;
      current.waiting.push(message, urgent);
      if (current.timer === null) current.timer = setTimeout(pump, 0);
    },
    [pump],
  );

  useEffect(() => {
    const current = state.current;
    return () => {
      if (current.timer !== null) clearTimeout(current.timer);
    };
  }, []);

  // The region keeps the text as its own state: a message re-renders the region alone, not the
  // screen that announces (with 50 particles a screen render for each collision message cost a
  // slow phone a frame or two).
  const region = useMemo(() => <AnnouncerRegion name={name} state={state.current} />, [name]);
  return { announce, region };
}

/** The parts of an announcer's state its region reads and writes. */
interface RegionState {
  show: ((text: string) => void) | null;
  lastAt: number;
  pending: boolean;
}

/** The visually hidden live region of {@link useAnnouncer}, holding the text spoken last. */
function AnnouncerRegion({ name, state }: { name: string; state: RegionState }) {
  const [text, setText] = useState('');
  useEffect(() => {
    state.show = setText;
    return () => {
      state.show = null;
    };
  }, [state]);
  // The gap counts from when the text reached the page (a busy frame delays the commit), and
  // from after the whole commit: a passive effect runs once the commit's task is over, so after
  // a screen reader (or a MutationObserver) has seen the change. A layout effect ran inside the
  // commit, and a long commit then shortened the next gap as the page showed it (1,362 ms
  // between two texts in a loaded CI run).
  useEffect(() => {
    if (text === '') return;
    state.lastAt = performance.now();
    state.pending = false;
  }, [text, state]);
  // Visually hidden, one pixel in size (app.css): a region as tall and wide as the window made
  // the whole page scroll.
  return (
    <div
      role="status"
      aria-live="polite"
      aria-atomic="true"
      data-announcer={name}
      className="visually-hidden"
    >
      {text}
    </div>
  );
}
