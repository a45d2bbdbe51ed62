import type { Body } from '@physical/engine';
import { DEFAULT_BACKGROUND } from '../draw/body-style.ts';
import { BodyBatches } from '../draw/draw-bodies.ts';
import { drawScene, type JointsDrawer } from '../draw/draw-scene.ts';
import type { OverlaysDrawer } from '../draw/draw-overlays.ts';
import type { DrawingSource } from '../draw/drawing-source.ts';
import type { Pose } from '../draw/pose.ts';
import type { HeldPoint, Scene } from '../draw/scene.ts';
import { computeViewport, type Viewport } from '../draw/viewport.ts';
import type { BodyStyles } from './body-styles.ts';
import type { CanvasSettings } from './canvas-settings.ts';
import type { CollisionArrows } from './collision-arrows.ts';
import type { PoseHistory } from './pose-history.ts';

/** What a {@link CanvasRenderer} reads from its element. */
export interface CanvasRendererHost {
  readonly settings: CanvasSettings;
  readonly poses: PoseHistory;
  readonly styles: BodyStyles;
  readonly arrows: CollisionArrows;
  /** The points its drag holds now. */
  held(): readonly HeldPoint[];
  /** The element's CSS size before the first resize report, or null while detached. */
  measure(): { width: number; height: number } | null;
  /** Asks for a frame: the overlays' code arrived. */
  redraw(): void;
}

/**
 * Turns the element's state into frames: keeps the viewport in step with the element's size, the
 * pixel density and the view settings, sizes the backing store, and draws the scene. One scene
 * object is reused for every frame, so drawing allocates nothing.
 */
export class CanvasRenderer {
  /** How far between the last two steps the next frame is drawn (1 = the current poses). */
  alpha = 1;
  /** prefers-reduced-motion: reduce. */
  reducedMotion = false;
  private readonly host: CanvasRendererHost;
  private readonly context: CanvasRenderingContext2D | null;
  private readonly batches = new BodyBatches();
  private readonly scene: { -readonly [K in keyof Scene]: Scene[K] };
  private cssWidth = 0;
  private cssHeight = 0;
  private viewportInputsUnchanged = false;
  /** The collision arrows and debug overlays (draw-overlays.ts), once loaded; see draw. */
  private overlays: OverlaysDrawer | null = null;
  private overlaysLoading = false;
  /** The joints' drawing (draw-joints.ts), once loaded; see draw. */
  private joints: JointsDrawer | null = null;
  private jointsLoading = false;

  constructor(host: CanvasRendererHost, context: CanvasRenderingContext2D | null) {
    this.host = host;
    this.context = context;
    const { settings, poses, styles, arrows } = host;
    this.scene = {
      viewport: computeViewport({
        width: 0,
        height: 0,
        devicePixelRatio: 1,
        fit: 'none',
        pixelsPerMeter: settings.pixelsPerMeter,
        origin: { x: 0, y: 0 },
        viewBox: null,
      }),
      world: null,
      bodies: [],
      // A remote source (a worker's world) holds its own last two states.
      poseOf: (body: Body, index: number, out: Pose): Pose => {
        const remote = this.scene.world?.remote;
        return remote === undefined
          ? poses.interpolate(body, index, this.alpha, out)
          : remote.poseOf(body, index, this.alpha, out);
      },
      styleOf: (body: Body) => styles.resolve(body),
      background: DEFAULT_BACKGROUND,
      debug: settings.debug,
      collisionArrows: arrows.arrows,
      held: host.held(),
      forceScale: settings.forceScale,
      velocityScale: settings.velocityScale,
      reducedMotion: false,
    };
  }

  /** The element's content box is now `width` x `height` CSS px. */
  resize(width: number, height: number): void {
    this.cssWidth = width;
    this.cssHeight = height;
  }

  /** A setting changed: compute the viewport again before the next use. */
  settingsChanged(): void {
    this.viewportInputsUnchanged = false;
  }

