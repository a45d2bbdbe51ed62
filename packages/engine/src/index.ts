// Physical's public API. Everything not listed here is internal.

export { World } from './world/world.ts';
export type { WorldEvents } from './world/world.ts';
export type { WorldOptions } from './world/world-options.ts';
export type { RayCastHit } from './world/queries.ts';
export {
  checkQueryBox,
  checkRay,
  checkTimeStep,
  checkWorldOptions,
  checkWorldSetting,
} from './world/world-checks.ts';
export type { WorldSettingName, WorldSettingValues } from './world/world-checks.ts';
export { bodyAtPoint } from './world/body-at-point.ts';
export { restoreSnapshot, takeSnapshot } from './world/snapshot.ts';
export type { SnapshotNumber, SnapshotValue, WorldSnapshot } from './world/snapshot.ts';
export type { QueryPose, ShapeCastHit } from './world/shape-queries.ts';

export { Body } from './dynamics/body.ts';
export type { BodyOptions, BodyType } from './dynamics/body.ts';
export {
  box,
  capsule,
  particle,
  polygon,
  regularPolygon,
  wall,
} from './dynamics/body-factories.ts';
export type {
  BoxOptions,
  CapsuleOptions,
  ParticleOptions,
  PolygonOptions,
  RegularPolygonOptions,
  WallOptions,
} from './dynamics/body-factories.ts';
export { Shape } from './dynamics/shape.ts';
export type {
  BoxShapeOptions,
  CapsuleShapeOptions,
  CircleShapeOptions,
  CollisionOptions,
  Geometry,
  MaterialOptions,
  PolygonShapeOptions,
  SegmentShapeOptions,
  ShapeOptions,
} from './dynamics/shape.ts';
export type { Capsule } from './geometry/capsule.ts';
export type { Circle } from './geometry/circle.ts';
export type { Polygon } from './geometry/polygon.ts';
export type { Segment } from './geometry/segment.ts';
export { Force } from './dynamics/force.ts';
export type { Duration, ForceOptions, TorqueOptions } from './dynamics/force.ts';
export type {
  BodyEvents,
  CollisionEvent,
  ContactEvent,
  ContactPoint,
  ContactView,
  SensorEvent,
  WorldOnlyEvents,
} from './dynamics/events.ts';
export type { Filter, FilterOptions } from './dynamics/filter.ts';

export { Joint } from './dynamics/joints/joint.ts';
export type { JointOptions, JointType } from './dynamics/joints/joint.ts';
export {
  distanceJoint,
  mouseJoint,
  prismaticJoint,
  revoluteJoint,
  weldJoint,
} from './dynamics/joints/joint-factories.ts';
export { DistanceJoint } from './dynamics/joints/distance-joint.ts';
export type { DistanceJointOptions } from './dynamics/joints/distance-joint.ts';
export { MouseJoint } from './dynamics/joints/mouse-joint.ts';
export type { MouseJointOptions } from './dynamics/joints/mouse-joint.ts';
export { PrismaticJoint } from './dynamics/joints/prismatic-joint.ts';
export type { PrismaticJointOptions } from './dynamics/joints/prismatic-joint.ts';
export { RevoluteJoint } from './dynamics/joints/revolute-joint.ts';
export type { RevoluteJointOptions } from './dynamics/joints/revolute-joint.ts';
export { WeldJoint } from './dynamics/joints/weld-joint.ts';
export type { WeldJointOptions } from './dynamics/joints/weld-joint.ts';

export { PhysicalError } from './core/errors.ts';
export type { Vec2, Vec2Like } from './math/vec2.ts';
