import type { ReactNode } from 'react';
import { useTicker } from './use-ticker.ts';

/** Props of {@link Live}. */
export interface LiveProps {
  /** Ticks while true (the screen is shown and running). */
  readonly active: boolean;
  /** Milliseconds between two looks. Default 100. */
  readonly ms?: number;
  /**
   * What the content shows, as a short text: it re-renders only when this changed since the
   * last look (nothing renders at rest). Without it, every tick re-renders.
   */
  readonly watch?: () => string;
  /** The live content, read afresh at each render. */
  readonly children: () => ReactNode;
}

/**
 * A live part of a screen: re-renders on its own ticker, so a readout that changes ten times a
 * second re-renders itself, not the whole screen around it (a screen's tree of MUI components
 * re-rendered ten times a second took most of a slow phone's frame with 50 particles).
 */
export function Live({ active, ms = 100, watch, children }: LiveProps) {
  useTicker(active, ms, watch);
  return <>{children()}</>;
}
