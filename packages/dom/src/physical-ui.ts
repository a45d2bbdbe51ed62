import { FrameLoop, animationFrameScheduler, type FrameScheduler } from '@physical/canvas';
import { Body, PhysicalError, World, type Vec2Like } from '@physical/engine';
import { ContainerWalls } from './container-walls.ts';
import { DragInput } from './drag-input.ts';
import { watchEnvironment, type EnvironmentWatch } from './environment-watch.ts';
import { shapeForBox } from './element-shape.ts';
import { formatTransform, snap } from './element-transform.ts';
import { Grab } from './grab.ts';
import {
  measureContainer,
  measureSlots,
  type ContainerFrame,
  type Slot,
} from './layout-measure.ts';
import { springStep } from './return-spring.ts';

/**
 * Where an element is:
 * - `'layout'`: in its layout slot, untransformed; its body is a static obstacle there.
 * - `'free'`: a dynamic body: it falls, collides, can be dragged and thrown.
 * - `'returning'`: springing back to its layout slot (then `'layout'`).
 */
export type ElementState = 'layout' | 'free' | 'returning';

/**
 * What to do about `prefers-reduced-motion: reduce`: `'respect'` (default) keeps every element
 * in its layout while the user asks for less motion; `'ignore'` is the app's explicit opt-in to
 * motion anyway (for example behind a "let them fall" button the user pressed).
 */
export type ReducedMotionPolicy = 'respect' | 'ignore';

/** Options of {@link PhysicalUI}. Every field is optional. */
export interface PhysicalUIOptions {
  /**
   * Which elements become bodies: a selector matched inside the container (elements added later
   * that match join by themselves), or a list of elements (add more with `add`). Default: the
   * container's children, and children added later.
   */
  readonly elements?: string | Iterable<HTMLElement>;
  /** CSS px per metre. Default 100: a 100 px button is a 1 m body. */
  readonly pixelsPerMeter?: number;
  /** Gravity (m/s^2, y-down). Default (0, 9.81). */
  readonly gravity?: Vec2Like;
  /** Mass per area (kg/m^2). Default 1. */
  readonly density?: number;
  /** Coulomb friction. Default 0.5. */
  readonly friction?: number;
  /** Bounciness. Default 0.2. */
  readonly restitution?: number;
  /** Start with every element free (falling) instead of in its layout. Default false. */
  readonly released?: boolean;
  /** Reduced-motion policy. Default `'respect'`. */
  readonly reducedMotion?: ReducedMotionPolicy;
  /** Frequency (Hz) of the spring that returns elements to their layout. Default 2. */
  readonly returnHertz?: number;
  /** Where frames come from; default `requestAnimationFrame`. */
  readonly frameScheduler?: FrameScheduler | null;
}

interface Item {
  readonly element: HTMLElement;
  body: Body;
  state: ElementState;
  readonly slot: Slot;
  /** Pose before the last step (m, rad), for interpolation. */
  prevX: number;
  prevY: number;
  prevAngle: number;
  /** Angle (rad) the return spring aims at: the whole turn nearest the angle when sent back. */
  homeAngle: number;
  /** Seconds spent returning. */
  returnTime: number;
  /** The transform last written (px, rad), or null when the element shows its layout. */
  shown: boolean;
  shownX: number;
  shownY: number;
  shownAngle: number;
  /** Inline styles to put back on removal. */
  readonly savedTransform: string;
  readonly savedOrigin: string;
  readonly savedTouchAction: string;
}

/** Below these the return spring has arrived: the element snaps into its layout. */
const ARRIVED_PX = 0.25;
const ARRIVED_RAD = 0.002;
/** A return never takes longer than this (s). */
const MAX_RETURN_TIME = 4;
/** Fastest throw (m/s): a flick is fast, not ballistic. */
const MAX_THROW_SPEED = 30;

const spring: [number, number] = [0, 0];
const velocityScratch = { x: 0, y: 0 };

