// Material Design icons (Apache 2.0), as path data.
export const ICONS = {
  back: 'M20 11H7.83l5.59-5.59L12 4l-8 8 8 8 1.41-1.41L7.83 13H20v-2z',
  play: 'M8 5v14l11-7z',
  pause: 'M6 19h4V5H6v14zm8-14v14h4V5h-4z',
  step: 'M6 18l8.5-6L6 6v12zM16 6v12h2V6h-2z',
  reset:
    'M12 5V1L7 6l5 5V7c3.31 0 6 2.69 6 6s-2.69 6-6 6-6-2.69-6-6H4c0 4.42 3.58 8 8 8s8-3.58 8-8-3.58-8-8-8z',
  slow: 'M13.05 9.79 10 7.5v9l3.05-2.29L16 12zM11 4.07V2.05a9.9 9.9 0 0 0-5.32 2.21L7.1 5.69A7.9 7.9 0 0 1 11 4.07zM5.69 7.1 4.26 5.68A9.9 9.9 0 0 0 2.05 11h2.02a7.9 7.9 0 0 1 1.62-3.9zM4.07 13H2.05a9.9 9.9 0 0 0 2.21 5.32l1.43-1.43A7.9 7.9 0 0 1 4.07 13zm1.61 6.74A10 10 0 0 0 11 21.95v-2.02a7.9 7.9 0 0 1-3.9-1.62zM22 12c0 5.16-3.92 9.42-8.95 9.95v-2.02C16.97 19.41 20 16.05 20 12s-3.03-7.41-6.95-7.93V2.05C18.08 2.58 22 6.84 22 12z',
} as const;

/** An inline SVG icon. */
export function icon(name: keyof typeof ICONS): string {
  return `<svg viewBox="0 0 24 24" aria-hidden="true"><path d="${ICONS[name]}"/></svg>`;
}
