import type { Body, Vec2, Vec2Like, World } from '@physical/engine';
import type { BodyStyle } from '../draw/body-style.ts';
import type { HeldPoint } from '../draw/scene.ts';
import { MAX_REMOTE_STEPS_IN_FLIGHT, type DrawingSource } from '../draw/drawing-source.ts';
import type { DebugOverlays } from '../draw/debug-overlays.ts';
import {
  screenToWorld,
  worldToScreen,
  type FitMode,
  type ViewBox,
  type Viewport,
} from '../draw/viewport.ts';
import {
  CanvasSettingError,
  formatDebug,
  parseColor,
  parseDebug,
  parseDrag,
  parseFit,
  parseNonNegative,
  parsePoint,
  parsePositive,
  parsePositiveInteger,
  parseViewBox,
} from './attribute-parsers.ts';
import type { BodyDrag } from './body-drag.ts';
import { BodyStyles, type StyleResolver } from './body-styles.ts';
import { emit, type PhysicalCanvasEventMap } from './canvas-events.ts';
import { CanvasRenderer } from './canvas-renderer.ts';
import { CanvasSettings, SETTING_ATTRIBUTES, type SettingAttribute } from './canvas-settings.ts';
import { CollisionArrows } from './collision-arrows.ts';
import { FrameLoop, type FrameLoopTarget } from './frame-loop.ts';
import { animationFrameScheduler, type FrameScheduler } from './frame-scheduler.ts';
import { PointerInput } from './pointer-input.ts';
import { PoseHistory } from './pose-history.ts';
import { watchEnvironment } from './environment-watch.ts';
import { WorldSubscription } from './world-subscription.ts';

/** Draws app overlays after the bodies, on a context in world metres. */
export type OverlayDrawer = (
  context: CanvasRenderingContext2D,
  canvas: PhysicalCanvasElement,
) => void;

const NOT_HOLDING: readonly HeldPoint[] = [];

/** Properties an app may set before the element is defined; re-applied on upgrade. */
const UPGRADED_PROPERTIES = [
  'world',
  'styleFor',
  'drawOverlay',
  'frameScheduler',
  'pixelsPerMeter',
  'origin',
  'fit',
  'viewBox',
  'paused',
  'timeScale',
  'background',
  'debug',
  'collisionArrows',
  'drag',
  'maxPixelRatio',
] as const;

const TEMPLATE = `<style>
:host { display: block; position: relative; height: 300px; contain: layout paint; outline: none; }
:host([hidden]) { display: none; }
:host(:focus-visible) { box-shadow: 0 0 0 2px #82b1ff; }
canvas { display: block; width: 100%; height: 100%; touch-action: none; }
:host([drag='off' i]) canvas, :host([drag='false' i]) canvas { touch-action: manipulation; }
</style><canvas part="canvas"></canvas>`;

// Server rendering and Node tests import this module without a DOM: the class then extends a
// stand-in and is only defined (customElements.define) in a browser.
const ElementBase: typeof HTMLElement =
  typeof HTMLElement === 'undefined' ? (Object as unknown as typeof HTMLElement) : HTMLElement;

/**
 * `<physical-canvas>`: runs a Physical world at a fixed step and draws it, sharp at any size and
 * pixel density. Register it with `define()` (or import `@physical/canvas/define`), give it a
 * `world`, and add or remove bodies whenever you like.
 *
 * Attributes (each also a property): `pixels-per-meter`, `origin`, `fit`, `view-box`, `paused`,
 * `time-scale`, `background`, `debug`, `collision-arrows`, `collision-arrow-duration`,
 * `force-scale`, `velocity-scale`, `steps-per-second`, `max-steps-per-frame`, `drag`. Properties only:
 * `world`, `styleFor`, `drawOverlay`, `frameScheduler`. Events: see {@link PhysicalCanvasEventMap}.
 */
