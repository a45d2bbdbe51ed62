import {
  stateLayout,
  type Joint,
  type JointState,
  type JointStateLayout,
  type SavedFields,
} from './joint.ts';
import { REACTION_ANGULAR, REACTION_X, SUB_STEP_DURATION } from './joint-record.ts';

// A joint's state as world snapshots save and load it: free functions, not Joint methods, so that
// an app without snapshots (a canvas whose drag adds a mouse joint, a worker world's page) does
// not bundle them with the Joint class.

/** @internal Saved for every kind of joint: what the last step left. */
const JOINT_SAVED: SavedFields = {
  reactionForce: ['vector', REACTION_X],
  reactionTorque: ['finite', REACTION_ANGULAR],
  subStepDuration: ['positive', SUB_STEP_DURATION],
};

/** @internal Saved for every kind of joint (see {@link exportJointState}). */
export const JOINT_STATE: JointStateLayout = /* @__PURE__ */ stateLayout(
  { saved: JOINT_SAVED },
  [],
);

/**
 * @internal Everything about `joint` that decides later steps, by the names of its kind's layout
 * plus {@link JOINT_STATE} (world snapshots): frames, settings, and the accumulated impulses the
 * next step warm-starts from. What prepare() recomputes every step is left out.
 */
export function exportJointState(joint: Joint): JointState {
  const state: JointState = {};
  exportFields(joint, joint.savedFields, state);
  exportFields(joint, JOINT_SAVED, state);
  return state;
}

/** @internal Puts back what {@link exportJointState} saved; the values were checked by the loader. */
export function importJointState(joint: Joint, state: JointState): void {
  importFields(joint, joint.savedFields, state);
  importFields(joint, JOINT_SAVED, state);
}

function exportFields(joint: Joint, saved: SavedFields, state: JointState): void {
  const d = joint.store.data;
  const o = joint.base;
  for (const key of Object.keys(saved)) {
    const [kind, offset] = saved[key]!;
    state[key] =
      kind === 'boolean'
        ? d[o + offset] === 1
        : kind === 'vector' || kind === 'unitVector'
          ? [d[o + offset]!, d[o + offset + 1]!]
          : d[o + offset]!;
  }
}

function importFields(joint: Joint, saved: SavedFields, state: JointState): void {
  const d = joint.store.data;
  const o = joint.base;
  for (const key of Object.keys(saved)) {
    const offset = saved[key]![1];
    const value = state[key]!;
    if (typeof value === 'boolean') d[o + offset] = value ? 1 : 0;
    else if (typeof value === 'number') d[o + offset] = value;
    else {
      d[o + offset] = value[0]!;
      d[o + offset + 1] = value[1]!;
    }
  }
}