/**
 * Physical UI: makes a container's own elements physical. Each element becomes a body shaped
 * like its box (a circle for a round element, a rounded box otherwise), the container's edges
 * become walls, and the element is moved by its CSS `transform` alone: it keeps its place in
 * the DOM, its events, focus and text.
 *
 * Elements start in their layout (as static obstacles); {@link release} lets them fall,
 * dragging pulls them out with the pointer (mouse, touch or pen, several at once), a drag's
 * release throws them, and {@link restore} springs them back to their layout slots.
 *
 * Layout is read only when measuring (at start, when the container or an element resizes, and
 * on {@link measure}); a frame only steps the world and writes transforms. While the user
 * prefers reduced motion every element stays in its layout unless the app opts in with
 * `reducedMotion: 'ignore'`.
 */
export class PhysicalUI {
  /** The element whose children are physical, and whose edges are walls. */
  readonly container: HTMLElement;
  /** The world the elements live in (metres, y-down, origin at the container's padding box). */
  readonly world: World;

  private readonly ppm: number;
  private readonly material: { density: number; friction: number; restitution: number };
  private readonly returnOmega: number;
  private readonly selector: string | null;
  /** With no `elements` option, children added later join too. */
  private readonly followChildren: boolean;
  private readonly items: Item[] = [];
  private readonly byElement = new Map<HTMLElement, Item>();
  private readonly walls = new ContainerWalls();
  private readonly frame: ContainerFrame = { left: 0, top: 0, scale: 1, width: 0, height: 0 };
  private frameStale = true;
  private devicePixelRatio = 1;
  private policy: ReducedMotionPolicy;
  private prefersReduced = false;
  private readonly grabs = new Map<number, { grab: Grab; item: Item }>();
  private readonly input: DragInput;
  private readonly loop: FrameLoop;
  private readonly teardown: (() => void)[] = [];
  private destroyed = false;

  constructor(container: HTMLElement, options: PhysicalUIOptions = {}) {
    if (typeof HTMLElement === 'undefined' || !(container instanceof HTMLElement)) {
      throw new PhysicalError('container', 'must be an HTMLElement in a document.');
    }
    this.container = container;
    this.ppm = positive('pixelsPerMeter', options.pixelsPerMeter ?? 100);
    this.material = {
      density: positive('density', options.density ?? 1),
      friction: nonNegative('friction', options.friction ?? 0.5),
      restitution: nonNegative('restitution', options.restitution ?? 0.2),
    };
    this.returnOmega = 2 * Math.PI * positive('returnHertz', options.returnHertz ?? 2);
    const policy = options.reducedMotion ?? 'respect';
    if (policy !== 'respect' && policy !== 'ignore') {
      throw new PhysicalError(
        'reducedMotion',
        `must be 'respect' or 'ignore', got ${String(policy)}.`,
      );
    }
    this.policy = policy;
    this.world = new World(options.gravity === undefined ? {} : { gravity: options.gravity });
    this.loop = new FrameLoop(
      {
        step: (dt) => this.step(dt),
        render: (alpha) => this.render(alpha),
        isSettled: () => this.isSettled(),
      },
      options.frameScheduler ?? animationFrameScheduler,
    );
    this.input = new DragInput({
      elementAt: (target) => this.elementAt(target),
      canDrag: () => this.motionAllowed,
      dragStart: (id, element, x, y) => this.dragStart(id, element, x, y),
      dragMove: (id, x, y) => this.dragMove(id, x, y),
      dragEnd: (id, vx, vy) => this.dragEnd(id, vx, vy),
    });

    const elements = options.elements;
    this.selector = typeof elements === 'string' ? elements : null;
    this.followChildren = elements === undefined;
    const initial =
      elements === undefined
        ? [...container.children].filter((child) => child instanceof HTMLElement)
        : typeof elements === 'string'
          ? [...container.querySelectorAll<HTMLElement>(elements)]
          : [...elements];

    this.watch();
    this.input.attach(container);
    try {
      this.addAll(initial);
    } catch (error) {
      this.destroy(); // an element it cannot use: leave nothing behind
      throw error;
    }
    if (options.released === true) this.release();
  }

  // ------------------------------------------------------------------ reading