// The interface of the same name below adds typed addEventListener overloads (the usual pattern
// for custom elements' events); it declares no members the class would have to initialise.
// eslint-disable-next-line @typescript-eslint/no-unsafe-declaration-merging
export class PhysicalCanvasElement extends ElementBase {
  /** The attributes the element reacts to. */
  static readonly observedAttributes: readonly string[] = SETTING_ATTRIBUTES;

  private worldValue: DrawingSource | null = null;
  /** Pointers whose drag went to the remote source (the others are held by {@link drags}). */
  private readonly remoteDrags = new Set<number>();
  private drawOverlayValue: OverlayDrawer | null = null;
  private schedulerValue: FrameScheduler | null = null;
  private readonly settings = new CanvasSettings();
  private readonly loop = new FrameLoop(
    {
      step: (dt) => this.stepWorld(dt),
      render: (alpha, elapsed) => this.render(alpha, elapsed),
      isSettled: () => this.isSettled(),
      canStep: () => this.canStepWorld(),
    } satisfies FrameLoopTarget,
    animationFrameScheduler,
  );
  private readonly poses = new PoseHistory();
  private readonly styles = new BodyStyles();
  private readonly arrows = new CollisionArrows();
  /**
   * The local drag (body-drag.ts), loaded apart when a press first lands on a body of a local
   * world: pages that never drag (and a worker world's, whose worker drags) never load it.
   */
  private drags: BodyDrag | null = null;
  private dragLoading = false;
  /** Drags begun before its code arrived (pointer id: world, body, x, y, toX, toY); see loadDrag. */
  private readonly waitingDrags = new Map<number, [World, Body, number, number, number, number]>();
  private readonly input = new PointerInput({
    clientToWorld: (x, y) => this.clientToWorld(x, y),
    bodyAt: (point) => {
      const body = this.worldValue?.bodyAt(point) ?? null;
      // A press on a body may become a drag once it moves: fetch the drag's code now.
      if (body !== null && this.worldValue!.remote === undefined) this.loadDrag();
      return body;
    },
    emit: (type, detail) => emit(this, type, detail),
    wake: () => this.invalidate(),
    dragStart: (pointerId, body, x, y, toX, toY) => {
      const world = this.worldValue;
      if (world === null || !this.settings.drag) return false;
      if (world.remote !== undefined) {
        if (!world.remote.grab(pointerId, body, x, y, toX, toY)) return false;
        this.remoteDrags.add(pointerId);
        return true;
      }
      // A source without `remote` is a World, stepped here: the drag pulls before each step.
      if (this.drags !== null)
        return this.drags.start(world as World, pointerId, body, x, y, toX, toY);
      if (body.type !== 'dynamic' || !(world as World).has(body)) return false;
      this.waitingDrags.set(pointerId, [world as World, body, x, y, toX, toY]);
      this.loadDrag();
      return true;
    },
    dragMove: (pointerId, x, y) => {
      if (this.remoteDrags.has(pointerId)) this.worldValue?.remote?.moveGrab(pointerId, x, y);
      else {
        const waiting = this.waitingDrags.get(pointerId);
        if (waiting !== undefined) {
          waiting[4] = x;
          waiting[5] = y;
        } else this.drags?.move(pointerId, x, y);
      }
    },
    dragEnd: (pointerId, vx, vy, isThrow) => {
      if (this.remoteDrags.delete(pointerId)) {
        this.worldValue?.remote?.releaseGrab(pointerId, vx, vy, isThrow);
      } else if (!this.waitingDrags.delete(pointerId)) this.drags?.end(pointerId, vx, vy, isThrow);
    },
  });
  private readonly renderer: CanvasRenderer;
  private canvasElement: HTMLCanvasElement | null = null;
  private stepDuration = 1 / 60;
  private isConnectedValue = false;
  private teardown: (() => void)[] = [];
  private readonly subscription = new WorldSubscription({
    changed: () => this.invalidate(),
    collided: (event) => this.arrows.record(event, this.stepDuration),
  });
  // Made once: drawOverlay gets the element as its second argument.
  private readonly drawAppOverlay = (context: CanvasRenderingContext2D): void => {
    const overlay = this.drawOverlayValue;
    if (overlay !== null) overlay(context, this);
  };