  /** The mapping in use, brought up to date. */
  get viewport(): Viewport {
    this.updateViewport();
    return this.scene.viewport;
  }

  /** Draws a frame of `world`, then `overlay` (app drawings in world metres). */
  draw(
    world: DrawingSource | null,
    overlay: ((context: CanvasRenderingContext2D) => void) | null,
  ): void {
    const context = this.context;
    if (context === null) return;
    this.updateViewport();
    const viewport = this.scene.viewport;
    const canvas = context.canvas;
    const width = Math.max(1, Math.round(viewport.width * viewport.devicePixelRatio));
    const height = Math.max(1, Math.round(viewport.height * viewport.devicePixelRatio));
    if (canvas.width !== width || canvas.height !== height) {
      canvas.width = width;
      canvas.height = height;
    }
    const settings = this.host.settings;
    const scene = this.scene;
    scene.world = world;
    scene.bodies = world === null ? [] : world.bodies;
    scene.background = settings.background;
    scene.debug = settings.debug;
    scene.forceScale = settings.forceScale;
    scene.velocityScale = settings.velocityScale;
    scene.reducedMotion = this.reducedMotion;
    scene.held = this.host.held();
    if (this.overlays === null && wantsOverlays(scene)) this.loadOverlays();
    if (this.joints === null && world !== null && world.joints.length + scene.held!.length > 0) {
      this.loadJoints();
    }
    drawScene(context, scene, this.batches, overlay, this.overlays, this.joints);
  }

  /**
   * Loads the overlays' chunk the first time a frame asks for them, then draws again: they
   * appear a frame or two after being turned on, and pages that never show them never load it.
   */
  private loadOverlays(): void {
    if (this.overlaysLoading) return;
    this.overlaysLoading = true;
    void import('../draw/draw-overlays.ts').then(({ drawOverlays }) => {
      this.overlays = drawOverlays;
      this.host.redraw();
    });
  }

  /**
   * Loads the joints' drawing the first time a frame has joints (or a held body), then draws
   * again, as the overlays: pages whose worlds have no joints and are never dragged never load it.
   */
  private loadJoints(): void {
    if (this.jointsLoading) return;
    this.jointsLoading = true;
    void import('../draw/draw-joints.ts').then(({ drawJoints }) => {
      this.joints = drawJoints;
      this.host.redraw();
    });
  }

  private updateViewport(): void {
    if (this.cssWidth === 0 && this.cssHeight === 0) {
      // Before the first ResizeObserver report, read the size from layout.
      const size = this.host.measure();
      if (size !== null) {
        this.cssWidth = size.width;
        this.cssHeight = size.height;
      }
    }
    const current = this.scene.viewport;
    const settings = this.host.settings;
    // Capped by max-pixel-ratio: on a DPR 3 phone a full-resolution canvas is 9 device pixels
    // per CSS px to fill every frame, and rasterising them is most of a frame's cost.
    const devicePixelRatio = Math.min(
      typeof window === 'undefined' ? 1 : window.devicePixelRatio || 1,
      settings.maxPixelRatio,
    );
    if (
      current.width === this.cssWidth &&
      current.height === this.cssHeight &&
      current.devicePixelRatio === devicePixelRatio &&
      this.viewportInputsUnchanged
    ) {
      return;
    }
    this.viewportInputsUnchanged = true;
    this.scene.viewport = computeViewport({
      width: this.cssWidth,
      height: this.cssHeight,
      devicePixelRatio,
      fit: settings.fit,
      pixelsPerMeter: settings.pixelsPerMeter,
      origin: settings.origin,
      viewBox: settings.viewBox,
    });
  }
}

/** Whether a frame of `scene` shows collision arrows or a debug overlay. */
function wantsOverlays(scene: Scene): boolean {
  const debug = scene.debug;
  return (
    scene.collisionArrows.length > 0 ||
    debug.aabbs ||
    debug.centers ||
    debug.velocities ||
    debug.contacts ||
    debug.normals
  );
}