  /** The physical elements, in the order they joined. */
  get elements(): readonly HTMLElement[] {
    return this.items.map((item) => item.element);
  }

  /** CSS px per metre. */
  get pixelsPerMeter(): number {
    return this.ppm;
  }

  /**
   * False while the user prefers reduced motion and the policy is `'respect'`: every element
   * then stays in its layout, {@link release} does nothing and nothing can be dragged.
   */
  get motionAllowed(): boolean {
    return this.policy === 'ignore' || !this.prefersReduced;
  }

  /** The reduced-motion policy; set `'ignore'` to opt in to motion explicitly. */
  get reducedMotion(): ReducedMotionPolicy {
    return this.policy;
  }

  set reducedMotion(value: ReducedMotionPolicy) {
    if (value !== 'respect' && value !== 'ignore') {
      throw new PhysicalError(
        'reducedMotion',
        `must be 'respect' or 'ignore', got ${String(value)}.`,
      );
    }
    this.policy = value;
    this.motionChanged();
  }

  /** The state of a physical element, or null if it is not one. */
  stateOf(element: HTMLElement): ElementState | null {
    return this.byElement.get(element)?.state ?? null;
  }

  /** The body of a physical element (it changes when the element changes state or size). */
  bodyOf(element: HTMLElement): Body | null {
    return this.byElement.get(element)?.body ?? null;
  }

  /** True while a pointer drags `element`. */
  isDragging(element: HTMLElement): boolean {
    return this.input.isDragging(element);
  }

  /** Frames drawn so far, and whether a frame is scheduled (false when everything rests). */
  get frameCount(): number {
    return this.loop.frameCount;
  }

  get isRunning(): boolean {
    return this.loop.isRunning;
  }

  /** Replaces the frame source (a `ManualFrameScheduler` for tests and benchmarks). */
  set frameScheduler(value: FrameScheduler | null) {
    this.loop.reset();
    this.loop.setScheduler(value ?? animationFrameScheduler);
  }

  // ------------------------------------------------------------------ changing

  /** Makes `element` (inside the container) physical, in its layout. */
  add(element: HTMLElement): void {
    this.addAll([element]);
  }

  /** Gives `element` back to plain layout: its body leaves, its inline styles are restored. */
  remove(element: HTMLElement): void {
    const item = this.byElement.get(element);
    if (item === undefined) return;
    this.dropGrabs(item);
    this.world.remove(item.body);
    this.byElement.delete(element);
    this.items.splice(this.items.indexOf(item), 1);
    this.environment?.unobserve(element);
    element.style.transform = item.savedTransform;
    element.style.transformOrigin = item.savedOrigin;
    element.style.touchAction = item.savedTouchAction;
    delete element.dataset['physical'];
  }

  /** Lets `element` (or every element) fall from where it is. Does nothing under reduced motion. */
  release(element?: HTMLElement): void {
    if (!this.motionAllowed) return;
    for (const item of this.select(element)) {
      if (item.state !== 'free') this.setState(item, 'free');
    }
    this.loop.invalidate();
  }

  /** Springs `element` (or every element) back to its layout slot. */
  restore(element?: HTMLElement): void {
    for (const item of this.select(element)) {
      this.dropGrabs(item);
      if (item.state !== 'free') continue;
      if (!this.motionAllowed) {
        this.setState(item, 'layout');
        continue;
      }
      const turn = 2 * Math.PI;
      item.homeAngle = Math.round(item.body.angle / turn) * turn;
      item.returnTime = 0;
      this.setState(item, 'returning');
    }
    this.loop.invalidate();
  }