  constructor() {
    super();
    this.loop.suspend('detached');
    let context: CanvasRenderingContext2D | null = null;
    if (typeof document !== 'undefined' && typeof this.attachShadow === 'function') {
      const root = this.attachShadow({ mode: 'open' });
      root.innerHTML = TEMPLATE;
      this.canvasElement = root.querySelector('canvas')!;
      context = this.canvasElement.getContext('2d', { alpha: true });
    }
    this.renderer = new CanvasRenderer(
      {
        settings: this.settings,
        poses: this.poses,
        styles: this.styles,
        arrows: this.arrows,
        held: () => this.drags?.held ?? NOT_HOLDING,
        measure: () =>
          this.isConnectedValue ? { width: this.clientWidth, height: this.clientHeight } : null,
        redraw: () => this.invalidate(),
      },
      context,
    );
  }

  // ------------------------------------------------------------------ world and styles

  /**
   * The world to run and draw, or null: a `World` of `@physical/engine`, or any
   * {@link DrawingSource} (a `WorkerWorld` of `@physical/worker`, drawn from its pose stream).
   * The element steps it (do not also call `world.step`), subscribes to its events while
   * connected, and drops them when disconnected or replaced.
   *
   * Reads back typed as a `World` (what nearly every page sets); after setting another source,
   * read {@link source} for its honest type.
   */
  get world(): World | null {
    return this.worldValue as World | null;
  }

  set world(value: World | DrawingSource | null) {
    if (value !== null && (typeof value !== 'object' || !('step' in value))) {
      throw new CanvasSettingError(
        'world',
        value,
        'a World from @physical/engine, a WorkerWorld from @physical/worker, or null',
      );
    }
    if (value === this.worldValue) return;
    this.releaseRemoteDrags();
    this.releaseLocalDrags();
    this.unsubscribe();
    this.worldValue = value;
    this.poses.clear();
    this.arrows.clear();
    this.loop.reset();
    if (this.isConnectedValue) this.subscribe();
    this.invalidate();
  }

  /** The world being drawn, as the {@link DrawingSource} it was set as, or null. */
  get source(): DrawingSource | null {
    return this.worldValue;
  }

  /**
   * Gives a body its own style (or with null, back to `styleFor` or the default). The body need
   * not be in the world yet; the style is forgotten with the body.
   */
  setStyle(body: Body, style: BodyStyle | null): void {
    this.styles.set(body, style);
    this.invalidate();
  }

  /** The style set with {@link setStyle}, if any. */
  getStyle(body: Body): BodyStyle | undefined {
    return this.styles.get(body);
  }

  /**
   * Styles every body without an explicit style. Called each frame for each body: return the
   * same object for the same look (for example from a table by `body.userData`), not a new one.
   */
  get styleFor(): StyleResolver | null {
    return this.styles.styleFor;
  }

  set styleFor(value: StyleResolver | null) {
    if (value !== null && typeof value !== 'function') {
      throw new CanvasSettingError('styleFor', value, 'a function (body) => style, or null');
    }
    this.styles.styleFor = value;
    this.styles.invalidate();
    this.invalidate();
  }

  /**
   * Draws app overlays (force arrows with `drawArrow`, trails, targets) after the bodies, each
   * frame, on a context in world metres.
   */
  get drawOverlay(): OverlayDrawer | null {
    return this.drawOverlayValue;
  }

  set drawOverlay(value: OverlayDrawer | null) {
    if (value !== null && typeof value !== 'function') {
      throw new CanvasSettingError('drawOverlay', value, 'a function (context, canvas), or null');
    }
    this.drawOverlayValue = value;
    this.invalidate();
  }

  /**
   * Where frames come from: `requestAnimationFrame` by default (null). Set a
   * `ManualFrameScheduler` to drive the element by hand (tests, offline rendering).
   */
  get frameScheduler(): FrameScheduler | null {
    return this.schedulerValue;
  }

