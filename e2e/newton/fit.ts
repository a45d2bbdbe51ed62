// What "fits the phone" means, checked in the page: shared by the fit spec and the screenshot
// script. The document is exactly the viewport (nothing scrolls the page), and every control one
// can see is reachable: at its centre, `document.elementFromPoint` is the control or inside it.
import type { BrowserContextOptions, Page } from 'playwright-core';

/** The phones schools have (CSS px, portrait). */
export const PHONES: readonly (readonly [number, number])[] = [
  [320, 568],
  [360, 640],
  [375, 667],
  [390, 844],
  [412, 915],
  [430, 932],
];

export const SCREENS = ['inertia', 'forces', 'reactions'] as const;

/** A phone's context: touch, 3 device pixels per CSS px, portrait or turned sideways. */
export function phoneOptions(
  width: number,
  height: number,
  landscape: boolean,
): BrowserContextOptions {
  return {
    viewport: landscape ? { width: height, height: width } : { width, height },
    deviceScaleFactor: 3,
    isMobile: true,
    hasTouch: true,
    locale: 'en-US',
    serviceWorkers: 'allow',
  };
}

/**
 * iOS asks before it reports the device's tilt: this makes Chromium look like it, so Reactions
 * shows its "Use device tilt" button (the longest label on that screen).
 */
export const TILT_PERMISSION =
  "DeviceOrientationEvent.requestPermission = () => Promise.resolve('granted');";

/**
 * The actions a learner must reach without scrolling: the screen's main buttons, the
 * simulation controls and the navigation.
 */
export const PRIMARY = [
  '[data-action="change-force"]',
  '[data-action="toggle-force"]',
  '[data-action="return"]',
  '[data-action="start"]',
  '[data-action="play"]',
  '[data-action="reset"]',
  '[data-nav]',
];

/** What is wrong with the fit of the page as it stands (empty when it fits). */
export async function fitProblems(page: Page): Promise<string[]> {
  return page.evaluate((primary) => {
    /** CSS px a navigation label keeps from its button's top and bottom edges. */
    const navMargin = 2;
    const problems: string[] = [];
    const root = document.documentElement;
    const width = window.innerWidth;
    const height = window.innerHeight;
    if (root.scrollWidth !== width || root.scrollHeight !== height) {
      problems.push(
        `the document is ${root.scrollWidth}x${root.scrollHeight} in a ${width}x${height} viewport`,
      );
    }
    const describe = (element: Element | null): string => {
      if (element === null) return 'nothing';
      const label =
        element.getAttribute('aria-label') ??
        element.getAttribute('data-action') ??
        element.getAttribute('data-nav') ??
        element.getAttribute('data-readout') ??
        (element.textContent ?? '').trim().slice(0, 30);
      return `<${element.tagName.toLowerCase()} class="${String(element.className).slice(0, 40)}"> "${label}"`;
    };
    const shown = (element: Element): boolean => {
      const rect = element.getBoundingClientRect();
      if (rect.width === 0 && rect.height === 0) return false;
      for (let node: Element | null = element; node !== null; node = node.parentElement) {
        const style = getComputedStyle(node);
        if (style.display === 'none' || style.visibility === 'hidden' || style.opacity === '0') {
          // A switch's native input is transparent on purpose, over the switch one sees.
          if (node === element && element instanceof HTMLInputElement) continue;
          return false;
        }
      }
      return true;
    };
    const selector =
      'button, a[href], input:not([type="hidden"]), select, textarea, [role="button"], ' +
      '[role="slider"], [role="switch"], [role="tab"], [role="checkbox"], [role="radio"]';
    for (const control of document.querySelectorAll(selector)) {
      if (!shown(control)) continue;
      // MUI hides a slider's native input (clipped to nothing) inside the thumb one sees and drags.
      let target: Element = control;
      let rect = target.getBoundingClientRect();
      const hidden = getComputedStyle(target).clip.startsWith('rect');
      if ((hidden || rect.width <= 2 || rect.height <= 2) && target.parentElement !== null) {
        target = target.parentElement;
        rect = target.getBoundingClientRect();
      }
      const x = rect.left + rect.width / 2;
      const y = rect.top + rect.height / 2;
      const name = describe(control);
      // Scrolled out of a panel that scrolls is not shown until scrolled to; clipped by a box
      // that does not scroll, or by the window, it cannot be reached at all.
      let away = false;
      for (let node = target.parentElement; node !== null; node = node.parentElement) {
        const style = getComputedStyle(node);
        if (style.overflowX === 'visible' && style.overflowY === 'visible') continue;
        const box = node.getBoundingClientRect();
        if (x >= box.left && x <= box.right && y >= box.top && y <= box.bottom) continue;
        if (/auto|scroll/.test(style.overflowY + style.overflowX) && node !== root) away = true;
        else problems.push(`${name} is clipped by ${describe(node)}`);
        break;
      }
      if (away) {
        if (primary.some((css) => control.matches(css))) {
          problems.push(`${name} is hidden until its panel is scrolled`);
        }
        continue;
      }
      if (x < 0 || y < 0 || x >= width || y >= height) {
        problems.push(`${name} is off screen (centre ${Math.round(x)}, ${Math.round(y)})`);
        continue;
      }
      const hit = document.elementFromPoint(x, y);
      // A disabled button lets taps through (pointer-events: none) to what holds it.
      const through = getComputedStyle(target).pointerEvents === 'none';
      // MUI draws a native input's visible part around it (a slider's thumb holds its input).
      const drawnAround = target instanceof HTMLInputElement && hit === target.parentElement;
      const reached =
        hit !== null &&
        (hit === target ||
          target.contains(hit) ||
          drawnAround ||
          (through && hit.contains(target)));
      if (!reached) {
        problems.push(
          `${name} is covered by ${describe(hit)} at (${Math.round(x)}, ${Math.round(y)})`,
        );
      }
    }
    // A rail, bottom bar or tab label is whole: not cut with an ellipsis (its text wider than its
    // box) nor running past its button ("Wechselwirkung" in a 72 px rail in landscape).
    for (const control of document.querySelectorAll('[data-nav], [role="tab"]')) {
      if (!shown(control)) continue;
      const box = control.getBoundingClientRect();
      for (const part of control.querySelectorAll('*')) {
        const text = [...part.childNodes]
          .filter((node) => node.nodeType === Node.TEXT_NODE)
          .map((node) => node.textContent ?? '')
          .join('')
          .trim();
        if (text === '' || !shown(part)) continue;
        const rect = part.getBoundingClientRect();
        if (part.clientWidth > 0 && part.scrollWidth > part.clientWidth) {
          problems.push(
            `the label "${text}" of ${describe(control)} is cut (${part.scrollWidth} > ${part.clientWidth} px)`,
          );
        } else if (rect.left < box.left - 0.5 || rect.right > box.right + 0.5) {
          problems.push(
            `the label "${text}" of ${describe(control)} runs past it (${Math.round(rect.width)} px in ${Math.round(box.width)} px)`,
          );
        } else if (
          control.hasAttribute('data-nav') &&
          (rect.top < box.top + navMargin || rect.bottom > box.bottom - navMargin)
        ) {
          // A label that wraps to a second line must still sit inside its button, clear of the
          // screen's bottom edge ("Wechsel-wirkung" at 320x568 ran 4 px past it).
          problems.push(
            `the label "${text}" of ${describe(control)} is not inside it with ${navMargin} px to spare (${Math.round(rect.top)} to ${Math.round(rect.bottom)} px in ${Math.round(box.top)} to ${Math.round(box.bottom)} px)`,
          );
        }
      }
    }
    // A readout's text stays in its box: none runs under a button or off the screen.
    for (const value of document.querySelectorAll('[data-readout]')) {
      if (!shown(value)) continue;
      if (value.scrollWidth > value.clientWidth + 1 && value.clientWidth > 0) {
        problems.push(
          `${describe(value)} overflows its box (${value.scrollWidth} > ${value.clientWidth} px)`,
        );
      }
    }
    return problems;
  }, PRIMARY);
}