  /**
   * Measures again: layout slots, sizes, corner radii and the container's walls. Called by
   * itself when the container or an element resizes; call it after moving elements in the
   * layout by other means.
   */
  measure(): void {
    if (this.destroyed) return;
    const elements = this.items.map((item) => item.element);
    const slots = measureSlots(
      this.container,
      elements,
      this.frame,
      this.items.map((item) => ({ ...item.slot })),
    );
    this.frameStale = false;
    const ppm = this.ppm;
    this.walls.rebuild(
      this.world,
      this.frame.width / ppm,
      this.frame.height / ppm,
      this.material.friction,
    );
    const movedIn: Item[] = [];
    for (let i = 0; i < this.items.length; i++) {
      const item = this.items[i]!;
      const slot = slots[i]!;
      const old = item.slot;
      const reshaped =
        Math.abs(slot.width - old.width) > 0.01 ||
        Math.abs(slot.height - old.height) > 0.01 ||
        Math.abs(slot.radius - old.radius) > 0.01;
      const moved =
        Math.abs(slot.centerX - old.centerX) > 0.01 || Math.abs(slot.centerY - old.centerY) > 0.01;
      Object.assign(old, slot);
      if (reshaped) this.rebuildBody(item, item.body.type);
      else if (moved && item.state === 'layout') {
        item.body.position = { x: slot.centerX / ppm, y: slot.centerY / ppm };
      }
      if (item.state !== 'layout' && this.keepInside(item)) movedIn.push(item);
      if (item.state === 'layout') item.shown = true; // rewrite: '' after the slot moved
    }
    for (const item of movedIn) this.liftClear(item);
    this.loop.invalidate();
  }

  /** Stops everything and gives every element back its inline styles. */
  destroy(): void {
    if (this.destroyed) return;
    for (const element of this.elements) this.remove(element);
    this.input.detach();
    for (const undo of this.teardown) undo();
    this.teardown.length = 0;
    this.loop.suspend('detached');
    this.walls.remove(this.world);
    this.destroyed = true;
  }

  // ------------------------------------------------------------------ internals

  private environment: EnvironmentWatch | null = null;

  private select(element: HTMLElement | undefined): Item[] {
    if (element === undefined) return this.items.slice();
    const item = this.byElement.get(element);
    return item === undefined ? [] : [item];
  }

  private addAll(elements: readonly HTMLElement[]): void {
    const fresh = elements.filter((element) => {
      if (!(element instanceof HTMLElement) || !this.container.contains(element)) {
        throw new PhysicalError('element', 'must be an HTMLElement inside the container.');
      }
      return element !== this.container && !this.byElement.has(element);
    });
    if (fresh.length === 0) return;
    const slots = measureSlots(this.container, fresh, this.frame, []);
    this.frameStale = false;
    const ppm = this.ppm;
    this.walls.rebuild(
      this.world,
      this.frame.width / ppm,
      this.frame.height / ppm,
      this.material.friction,
    );
    const motion = this.motionAllowed;
    for (let i = 0; i < fresh.length; i++) {
      const element = fresh[i]!;
      const slot = slots[i]!;
      const x = slot.centerX / ppm;
      const y = slot.centerY / ppm;
      const item: Item = {
        element,
        body: this.makeBody(element, slot, 'static', x, y, 0, 0, 0, 0),
        state: 'layout',
        slot,
        prevX: x,
        prevY: y,
        prevAngle: 0,
        homeAngle: 0,
        returnTime: 0,
        shown: false,
        shownX: 0,
        shownY: 0,
        shownAngle: 0,
        savedTransform: element.style.transform,
        savedOrigin: element.style.transformOrigin,
        savedTouchAction: element.style.touchAction,
      };
      // The body turns about its centre of mass, the box's centre; CSS turns about
      // transform-origin, which defaults to the centre too, but a stylesheet may move it.
      element.style.transformOrigin = '50% 50%';
      if (motion) element.style.touchAction = 'none';
      element.dataset['physical'] = 'layout';
      this.items.push(item);
      this.byElement.set(element, item);
      this.environment?.observe(element);
    }
    this.loop.invalidate();
  }

  /** A body for `element` with the shape of its slot, added to the world. */
  private makeBody(
    element: HTMLElement,
    slot: Slot,
    type: 'static' | 'kinematic' | 'dynamic',
    x: number,
    y: number,
    angle: number,
    vx: number,
    vy: number,
    w: number,
  ): Body {
    const body = new Body<HTMLElement>({
      type,
      position: { x, y },
      angle,
      ...(type === 'static' ? {} : { linearVelocity: { x: vx, y: vy }, angularVelocity: w }),
      shapes: [shapeForBox(slot, this.ppm, this.material)],
      userData: element,
    });
    return this.world.add(body);
  }