  set frameScheduler(value: FrameScheduler | null) {
    this.schedulerValue = value;
    this.loop.reset();
    this.loop.setScheduler(value ?? animationFrameScheduler);
  }

  // ------------------------------------------------------------------ view

  /** CSS px per metre when `fit` is `"none"` (attribute `pixels-per-meter`). Default 50. */
  get pixelsPerMeter(): number {
    return this.settings.pixelsPerMeter;
  }

  set pixelsPerMeter(value: number) {
    this.reflect('pixels-per-meter', String(parsePositive('pixels-per-meter', value)));
  }

  /**
   * The world point (m) at the element's top-left corner when `fit` is `"none"` (attribute
   * `origin="x y"`): the camera. Default (0, 0). Resizing keeps it, and the scale.
   */
  get origin(): Readonly<Vec2> {
    return { x: this.settings.origin.x, y: this.settings.origin.y };
  }

  set origin(value: Vec2Like) {
    const point = parsePoint('origin', value);
    this.reflect('origin', `${point.x} ${point.y}`);
  }

  /** `"none"` (default), `"contain"` or `"cover"`: how `viewBox` fits the element. */
  get fit(): FitMode {
    return this.settings.fit;
  }

  set fit(value: FitMode) {
    this.reflect('fit', parseFit('fit', value));
  }

  /**
   * The world rectangle (m) that `fit="contain"` or `"cover"` keeps in view, centred, at any
   * element size (attribute `view-box="x y width height"`). Null by default.
   */
  get viewBox(): ViewBox | null {
    return this.settings.viewBox;
  }

  set viewBox(value: ViewBox | null) {
    const box = parseViewBox('view-box', value);
    if (box === null) this.removeAttribute('view-box');
    else this.reflect('view-box', `${box.x} ${box.y} ${box.width} ${box.height}`);
  }

  /** The mapping in use: element size, scale (CSS px per metre) and origin. */
  get viewport(): Viewport {
    return this.renderer.viewport;
  }

  /** Element point (CSS px from its top-left corner) to world point (m). */
  screenToWorld(point: Vec2Like): Vec2 {
    return screenToWorld(this.viewport, point);
  }

  /** World point (m) to element point (CSS px from its top-left corner). */
  worldToScreen(point: Vec2Like): Vec2 {
    return worldToScreen(this.viewport, point);
  }

  /** Viewport point (`clientX`, `clientY` of a mouse event) to world point (m). */
  clientToWorld(clientX: number, clientY: number): Vec2 {
    const rect = this.getBoundingClientRect();
    return screenToWorld(this.viewport, { x: clientX - rect.left, y: clientY - rect.top });
  }

  // ------------------------------------------------------------------ input

  /**
   * Pointers drag dynamic bodies (attribute `drag`; `drag="off"` turns it off): press on a body
   * and move, and a soft spring (the engine's mouse joint's tuning) pulls the pressed point after
   * the pointer before each step the element runs; letting go
   * throws the body with the pointer's velocity. Mouse, touch and pen; several fingers drag
   * several bodies. Default on. While on, the canvas takes touch gestures (`touch-action: none`),
   * so a page does not scroll by a swipe over it.
   */
  get drag(): boolean {
    return this.settings.drag;
  }

  set drag(value: boolean) {
    if (parseDrag('drag', value)) this.removeAttribute('drag');
    else this.setAttribute('drag', 'off');
  }

  // ------------------------------------------------------------------ time

  /** True stops time (frames are still drawn when something changes). Attribute `paused`. */
  get paused(): boolean {
    return this.loop.paused;
  }

  set paused(value: boolean) {
    this.toggleAttribute('paused', Boolean(value));
  }

  /** Simulated seconds per real second: 0.25 is slow motion (attribute `time-scale`). Default 1. */
  get timeScale(): number {
    return this.loop.timeScale;
  }

  set timeScale(value: number) {
    this.reflect('time-scale', String(parseNonNegative('time-scale', value)));
  }

  /** Fixed steps per simulated second (attribute `steps-per-second`). Default 60. */
  get stepsPerSecond(): number {
    return 1 / this.loop.fixedStep;
  }

