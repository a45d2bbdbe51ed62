// @physical/canvas's public API. Everything not listed here is internal.

export { PhysicalCanvasElement } from './element/physical-canvas-element.ts';
export type { OverlayDrawer } from './element/physical-canvas-element.ts';
export type {
  AttributeErrorDetail,
  PauseChangeDetail,
  PhysicalCanvasEventMap,
  PhysicalCanvasEvents,
} from './element/canvas-events.ts';
export type {
  PhysicalCanvasAttributes,
  PhysicalCanvasEventProps,
  PhysicalCanvasProperties,
} from './element/element-typings.ts';
export { define } from './element/define-physical-canvas.ts';
export { CanvasSettingError } from './element/attribute-parsers.ts';
export type { PointerEventDetail } from './element/pointer-input.ts';
export { TAP_SLOP } from './element/pointer-input.ts';
export { PointerVelocity, VELOCITY_WINDOW_MS } from './element/pointer-velocity.ts';
export type { StyleResolver } from './element/body-styles.ts';
export { FrameLoop } from './element/frame-loop.ts';
export type { FrameLoopTarget, SuspendReason } from './element/frame-loop.ts';
export { ManualFrameScheduler, animationFrameScheduler } from './element/frame-scheduler.ts';
export type { FrameScheduler } from './element/frame-scheduler.ts';

export { DEFAULT_BACKGROUND, DYNAMIC_PALETTE } from './draw/body-style.ts';
export type { BodyDrawInfo, BodyStyle, ResolvedBodyStyle } from './draw/body-style.ts';
export { ARROW_COLORS, drawArrow } from './draw/draw-arrow.ts';
export { ArrowBatch } from './draw/arrow-batch.ts';
export type { ArrowKind, ArrowStyle } from './draw/draw-arrow.ts';
export type { DebugOverlays } from './draw/debug-overlays.ts';
export type { Pose } from './draw/pose.ts';
export { MAX_REMOTE_STEPS_IN_FLIGHT } from './draw/drawing-source.ts';
export type {
  CollisionLike,
  DrawingSource,
  DrawnJoint,
  RemoteDrawing,
} from './draw/drawing-source.ts';
export { computeViewport, screenToWorld, worldToScreen } from './draw/viewport.ts';
export type { FitMode, ViewBox, Viewport, ViewportInput } from './draw/viewport.ts';