  /** Replaces the item's body by one of `type` at the same pose and velocity. */
  private rebuildBody(item: Item, type: 'static' | 'kinematic' | 'dynamic'): void {
    const old = item.body;
    const { x, y } = old.position;
    const velocity = old.linearVelocity;
    const body = this.makeBody(
      item.element,
      item.slot,
      type,
      x,
      y,
      old.angle,
      velocity.x,
      velocity.y,
      old.angularVelocity,
    );
    this.world.remove(old);
    item.body = body;
    for (const entry of this.grabs.values()) if (entry.item === item) entry.grab.rebind(body);
  }

  private setState(item: Item, state: ElementState): void {
    const ppm = this.ppm;
    if (state === 'layout') {
      const x = item.slot.centerX / ppm;
      const y = item.slot.centerY / ppm;
      this.world.remove(item.body);
      item.body = this.makeBody(item.element, item.slot, 'static', x, y, 0, 0, 0, 0);
      item.prevX = x;
      item.prevY = y;
      item.prevAngle = 0;
    } else {
      this.rebuildBody(item, state === 'free' ? 'dynamic' : 'kinematic');
    }
    item.state = state;
    item.element.dataset['physical'] = state;
  }

  /**
   * A body left outside the walls (the container shrank) goes back in, at the nearest place.
   * Returns true if it moved.
   */
  private keepInside(item: Item): boolean {
    const ppm = this.ppm;
    const halfW = item.slot.width / 2 / ppm;
    const halfH = item.slot.height / 2 / ppm;
    const width = this.frame.width / ppm;
    const height = this.frame.height / ppm;
    const reach = Math.hypot(halfW, halfH);
    const { x, y } = item.body.position;
    const marginX = Math.min(reach, width / 2);
    const marginY = Math.min(reach, height / 2);
    const cx = Math.min(Math.max(x, marginX), width - marginX);
    const cy = Math.min(Math.max(y, marginY), height - marginY);
    if (cx === x && cy === y) return false;
    item.body.position = { x: cx, y: cy };
    item.prevX = cx;
    item.prevY = cy;
    return true;
  }

  /**
   * Lifts a body keepInside moved until its box clears every other element's (boxes unrotated),
   * or it reaches the top. Bodies moved in from a shrinking container's edge land on the same
   * line, deep inside one another; pushed apart at the solver's speed cap, one can be pressed
   * into a wall. Lifted clear, they only fall back onto one another.
   */
  private liftClear(item: Item): void {
    const ppm = this.ppm;
    const halfW = item.slot.width / 2 / ppm;
    const halfH = item.slot.height / 2 / ppm;
    const { x } = item.body.position;
    let y = item.body.position.y;
    const top = Math.min(Math.hypot(halfW, halfH), this.frame.height / ppm / 2);
    const overlaps = (): boolean =>
      this.items.some((other) => {
        if (other === item) return false;
        const at = other.body.position;
        return (
          Math.abs(at.x - x) < halfW + other.slot.width / 2 / ppm &&
          Math.abs(at.y - y) < halfH + other.slot.height / 2 / ppm
        );
      });
    const start = y;
    while (y > top && overlaps()) y = Math.max(top, y - halfH / 2);
    if (y === start) return;
    item.body.position = { x, y };
    item.prevY = y;
  }

  private elementAt(target: EventTarget | null): HTMLElement | null {
    let node = target instanceof Node ? target : null;
    while (node !== null && node !== this.container) {
      if (node instanceof HTMLElement && this.byElement.has(node)) return node;
      node = node.parentNode;
    }
    return null;
  }

  /** Client point to world point (m); re-reads the container's place only after a scroll. */
  private clientToWorld(clientX: number, clientY: number): [number, number] {
    if (this.frameStale) {
      measureContainer(this.container, this.frame);
      this.frameStale = false;
    }
    const frame = this.frame;
    const scale = frame.scale * this.ppm;
    return [(clientX - frame.left) / scale, (clientY - frame.top) / scale];
  }