  set stepsPerSecond(value: number) {
    this.reflect('steps-per-second', String(parsePositive('steps-per-second', value)));
  }

  /**
   * Most steps per frame when catching up after a stall (attribute `max-steps-per-frame`).
   * Default 4; beyond it the backlog is dropped and the simulation slows down instead.
   */
  get maxStepsPerFrame(): number {
    return this.loop.maxStepsPerFrame;
  }

  set maxStepsPerFrame(value: number) {
    this.reflect('max-steps-per-frame', String(parsePositiveInteger('max-steps-per-frame', value)));
  }

  /**
   * Most device pixels per CSS pixel the canvas draws at (attribute `max-pixel-ratio`). Default:
   * no cap, the screen's `devicePixelRatio`. Set 2 (or 1.5) to trade sharpness on 3x phones for
   * frame rate: the canvas then fills 4 (or 2.25) device pixels per CSS px instead of 9.
   */
  get maxPixelRatio(): number {
    return this.settings.maxPixelRatio;
  }

  set maxPixelRatio(value: number) {
    this.reflect('max-pixel-ratio', String(parsePositive('max-pixel-ratio', value)));
  }

  /** Steps taken by this element so far. */
  get stepCount(): number {
    return this.loop.stepCount;
  }

  /** Frames drawn by this element so far. */
  get frameCount(): number {
    return this.loop.frameCount;
  }

  /** True while the element has a frame scheduled (false when idle, hidden or detached). */
  get isRunning(): boolean {
    return this.loop.isRunning;
  }

  /**
   * Advances the world by exactly one fixed step (`1 / stepsPerSecond` s) and draws the result
   * at once: a "next step" button for a paused element (`canvas.paused = true`, then
   * `canvas.step()` per press), in place of `world.step()` followed by {@link invalidate}. Goes
   * through the element, so what a running element does per step happens too: collision arrows
   * are recorded, a drag pulls, {@link stepCount} counts it. With a `WorkerWorld`
   * the step is posted and its poses are drawn when they arrive. Also works while running (one
   * step more than the clock gives). Without a world it throws a `CanvasSettingError` naming
   * `world`.
   */
  step(): void {
    if (this.worldValue === null) {
      throw new CanvasSettingError('world', null, 'a world before step() (set canvas.world)');
    }
    this.loop.stepOnce();
  }

  /**
   * Asks for a frame: call it after changing the world by hand while paused (teleporting a body),
   * or after changing a style object in place. Other changes wake the element by themselves.
   */
  invalidate(): void {
    this.loop.invalidate();
  }

  // ------------------------------------------------------------------ look

  /** Background colour (any CSS colour, or `"transparent"`). Default Material dark `#121212`. */
  get background(): string {
    return this.settings.background;
  }

  set background(value: string) {
    this.reflect('background', parseColor('background', value));
  }

  /**
   * Debug overlays that are on. The attribute is a list: `debug="contacts normals aabbs centers
   * velocities sleep"` (or `"all"`); the property also takes an array or an object of flags.
   */
  get debug(): Readonly<DebugOverlays> {
    return { ...this.settings.debug };
  }

  set debug(value: string | readonly string[] | Partial<DebugOverlays>) {
    const overlays = parseDebug('debug', value);
    const text = formatDebug(overlays);
    if (text === '') this.removeAttribute('debug');
    else this.reflect('debug', text);
  }

  /**
   * Collision-force arrows (attribute `collision-arrows`): at each impact, two equal and
   * opposite arrows of the average contact force, fading over `collisionArrowDuration`.
   */
  get collisionArrows(): boolean {
    return this.settings.collisionArrows;
  }

  set collisionArrows(value: boolean) {
    this.toggleAttribute('collision-arrows', Boolean(value));
  }

  /** Seconds a collision arrow takes to fade (attribute `collision-arrow-duration`). Default 1. */
  get collisionArrowDuration(): number {
    return this.arrows.duration;
  }

