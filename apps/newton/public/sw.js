// Newton's service worker: precaches every built file on install (the list and its version come
// from precache-manifest.js, written by the build), answers from the cache first, and falls back
// to the cached page for navigations (the app, or a teacher page for its own address), so the app
// and its teacher pages reload with the network off after one visit.
// Lookups ignore Vary: `vite preview` (npm start) answers with `Vary: Origin`, and a module
// script's request carries an Origin header the cached copy was not fetched with.
/* global self, caches, fetch, URL, Request, Response */
self.importScripts('./precache-manifest.js');

const { version, files } = self.__PRECACHE;
const CACHE = `newton-${version}`;

self.addEventListener('install', (event) => {
  event.waitUntil(
    caches
      .open(CACHE)
      .then((cache) => cache.addAll(files.map((file) => new Request(file, { cache: 'reload' }))))
      .then(() => self.skipWaiting()),
  );
});

self.addEventListener('activate', (event) => {
  event.waitUntil(
    caches
      .keys()
      .then((keys) =>
        Promise.all(
          keys
            .filter((key) => key.startsWith('newton-') && key !== CACHE)
            .map((key) => caches.delete(key)),
        ),
      )
      .then(() => self.clients.claim()),
  );
});

self.addEventListener('fetch', (event) => {
  const request = event.request;
  if (request.method !== 'GET' || new URL(request.url).origin !== self.location.origin) return;
  if (request.mode === 'navigate') {
    // A page: the network when there is one (updates), else the cached copy of that very page
    // (the teacher pages are pages of their own), and the app for any other address.
    const url = new URL(request.url);
    const page = /\/teacher(\.de)?\.html$/.test(url.pathname) ? url.pathname : null;
    const key = page === null ? './index.html' : new URL(page, self.location.href).href;
    event.respondWith(
      fetch(request)
        .then((response) => {
          if (response.ok) {
            const copy = response.clone();
            caches.open(CACHE).then((cache) => cache.put(key, copy));
          }
          return response;
        })
        .catch(() =>
          caches
            .match(key, { ignoreSearch: true, ignoreVary: true })
            .then((cached) => cached ?? Response.error()),
        ),
    );
    return;
  }
  // Hashed assets and icons: the cache first, then the network (and keep a copy).
  event.respondWith(
    caches.match(request, { ignoreSearch: true, ignoreVary: true }).then(
      (cached) =>
        cached ??
        fetch(request).then((response) => {
          if (response.ok) {
            const copy = response.clone();
            caches.open(CACHE).then((cache) => cache.put(request, copy));
          }
          return response;
        }),
    ),
  );
});
