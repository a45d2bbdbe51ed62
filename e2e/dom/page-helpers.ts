import type { Page } from 'playwright-core';
import type { PhysicalUI } from '@physical/dom';

declare global {
  interface Window {
    ui: PhysicalUI;
  }
}

/** Where the container's padding box and each physical element are (client px), with state. */
export interface Boxes {
  container: {
    left: number;
    top: number;
    right: number;
    bottom: number;
    width: number;
    height: number;
  };
  elements: {
    id: string;
    text: string;
    x: number;
    y: number;
    state: string | null;
    transform: string;
    bodyMinX: number;
    bodyMaxX: number;
    bodyMinY: number;
    bodyMaxY: number;
  }[];
}

/** Reads the container and every physical element (their centres, bodies' boxes in px). */
export function boxes(page: Page): Promise<Boxes> {
  return page.evaluate(() => {
    const ui = window.ui;
    const container = ui.container;
    const rect = container.getBoundingClientRect();
    const left = rect.left + container.clientLeft;
    const top = rect.top + container.clientTop;
    const ppm = ui.pixelsPerMeter;
    return {
      container: {
        left,
        top,
        right: left + container.clientWidth,
        bottom: top + container.clientHeight,
        width: container.clientWidth,
        height: container.clientHeight,
      },
      elements: ui.elements.map((element) => {
        const box = element.getBoundingClientRect();
        const bounds = ui.bodyOf(element)!.shapes[0]!.getBounds();
        return {
          id: element.id,
          text: element.textContent ?? '',
          x: box.left + box.width / 2,
          y: box.top + box.height / 2,
          state: element.dataset['physical'] ?? null,
          transform: element.style.transform,
          bodyMinX: bounds.minX * ppm,
          bodyMaxX: bounds.maxX * ppm,
          bodyMinY: bounds.minY * ppm,
          bodyMaxY: bounds.maxY * ppm,
        };
      }),
    };
  });
}

/** Waits until the UI stops requesting frames (every body asleep, nothing returning). */
export async function waitSettled(page: Page, timeout = 15_000): Promise<void> {
  await page.waitForFunction(() => !window.ui.isRunning, undefined, { timeout, polling: 100 });
}
