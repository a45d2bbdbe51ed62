import { useEffect, useLayoutEffect, useRef } from 'react';

/** Props of {@link LiveText}. */
export interface LiveTextProps {
  /** Looks while true (the screen is shown): a step taken while paused shows too. */
  readonly active: boolean;
  /** Milliseconds between two looks. Default 200: five a second, as fast as anyone reads. */
  readonly ms?: number;
  /** The text as it is now. */
  readonly text: () => string;
}

/**
 * A live value as a bare text node, rewritten in place: a look every `ms` writes the text when
 * it changed, and nothing re-renders. With 50 particles on a slow phone a React render of the
 * readouts ten times a second (MUI's styled boxes around each value) cost more main-thread
 * time than the frames it came between.
 */
export function LiveText({ active, ms = 200, text }: LiveTextProps) {
  const node = useRef<HTMLSpanElement | null>(null);
  const read = useRef(text);
  read.current = text;
  const write = (): void => {
    const element = node.current;
    if (element === null) return;
    const next = read.current();
    // The text node's own value, where there is one: setting `textContent` puts a new node in
    // place of the old, which the page then restyles as well as lays out.
    const only = element.firstChild;
    if (only !== null && only === element.lastChild && only.nodeType === Node.TEXT_NODE) {
      if (only.nodeValue !== next) only.nodeValue = next;
    } else if (element.textContent !== next) element.textContent = next;
  };
  // After each render of the screen around it (a tap, a step while paused): the text of now.
  useLayoutEffect(write);
  useEffect(() => {
    if (!active) return;
    const id = setInterval(write, ms);
    return () => clearInterval(id);
    // `write` reads refs only.
  }, [active, ms]);
  return <span ref={node}>{text()}</span>;
}