  private dragStart(
    pointerId: number,
    element: HTMLElement,
    clientX: number,
    clientY: number,
  ): boolean {
    const item = this.byElement.get(element);
    if (item === undefined || !this.motionAllowed) return false;
    if (item.state !== 'free') this.setState(item, 'free');
    const [x, y] = this.clientToWorld(clientX, clientY);
    this.grabs.set(pointerId, { grab: new Grab(this.world, item.body, x, y), item });
    item.element.dataset['physical'] = 'dragging';
    this.loop.invalidate();
    return true;
  }

  private dragMove(pointerId: number, clientX: number, clientY: number): void {
    const entry = this.grabs.get(pointerId);
    if (entry === undefined) return;
    const [x, y] = this.clientToWorld(clientX, clientY);
    entry.grab.setTarget(x, y);
    this.loop.invalidate();
  }

  private dragEnd(pointerId: number, vx: number, vy: number): void {
    const entry = this.grabs.get(pointerId);
    if (entry === undefined) return;
    this.grabs.delete(pointerId);
    entry.grab.release();
    const { item } = entry;
    if (item.state === 'free') {
      // The throw: the finger's velocity (client px/s to m/s), capped.
      const scale = this.frame.scale * this.ppm;
      let sx = vx / scale;
      let sy = vy / scale;
      const speed = Math.hypot(sx, sy);
      if (speed > MAX_THROW_SPEED) {
        sx *= MAX_THROW_SPEED / speed;
        sy *= MAX_THROW_SPEED / speed;
      }
      if (speed > 0) item.body.linearVelocity = { x: sx, y: sy };
      let held = false;
      for (const other of this.grabs.values()) if (other.item === item) held = true;
      if (!held) item.element.dataset['physical'] = 'free';
    }
    this.loop.invalidate();
  }

  private dropGrabs(item: Item): void {
    for (const [pointerId, entry] of this.grabs) {
      if (entry.item === item) {
        entry.grab.release();
        this.grabs.delete(pointerId);
      }
    }
  }

  private motionChanged(): void {
    const motion = this.motionAllowed;
    if (!motion) {
      this.input.cancelAll();
      for (const entry of this.grabs.values()) entry.grab.release();
      this.grabs.clear();
      for (const item of this.items) if (item.state !== 'layout') this.setState(item, 'layout');
    }
    for (const item of this.items) {
      item.element.style.touchAction = motion ? 'none' : item.savedTouchAction;
    }
    this.loop.invalidate();
  }

  // ------------------------------------------------------------------ the frame

  private step(dt: number): void {
    const ppm = this.ppm;
    for (const item of this.items) {
      const body = item.body;
      const position = body.position;
      item.prevX = position.x;
      item.prevY = position.y;
      item.prevAngle = body.angle;
      if (item.state === 'returning') this.springBack(item, dt, ppm);
    }
    this.world.step(dt);
    for (const item of this.items) {
      if (item.state === 'returning' && this.hasArrived(item, ppm)) this.setState(item, 'layout');
    }
  }

  /** Sets a returning body's velocity so that it lands on the spring's path after this step. */
  private springBack(item: Item, dt: number, ppm: number): void {
    const body = item.body;
    const omega = this.returnOmega;
    const position = body.position;
    const velocity = body.linearVelocity;
    const ex = position.x - item.slot.centerX / ppm;
    const ey = position.y - item.slot.centerY / ppm;
    const ea = body.angle - item.homeAngle;
    const ex1 = springStep(ex, velocity.x, omega, dt, spring)[0];
    const ey1 = springStep(ey, velocity.y, omega, dt, spring)[0];
    const ea1 = springStep(ea, body.angularVelocity, omega, dt, spring)[0];
    velocityScratch.x = (ex1 - ex) / dt;
    velocityScratch.y = (ey1 - ey) / dt;
    body.linearVelocity = velocityScratch; // copied by the body
    body.angularVelocity = (ea1 - ea) / dt;
    item.returnTime += dt;
  }

