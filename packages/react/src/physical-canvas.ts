import type {
  AttributeErrorDetail,
  DebugOverlays,
  DrawingSource,
  FitMode,
  FrameScheduler,
  OverlayDrawer,
  PauseChangeDetail,
  PhysicalCanvasElement,
  PointerEventDetail,
  StyleResolver,
  ViewBox,
} from '@physical/canvas';
import { define } from '@physical/canvas';
import type { Vec2Like, World } from '@physical/engine';
import {
  createElement,
  forwardRef,
  useEffect,
  useImperativeHandle,
  useLayoutEffect,
  useRef,
  type CSSProperties,
  type ForwardRefExoticComponent,
  type RefAttributes,
} from 'react';

/** Props of {@link PhysicalCanvas}: the element's attributes and properties, and its events. */
export interface PhysicalCanvasProps {
  /**
   * The world to run and draw (the element steps it): a `World`, or a `WorkerWorld` of
   * `@physical/worker` (see {@link useWorkerWorld}).
   */
  world: World | DrawingSource | null;
  /** CSS px per metre with `fit="none"`. Default 50. */
  pixelsPerMeter?: number;
  /** World point (m) at the top-left corner with `fit="none"`. Default (0, 0). */
  origin?: Vec2Like;
  /** `"none"` (default), `"contain"` or `"cover"` the `viewBox`. */
  fit?: FitMode;
  /** World rectangle (m) kept in view by `fit="contain"` or `"cover"`. */
  viewBox?: ViewBox | null;
  /** Stops time. */
  paused?: boolean;
  /** Simulated seconds per real second (slow motion below 1). Default 1. */
  timeScale?: number;
  /** Background colour. Default `#121212`. */
  background?: string;
  /** Debug overlays: `"contacts normals"`, `"all"`, or an array of names. */
  debug?: string | readonly (keyof DebugOverlays)[];
  /** Equal and opposite collision-force arrows that fade. */
  collisionArrows?: boolean;
  /** Seconds a collision arrow takes to fade. Default 1. */
  collisionArrowDuration?: number;
  /** Metres of collision arrow per newton. Default 0.01. */
  forceScale?: number;
  /** Seconds of motion a velocity arrow shows. Default 0.25. */
  velocityScale?: number;
  /** Fixed steps per simulated second. Default 60. */
  stepsPerSecond?: number;
  /** Catch-up cap after a stall. Default 4. */
  maxStepsPerFrame?: number;
  /** Pointers drag and throw dynamic bodies. Default true; false renders `drag="off"`. */
  drag?: boolean;
  /** Cap on device pixels per CSS px: 2 draws a 3x phone at 4 pixels per CSS px, not 9. */
  maxPixelRatio?: number;
  /** Style of each body (return shared objects: it is called every frame). */
  styleFor?: StyleResolver | null;
  /** App drawings after the bodies, in world metres. */
  drawOverlay?: OverlayDrawer | null;
  /** Frame source; default `requestAnimationFrame`. */
  frameScheduler?: FrameScheduler | null;
  /** A body was tapped. */
  onBodyTap?: (detail: PointerEventDetail) => void;
  /** A pointer pressed a body. */
  onBodyPress?: (detail: PointerEventDetail) => void;
  /** A pointer that pressed a body was released. */
  onBodyRelease?: (detail: PointerEventDetail) => void;
  /** Empty space was tapped (`detail.point` in metres). */
  onBackgroundTap?: (detail: PointerEventDetail) => void;
  /** An attribute had a value the element cannot use. */
  onAttributeError?: (detail: AttributeErrorDetail) => void;
  /** The keyboard (Space) paused or resumed the simulation. */
  onPauseChange?: (detail: PauseChangeDetail) => void;
  /** Accessible name. Default "Physics simulation". */
  'aria-label'?: string;
  id?: string;
  className?: string;
  style?: CSSProperties;
}

const EVENTS = {
  bodytap: 'onBodyTap',
  bodypress: 'onBodyPress',
  bodyrelease: 'onBodyRelease',
  backgroundtap: 'onBackgroundTap',
  attributeerror: 'onAttributeError',
  pausechange: 'onPauseChange',
} as const;

