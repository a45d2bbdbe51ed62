import type { ComponentType } from 'react';
import type { ScreenId } from './screens.ts';

/** A screen's component: `active` is true while it is the one shown. */
export type ScreenComponent = ComponentType<{ active: boolean }>;

/**
 * Each screen's code, fetched the first time it is needed: its own chunk, so the first screen
 * paints without the code of the other two.
 */
export const SCREEN_MODULES: Readonly<Record<ScreenId, () => Promise<ScreenComponent>>> = {
  inertia: () =>
    import('../screens/inertia/InertiaScreen.tsx').then((module) => module.InertiaScreen),
  forces: () => import('../screens/forces/ForcesScreen.tsx').then((module) => module.ForcesScreen),
  reactions: () =>
    import('../screens/reactions/ReactionsScreen.tsx').then((module) => module.ReactionsScreen),
};

/** The screen the app opens with, its code already here: it renders without a fallback. */
export interface FirstScreen {
  readonly id: ScreenId;
  readonly Component: ScreenComponent;
}