  private hasArrived(item: Item, ppm: number): boolean {
    if (item.returnTime >= MAX_RETURN_TIME) return true;
    const body = item.body;
    const position = body.position;
    const dx = position.x * ppm - item.slot.centerX;
    const dy = position.y * ppm - item.slot.centerY;
    return (
      Math.abs(dx) < ARRIVED_PX &&
      Math.abs(dy) < ARRIVED_PX &&
      Math.abs(body.angle - item.homeAngle) < ARRIVED_RAD
    );
  }

  /** Writes each moved element's transform: the only DOM write of a frame, and no reads. */
  private render(alpha: number): void {
    const ppm = this.ppm;
    const pixel = 1 / (this.devicePixelRatio * this.frame.scale);
    const beta = 1 - alpha;
    for (const item of this.items) {
      const element = item.element;
      if (item.state === 'layout') {
        if (item.shown) {
          element.style.transform = item.savedTransform;
          item.shown = false;
        }
        continue;
      }
      const body = item.body;
      const position = body.position;
      const x = beta * item.prevX + alpha * position.x;
      const y = beta * item.prevY + alpha * position.y;
      const angle = beta * item.prevAngle + alpha * body.angle;
      const dx = snap(x * ppm - item.slot.centerX, pixel);
      const dy = snap(y * ppm - item.slot.centerY, pixel);
      if (
        item.shown &&
        dx === item.shownX &&
        dy === item.shownY &&
        Math.abs(angle - item.shownAngle) < 1e-4
      ) {
        continue;
      }
      element.style.transform = formatTransform(dx, dy, angle);
      item.shown = true;
      item.shownX = dx;
      item.shownY = dy;
      item.shownAngle = angle;
    }
  }

  private isSettled(): boolean {
    if (!this.motionAllowed) return true;
    if (this.grabs.size > 0) return false;
    for (const item of this.items) if (item.state === 'returning') return false;
    return this.world.awakeBodyCount === 0;
  }

  // ------------------------------------------------------------------ environment

  private watch(): void {
    const container = this.container;
    const undo = this.teardown;
    const environment = watchEnvironment(container, this.loop, {
      resized: () => this.measure(),
      scrolled: () => {
        this.frameStale = true;
      },
      reducedMotionChanged: (reduce) => {
        this.prefersReduced = reduce;
        this.motionChanged();
      },
      densityChanged: (ratio) => {
        this.devicePixelRatio = ratio;
        this.frameStale = true;
        this.loop.invalidate();
      },
    });
    this.prefersReduced = environment.prefersReducedMotion;
    this.environment = environment;
    undo.push(() => environment.stop());

    // Elements that leave the DOM leave the world; with a selector, matching newcomers join.
    const mutations = new MutationObserver((records) => {
      const added: HTMLElement[] = [];
      for (const record of records) {
        for (const node of record.removedNodes) {
          for (const item of this.items.slice()) {
            if (node === item.element || node.contains(item.element)) {
              if (!container.contains(item.element)) this.remove(item.element);
            }
          }
        }
        for (const node of record.addedNodes) {
          if (!(node instanceof HTMLElement)) continue;
          if (this.followChildren && node.parentNode === container) added.push(node);
          if (this.selector === null) continue;
          if (node.matches(this.selector)) added.push(node);
          added.push(...node.querySelectorAll<HTMLElement>(this.selector));
        }
      }
      const joining = [...new Set(added)].filter((element) => container.contains(element));
      if (joining.length > 0) this.addAll(joining);
    });
    mutations.observe(container, { childList: true, subtree: true });
    undo.push(() => mutations.disconnect());
  }
}

function positive(field: string, value: number): number {
  if (typeof value !== 'number' || !Number.isFinite(value) || value <= 0) {
    throw new PhysicalError(field, `must be a finite number greater than 0, got ${String(value)}.`);
  }
  return value;
}

function nonNegative(field: string, value: number): number {
  if (typeof value !== 'number' || !Number.isFinite(value) || value < 0) {
    throw new PhysicalError(field, `must be a finite number, 0 or more, got ${String(value)}.`);
  }
  return value;
}
