import type { PointerEventDetail } from '@physical/canvas';
import type { MouseJoint, World } from '@physical/engine';
import { STEP, type Scene, grab, sceneValues, sceneView } from '@physical/scenes';
import { h } from './dom.ts';
import { icon } from './icons.ts';
import { sceneStyleFor } from './scene-styles.ts';
import { cameraAttribute, viewBoxAttribute } from './list-page.ts';
import { sourceOf } from './sources.ts';

/** Every overlay `<physical-canvas>` draws, with the chip's label. */
const OVERLAYS = [
  ['contacts', 'Contacts'],
  ['normals', 'Normals'],
  ['aabbs', 'AABBs'],
  ['centers', 'Centres'],
  ['velocities', 'Velocities'],
  ['sleep', 'Sleep'],
] as const;

/** The stage's colour: Material's raised dark surface, so the canvas reads as a panel. */
export const SURFACE = '#1e1e1e';

/** Time scale of slow motion. */
const SLOW_MOTION = 0.25;

function iconButton(name: Parameters<typeof icon>[0], label: string, action: string) {
  const button = h('button', {
    type: 'button',
    class: 'icon-button',
    'aria-label': label,
    title: label,
    'data-action': action,
  });
  button.innerHTML = icon(name);
  return button;
}

/** One sample: the live canvas, its controls, parameters, overlays and source. */
export function renderSample(root: HTMLElement, scene: Scene): () => void {
  document.title = `${scene.title} \u2013 Physical samples`;
  const values: Record<string, number> = { ...sceneValues(scene) };
  let world: World = scene.build(values);
  /** The mouse joint of the body being dragged, if any. */
  let dragged: MouseJoint | null = null;

  const canvas = h('physical-canvas', {
    fit: 'contain',
    'view-box': cameraAttribute(scene),
    background: SURFACE,
    // The page drags bodies itself (and draws the drag line), and a tap that is not a drag kicks.
    drag: 'off',
    'aria-label': `${scene.title}: live simulation`,
    // The stage takes the camera's shape (CSS caps its height), so no space is wasted on a phone.
    style: `aspect-ratio: ${scene.camera.width} / ${scene.camera.height}`,
  });
  canvas.world = world;
  canvas.styleFor = sceneStyleFor(scene);
  // Joints (the scene's rods and hinges, and the mouse joint of a drag) are drawn by the canvas.

  // ---- toolbar: play/pause, step, slow motion, reset, time
  const play = iconButton('pause', 'Pause', 'play');
  play.classList.add('primary');
  const step = iconButton('step', 'Step', 'step');
  step.disabled = true;
  const slow = iconButton('slow', 'Slow motion', 'slow');
  slow.setAttribute('aria-pressed', 'false');
  const reset = iconButton('reset', 'Reset', 'reset');
  const time = h('span', { class: 'time', 'data-readout': 'time' }, 't = 0.00 s');
  const setPaused = (paused: boolean): void => {
    canvas.paused = paused;
    play.innerHTML = icon(paused ? 'play' : 'pause');
    play.setAttribute('aria-label', paused ? 'Play' : 'Pause');
    play.title = paused ? 'Play' : 'Pause';
    step.disabled = !paused;
  };
  play.addEventListener('click', () => setPaused(!canvas.paused));
  canvas.addEventListener('pausechange', ({ detail }) => setPaused(detail.paused));
  step.addEventListener('click', () => canvas.step());
  slow.addEventListener('click', () => {
    const on = canvas.timeScale === 1;
    canvas.timeScale = on ? SLOW_MOTION : 1;
    slow.setAttribute('aria-pressed', String(on));
  });
  const rebuild = (): void => {
    dragged = null;
    world = scene.build(values);
    canvas.world = world;
  };
  reset.addEventListener('click', rebuild);

  // ---- drag and throw any dynamic body with a mouse joint; a tap kicks it
  const release = (): void => {
    if (dragged !== null && dragged.world !== null) world.removeJoint(dragged);
    dragged = null;
  };
  canvas.addEventListener('bodypress', ({ detail }: CustomEvent<PointerEventDetail>) => {
    const body = detail.body;
    if (body === null || body.type !== 'dynamic' || body.world !== world) return;
    release();
    dragged = grab(body, detail.point);
  });
  canvas.addEventListener('pointermove', (event) => {
    if (dragged === null) return;
    const point = canvas.clientToWorld(event.clientX, event.clientY);
    if (point !== null) dragged.target = point;
  });
  canvas.addEventListener('bodyrelease', release);
  canvas.addEventListener('bodytap', ({ detail }: CustomEvent<PointerEventDetail>) => {
    const body = detail.body;
    if (body === null || body.type !== 'dynamic') return;
    body.applyImpulse({ x: 0, y: -4 * body.mass }, detail.point);
  });

  // Once per frame: show the simulated time, and move the view with a followed body.
  let frame = 0;
  let view = cameraAttribute(scene);
  const tick = (): void => {
    time.textContent = `t = ${(world.steps * STEP).toFixed(2)} s`;
    if (scene.camera.follow !== undefined) {
      const next = viewBoxAttribute(sceneView(scene, world));
      if (next !== view) canvas.setAttribute('view-box', (view = next));
    }
    frame = requestAnimationFrame(tick);
  };
  frame = requestAnimationFrame(tick);

  // ---- parameters
  const parameters = h('section', { class: 'panel', 'aria-labelledby': 'parameters-title' });
  parameters.append(h('h2', { id: 'parameters-title' }, 'Parameters'));
  for (const parameter of scene.parameters) {
    const id = `parameter-${parameter.name}`;
    const output = h('output', { for: id }, format(values[parameter.name]!, parameter.step));
    const input = h('input', {
      id,
      type: 'range',
      min: String(parameter.min),
      max: String(parameter.max),
      step: String(parameter.step),
      value: String(values[parameter.name]),
      'data-parameter': parameter.name,
    });
    input.addEventListener('input', () => {
      values[parameter.name] = Number(input.value);
      output.textContent = format(values[parameter.name]!, parameter.step);
      rebuild();
    });
    parameters.append(
      h('div', { class: 'parameter' }, h('label', { for: id }, parameter.label), output, input),
    );
  }
  parameters.append(
    h('p', { class: 'hint' }, 'Changing a value rebuilds the scene. Drag bodies to throw them.'),
  );

  // ---- debug overlays
  const chips = h('div', { class: 'chips' });
  const overlays = new Set<string>();
  for (const [name, label] of OVERLAYS) {
    const box = h('input', { type: 'checkbox', 'data-overlay': name });
    box.addEventListener('change', () => {
      if (box.checked) overlays.add(name);
      else overlays.delete(name);
      canvas.debug = [...overlays];
    });
    chips.append(h('label', { class: 'chip' }, box, label));
  }
  const arrows = h('input', { type: 'checkbox', 'data-overlay': 'collision-arrows' });
  arrows.addEventListener('change', () => {
    canvas.collisionArrows = arrows.checked;
  });
  chips.append(h('label', { class: 'chip' }, arrows, 'Collision arrows'));

  // ---- source
  const code = h('code', { 'data-source': scene.id });
  code.textContent = sourceOf(scene.id);

  const back = h('a', { class: 'icon-button back', href: '#/', 'aria-label': 'All samples' });
  back.innerHTML = icon('back');
  root.replaceChildren(
    h('header', { class: 'app-bar' }, back, h('h1', {}, scene.title)),
    h(
      'div',
      { class: 'content sample' },
      h(
        'div',
        { class: 'column' },
        h(
          'div',
          { class: 'stage' },
          canvas,
          h(
            'div',
            { class: 'toolbar', role: 'toolbar', 'aria-label': 'Simulation' },
            play,
            step,
            slow,
            reset,
            time,
          ),
        ),
        h('section', { class: 'panel' }, h('p', { 'data-description': '' }, scene.description)),
        parameters,
        h('section', { class: 'panel' }, h('h2', {}, 'Debug overlays'), chips),
      ),
      h(
        'section',
        { class: 'panel' },
        h('h2', {}, `Source: packages/scenes/src/samples/${scene.id}.ts`),
        h(
          'pre',
          { class: 'source', tabindex: '0', 'aria-label': `Source of ${scene.title}` },
          code,
        ),
      ),
    ),
  );
  return () => cancelAnimationFrame(frame);
}

/** A parameter's value with as many decimals as its step has. */
function format(value: number, step: number): string {
  const decimals = step >= 1 ? 0 : Math.min(3, Math.ceil(-Math.log10(step) - 1e-9));
  return value.toFixed(decimals);
}
