import { PhysicalUI, type PhysicalUIOptions } from '@physical/dom';

const CHIPS = ['Gravity', 'Friction', 'Restitution', 'Torque', 'Impulse', 'Momentum', 'Inertia'];

const STYLE = `
.physical-showcase { font: 15px system-ui, sans-serif; color: #eceff1; max-width: 640px; }
.physical-showcase .box {
  position: relative; height: 360px; padding: 12px; box-sizing: border-box;
  background: #1e1e1e; border: 2px solid #424242; border-radius: 16px;
  display: flex; flex-wrap: wrap; align-content: flex-start; gap: 8px; overflow: hidden;
}
.physical-showcase .chip {
  font: inherit; padding: 6px 14px; border-radius: 999px; border: 1px solid #82b1ff;
  background: #0d47a1; color: #fff; cursor: pointer;
}
.physical-showcase .round {
  font: inherit; width: 56px; height: 56px; border-radius: 50%; border: none;
  background: #c2185b; color: #fff; cursor: pointer;
}
.physical-showcase .square {
  font: inherit; padding: 10px 16px; border-radius: 6px; border: none;
  background: #2e7d32; color: #fff; cursor: pointer;
}
.physical-showcase [data-physical='dragging'] { cursor: grabbing; }
.physical-showcase nav { display: flex; gap: 8px; padding: 10px 0; flex-wrap: wrap; align-items: center; }
`;

/**
 * The showcase: a row of chips and buttons in a box. Tap a chip and it falls into the box; drag
 * anything and throw it; the buttons still count their clicks; "Back to layout" springs them all
 * home. Builds its markup in `root` and returns the PhysicalUI.
 */
export function mountShowcase(root: HTMLElement, options: PhysicalUIOptions = {}): PhysicalUI {
  root.classList.add('physical-showcase');
  root.innerHTML = `<style>${STYLE}</style>
<div class="box" aria-label="Physical chips and buttons">
  ${CHIPS.map((name) => `<button class="chip" type="button">${name}</button>`).join('')}
  <button class="round" type="button" id="likes" aria-label="Like">&#9829; <span>0</span></button>
  <button class="square" type="button" id="count">Clicked <span>0</span></button>
</div>
<nav>
  <button type="button" id="drop">Drop all</button>
  <button type="button" id="home">Back to layout</button>
  <label hidden id="motion"><input type="checkbox" /> Move anyway (you asked for reduced motion)</label>
</nav>`;
  const box = root.querySelector<HTMLElement>('.box')!;
  const ui = new PhysicalUI(box, { elements: 'button', ...options });

  for (const chip of box.querySelectorAll<HTMLElement>('.chip')) {
    chip.addEventListener('click', () => ui.release(chip));
  }
  for (const id of ['likes', 'count']) {
    const button = root.querySelector<HTMLElement>(`#${id}`)!;
    button.addEventListener('click', () => {
      const counter = button.querySelector('span')!;
      counter.textContent = String(Number(counter.textContent) + 1);
      if (ui.stateOf(button) === 'layout') ui.release(button);
    });
  }
  root.querySelector('#drop')!.addEventListener('click', () => ui.release());
  root.querySelector('#home')!.addEventListener('click', () => ui.restore());
  const motion = root.querySelector<HTMLElement>('#motion')!;
  motion.hidden = ui.motionAllowed;
  motion.querySelector('input')!.addEventListener('change', (event) => {
    ui.reducedMotion = (event.target as HTMLInputElement).checked ? 'ignore' : 'respect';
  });
  return ui;
}
