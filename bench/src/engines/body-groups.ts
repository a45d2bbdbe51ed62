import type { BodyGroupDesc, Pose, World } from '../types.ts';

/** What an adapter says about its own bodies so {@link bodyGroups} can keep groups of them. */
export interface GroupBodies<B> {
  /** Creates a group's bodies and joints; the bodies in `group.bodies` order. */
  create(group: BodyGroupDesc): B[];
  /** Destroys one body (each engine here destroys the body's joints with it). */
  destroy(body: B): void;
  /** A body's pose in Box2D's frame. */
  pose(body: B): Pose;
}

/**
 * The groups a scene creates and destroys while it runs (rain's ragdolls), kept the same way for
 * every engine: a handle per group, and every live body's pose for the quality check.
 */
export function bodyGroups<B>(
  bodies: GroupBodies<B>,
): Required<Pick<World, 'createGroup' | 'destroyGroup' | 'groupPoses'>> {
  const groups = new Map<number, B[]>();
  let nextGroup = 0;
  return {
    createGroup(group) {
      groups.set(nextGroup, bodies.create(group));
      return nextGroup++;
    },
    destroyGroup(handle) {
      for (const body of groups.get(handle) ?? []) bodies.destroy(body);
      groups.delete(handle);
    },
    groupPoses() {
      const poses: Pose[] = [];
      for (const list of groups.values()) for (const body of list) poses.push(bodies.pose(body));
      return poses;
    },
  };
}
