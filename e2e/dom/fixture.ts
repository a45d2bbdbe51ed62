// A container for many physical elements: `fill(count)` adds chips, pills, buttons and round
// badges; the tests and the benchmark build a PhysicalUI over them.
import { ManualFrameScheduler } from '@physical/canvas';
import { PhysicalUI } from '@physical/dom';

/** Adds `count` elements of four kinds (chip, pill, button, round badge) to the box. */
function fill(count: number): HTMLElement {
  const box = document.getElementById('box')!;
  for (let i = 0; i < count; i++) {
    const kind = i % 4;
    const element = document.createElement(kind === 2 ? 'button' : 'span');
    element.className = kind === 1 ? 'pill' : kind === 3 ? 'round' : '';
    element.textContent = kind === 3 ? String(i % 10) : `item ${i}`;
    box.append(element);
  }
  return box;
}

const dom = { PhysicalUI, ManualFrameScheduler, fill };
declare global {
  interface Window {
    dom: typeof dom;
  }
}
window.dom = dom;
document.documentElement.dataset['ready'] = 'true';
