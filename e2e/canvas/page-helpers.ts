import type { Page } from 'playwright-core';

/** Waits for `count` animation frames in the page (real ones, whatever the element does). */
export async function waitFrames(page: Page, count = 2): Promise<void> {
  await page.evaluate(
    (frames) =>
      new Promise<void>((resolve) => {
        let left = frames;
        const tick = (): void => {
          if (--left <= 0) resolve();
          else requestAnimationFrame(tick);
        };
        requestAnimationFrame(tick);
      }),
    count,
  );
}

/**
 * RGBA of device pixels as they reach the screen: takes a screenshot at device scale and reads
 * it back through an ImageBitmap in the page (no PNG decoder needed in Node).
 */
export async function screenPixels(
  page: Page,
  points: readonly { x: number; y: number }[],
): Promise<number[][]> {
  const png = await page.screenshot({ scale: 'device', type: 'png' });
  return page.evaluate(
    async ({ base64, points }) => {
      const bytes = Uint8Array.from(atob(base64), (c) => c.charCodeAt(0));
      const bitmap = await createImageBitmap(new Blob([bytes], { type: 'image/png' }));
      const canvas = new OffscreenCanvas(bitmap.width, bitmap.height);
      const context = canvas.getContext('2d')!;
      context.drawImage(bitmap, 0, 0);
      return points.map(({ x, y }) => Array.from(context.getImageData(x, y, 1, 1).data));
    },
    { base64: png.toString('base64'), points },
  );
}

/** Sets up a scene in the page and returns nothing; the code runs with `window.physical`. */
export const RAF_COUNTER = `
  window.frameRequests = 0;
  const original = window.requestAnimationFrame.bind(window);
  window.requestAnimationFrame = (callback) => { window.frameRequests++; return original(callback); };
`;