/** Shows a screen through the navigation, and waits for it. */
export async function showScreen(page: Page, screen: string): Promise<void> {
  await page.locator(`[data-nav="${screen}"]`).first().click();
  await page.waitForSelector(`#${screen} physical-canvas`, { state: 'visible' });
}

/** Switches the language with the app bar's toggle. */
export async function chooseLocale(page: Page, locale: 'en' | 'de'): Promise<void> {
  await page.locator(`[data-locale="${locale}"]`).click();
  await page.waitForFunction((lang) => document.documentElement.lang === lang, locale);
}

/**
 * Records the boxes of the text each canvas draws in its latest frame (`canvas.__texts`, in the
 * canvas's device pixels): run before the page's scripts. A frame starts with a clear of the whole
 * canvas (physical-canvas's drawScene), which starts a new list.
 */
export const RECORD_CANVAS_TEXT = `
  (() => {
    const proto = CanvasRenderingContext2D.prototype;
    const clearRect = proto.clearRect;
    proto.clearRect = function (x, y, w, h) {
      if (x === 0 && y === 0 && w >= this.canvas.width && h >= this.canvas.height) this.canvas.__texts = [];
      return clearRect.call(this, x, y, w, h);
    };
    const fillText = proto.fillText;
    proto.fillText = function (text, x, y, maxWidth) {
      const m = this.measureText(text);
      const t = this.getTransform();
      const list = this.canvas.__texts ?? (this.canvas.__texts = []);
      list.push({
        text: String(text),
        left: t.a * (x - m.actualBoundingBoxLeft) + t.e,
        right: t.a * (x + m.actualBoundingBoxRight) + t.e,
        top: t.d * (y - m.actualBoundingBoxAscent) + t.f,
        bottom: t.d * (y + m.actualBoundingBoxDescent) + t.f,
      });
      return fillText.call(this, text, x, y, maxWidth);
    };
  })();
`;

/** A text box a canvas drew (see {@link RECORD_CANVAS_TEXT}), in its device pixels. */
export interface CanvasText {
  readonly text: string;
  readonly left: number;
  readonly right: number;
  readonly top: number;
  readonly bottom: number;
}

/** The text boxes each Forces track's canvas drew in its latest frame, by track name. */
export async function trackTexts(page: Page): Promise<Record<string, CanvasText[]>> {
  return page.evaluate(() => {
    const result: Record<string, CanvasText[]> = {};
    for (const track of document.querySelectorAll('#forces [data-track]')) {
      const canvas = track.querySelector('physical-canvas')?.shadowRoot?.querySelector('canvas') as
        (HTMLCanvasElement & { __texts?: CanvasText[] }) | null | undefined;
      result[track.getAttribute('data-track')!] = [...(canvas?.__texts ?? [])];
    }
    return result;
  });
}