  set collisionArrowDuration(value: number) {
    this.reflect(
      'collision-arrow-duration',
      String(parsePositive('collision-arrow-duration', value)),
    );
  }

  /** Metres of collision arrow per newton (attribute `force-scale`). Default 0.01. */
  get forceScale(): number {
    return this.settings.forceScale;
  }

  set forceScale(value: number) {
    this.reflect('force-scale', String(parsePositive('force-scale', value)));
  }

  /**
   * Seconds of motion a velocity arrow shows: its length is speed times this (attribute
   * `velocity-scale`). Default 0.25.
   */
  get velocityScale(): number {
    return this.settings.velocityScale;
  }

  set velocityScale(value: number) {
    this.reflect('velocity-scale', String(parsePositive('velocity-scale', value)));
  }

  // ------------------------------------------------------------------ lifecycle

  /** @internal */
  connectedCallback(): void {
    for (const name of UPGRADED_PROPERTIES) this.upgradeProperty(name);
    if (!this.hasAttribute('tabindex')) this.tabIndex = 0;
    if (!this.hasAttribute('role')) this.setAttribute('role', 'img');
    if (!this.hasAttribute('aria-label')) this.setAttribute('aria-label', 'Physics simulation');
    this.isConnectedValue = true;
    this.subscribe();
    const canvas = this.canvasElement!;
    this.input.attach(canvas);
    this.watch();
    this.loop.resume('detached');
  }

  /** @internal */
  disconnectedCallback(): void {
    this.isConnectedValue = false;
    this.loop.suspend('detached');
    this.unsubscribe();
    this.input.detach();
    this.releaseRemoteDrags();
    this.releaseLocalDrags();
    for (const undo of this.teardown) undo();
    this.teardown = [];
  }

  /** @internal */
  attributeChangedCallback(name: string, _old: string | null, value: string | null): void {
    try {
      this.applyAttribute(name as SettingAttribute, value);
    } catch (error) {
      if (!(error instanceof CanvasSettingError)) throw error;
      // eslint-disable-next-line no-console -- a bad attribute in markup has no caller to throw to
      console.error(error.message);
      emit(this, 'attributeerror', { error });
    }
    this.invalidate();
  }

  // ------------------------------------------------------------------ frame loop

  /** Snapshots the poses, then takes one fixed step. */
  private stepWorld(dt: number): void {
    const world = this.worldValue;
    if (world === null) return;
    // A remote source keeps its own last two states (see DrawingSource.remote).
    if (world.remote === undefined) {
      this.poses.snapshot(world.bodies);
      // Held bodies are pulled to their pointers before the step (see BodyDrag).
      this.drags?.pull(dt);
    }
    this.stepDuration = dt;
    world.step(dt);
  }

  /** A remote world still busy with {@link MAX_REMOTE_STEPS_IN_FLIGHT} steps takes no more. */
  private canStepWorld(): boolean {
    const inFlight = this.worldValue?.remote?.stepsInFlight?.();
    return inFlight === undefined || inFlight < MAX_REMOTE_STEPS_IN_FLIGHT;
  }

  /** Draws the frame at `alpha` between the last two steps. */
  private render(alpha: number, elapsed: number): void {
    this.renderer.alpha = alpha;
    this.arrows.advance(elapsed);
    this.draw();
  }

  /** Nothing moves and nothing fades: stop requesting frames. */
  private isSettled(): boolean {
    const world = this.worldValue;
    if (world === null || this.loop.paused || this.loop.timeScale === 0) return true;
    return world.awakeBodyCount === 0 && this.arrows.isEmpty;
  }

  // ------------------------------------------------------------------ internals

  private draw(): void {
    this.renderer.draw(
      this.worldValue,
      this.drawOverlayValue === null ? null : this.drawAppOverlay,
    );
  }

