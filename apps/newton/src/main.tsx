import { StrictMode } from 'react';
import { createRoot } from 'react-dom/client';
import { App } from './app/App.tsx';
import { SCREEN_MODULES, type FirstScreen } from './app/screen-modules.ts';
import { screenFromHash } from './app/screens.ts';

// Offline: the service worker precaches the built app (production builds only). Listened for
// before the first screen's code is awaited below: the page's load may come meanwhile.
if (import.meta.env.PROD && 'serviceWorker' in navigator) {
  window.addEventListener('load', () => {
    navigator.serviceWorker.register('./sw.js').catch(() => {
      // No service worker (private mode, file://): the app still works online.
    });
  });
}

// The first screen's code (already on its way: the page preloads it) before the first render:
// the app then renders once, the screen included, instead of a fallback and then the screen
// (which React reveals no sooner than 300 ms after the fallback). The page's own shell shows
// meanwhile. Should its code not load, the app renders without it (the screen retries lazily).
const id = screenFromHash(location.hash);
const first: FirstScreen | undefined = await SCREEN_MODULES[id]().then(
  (Component) => ({ id, Component }),
  () => undefined,
);

createRoot(document.getElementById('root')!).render(
  <StrictMode>
    <App first={first} />
  </StrictMode>,
);