// Layout effects do not run in server rendering; this avoids React 18's warning there.
const useClientLayoutEffect = typeof document === 'undefined' ? useEffect : useLayoutEffect;

// React 19 sets a custom element's prop as the property of the same name when the element has
// one (paused, origin, fit, debug, background), and as an attribute otherwise (the dashed names);
// React 18 sets every one as an attribute, turning `false` into "false" and an object into
// "[object Object]". So each value is one both read alike: `paused` is `true` or absent (the
// property takes the boolean; the attribute's presence means paused), `origin` the "x y" text
// that both the property and the attribute parse. On the server they are written as attributes.
function attributes(props: PhysicalCanvasProps): Record<string, string | true | undefined> {
  const { origin, viewBox, debug } = props;
  const text = (value: number | string | undefined): string | undefined =>
    value === undefined ? undefined : String(value);
  return {
    id: props.id,
    'aria-label': props['aria-label'],
    'pixels-per-meter': text(props.pixelsPerMeter),
    origin: origin === undefined ? undefined : `${origin.x} ${origin.y}`,
    fit: props.fit,
    'view-box':
      viewBox === undefined || viewBox === null
        ? undefined
        : `${viewBox.x} ${viewBox.y} ${viewBox.width} ${viewBox.height}`,
    paused: props.paused === true ? true : undefined,
    'time-scale': text(props.timeScale),
    background: props.background,
    debug: debug === undefined ? undefined : typeof debug === 'string' ? debug : debug.join(' '),
    'collision-arrows': props.collisionArrows === true ? '' : undefined,
    'collision-arrow-duration': text(props.collisionArrowDuration),
    'force-scale': text(props.forceScale),
    'velocity-scale': text(props.velocityScale),
    'steps-per-second': text(props.stepsPerSecond),
    'max-steps-per-frame': text(props.maxStepsPerFrame),
    drag: props.drag === false ? 'off' : undefined,
    'max-pixel-ratio': text(props.maxPixelRatio),
  };
}

/**
 * `<PhysicalCanvas world={world} pixelsPerMeter={40} onBodyTap={({ body }) => ...} />`: the
 * `<physical-canvas>` element in React. Settings become attributes (so they appear in server
 * rendered HTML); the world, callbacks and events are attached on the client. Registers the
 * element on first mount; safe under StrictMode's double mounting; touches no `window` at import.
 * The ref is the element (for `screenToWorld`, `setStyle`, `invalidate`, and `step()`: one fixed
 * step of a paused canvas, drawn at once).
 */
export const PhysicalCanvas: ForwardRefExoticComponent<
  PhysicalCanvasProps & RefAttributes<PhysicalCanvasElement | null>
> = forwardRef<PhysicalCanvasElement | null, PhysicalCanvasProps>(
  function PhysicalCanvas(props, ref) {
    const element = useRef<PhysicalCanvasElement | null>(null);
    const latest = useRef(props);
    latest.current = props;
    useImperativeHandle(ref, () => element.current!, []);

    const { world, styleFor = null, drawOverlay = null, frameScheduler = null } = props;
    useClientLayoutEffect(() => {
      define();
      const canvas = element.current!;
      canvas.frameScheduler = frameScheduler;
      canvas.styleFor = styleFor;
      canvas.drawOverlay = drawOverlay;
      canvas.world = world;
    }, [world, styleFor, drawOverlay, frameScheduler]);

    useEffect(() => {
      const canvas = element.current!;
      const listeners = Object.entries(EVENTS).map(([type, prop]) => {
        const listener = (event: Event): void => {
          const handler = latest.current[prop] as ((detail: unknown) => void) | undefined;
          handler?.((event as CustomEvent<unknown>).detail);
        };
        canvas.addEventListener(type, listener);
        return () => canvas.removeEventListener(type, listener);
      });
      return () => {
        for (const remove of listeners) remove();
      };
    }, []);

    return createElement('physical-canvas', {
      ref: element,
      style: props.style,
      className: props.className,
      ...attributes(props),
    });
  },
);