  /** Parses an attribute into the settings and hands the result to the loop and the arrows. */
  private applyAttribute(name: SettingAttribute, value: string | null): void {
    const settings = this.settings;
    settings.apply(name, value);
    const loop = this.loop;
    loop.paused = settings.paused;
    loop.timeScale = settings.timeScale;
    loop.fixedStep = 1 / settings.stepsPerSecond;
    loop.maxStepsPerFrame = settings.maxStepsPerFrame;
    this.arrows.duration = settings.collisionArrowDuration;
    if (name === 'drag' && !settings.drag) {
      this.releaseRemoteDrags();
      this.releaseLocalDrags();
    }
    if (name === 'collision-arrows') {
      // Listen to collisions only while arrows are on: the events cost the engine time.
      this.unsubscribe();
      if (this.isConnectedValue) this.subscribe();
      if (!settings.collisionArrows) this.arrows.clear();
    }
    this.renderer.settingsChanged();
  }

  /** Sets an attribute from a property setter (values are already validated). */
  private reflect(name: SettingAttribute, value: string): void {
    this.setAttribute(name, value);
  }

  private upgradeProperty(name: (typeof UPGRADED_PROPERTIES)[number]): void {
    if (!Object.prototype.hasOwnProperty.call(this, name)) return;
    const value = (this as Record<string, unknown>)[name];
    Reflect.deleteProperty(this, name);
    (this as Record<string, unknown>)[name] = value;
  }

  /** Lets go of the drags held here, without throwing. */
  private releaseLocalDrags(): void {
    this.drags?.clear();
    this.waitingDrags.clear();
  }

  /** Loads the drag's code once; drags begun meanwhile start when it arrives. */
  private loadDrag(): void {
    if (this.dragLoading) return;
    this.dragLoading = true;
    void import('./body-drag.ts').then(({ BodyDrag }) => {
      const drags = (this.drags = new BodyDrag());
      for (const [pointerId, [world, body, x, y, toX, toY]] of this.waitingDrags) {
        if (world === this.worldValue) drags.start(world, pointerId, body, x, y, toX, toY);
      }
      this.waitingDrags.clear();
    });
  }

  /** Lets go of drags held by a remote source, without throwing. */
  private releaseRemoteDrags(): void {
    const remote = this.worldValue?.remote;
    for (const pointerId of this.remoteDrags) remote?.releaseGrab(pointerId, 0, 0, false);
    this.remoteDrags.clear();
  }

  private subscribe(): void {
    this.subscription.start(this.worldValue, this.settings.collisionArrows);
  }

  private unsubscribe(): void {
    this.subscription.stop();
  }

  private watch(): void {
    this.teardown.push(
      watchEnvironment(this, this.loop, {
        resized: (width, height) => {
          this.renderer.resize(width, height);
          // Redraw now, before the browser paints the stretched old bitmap.
          this.draw();
          this.invalidate();
        },
        reducedMotionChanged: (reduce) => {
          this.renderer.reducedMotion = reduce;
          this.arrows.fade = !reduce;
          this.invalidate();
        },
        densityChanged: () => this.invalidate(),
        togglePause: () => {
          this.paused = !this.paused;
          emit(this, 'pausechange', { paused: this.paused });
        },
      }),
    );
  }
}

/** Typed `addEventListener` for the element's events. */
// eslint-disable-next-line @typescript-eslint/no-unsafe-declaration-merging
export interface PhysicalCanvasElement {
  addEventListener<K extends keyof PhysicalCanvasEventMap>(
    type: K,
    listener: (this: PhysicalCanvasElement, event: PhysicalCanvasEventMap[K]) => void,
    options?: boolean | AddEventListenerOptions,
  ): void;
  addEventListener(
    type: string,
    listener: EventListenerOrEventListenerObject,
    options?: boolean | AddEventListenerOptions,
  ): void;
  removeEventListener<K extends keyof PhysicalCanvasEventMap>(
    type: K,
    listener: (this: PhysicalCanvasElement, event: PhysicalCanvasEventMap[K]) => void,
    options?: boolean | EventListenerOptions,
  ): void;
  removeEventListener(
    type: string,
    listener: EventListenerOrEventListenerObject,
    options?: boolean | EventListenerOptions,
  ): void;
}
