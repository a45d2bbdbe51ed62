// @physical/scenes: Physical's samples, shared by the gallery, the regression suite and the docs.

export { STEP, defineScene, runScene, sceneValues } from './scene.ts';
export type { Scene, SceneCamera, SceneFollow, SceneParameter, SceneValues } from './scene.ts';
export { FOLLOW_WITHIN, sceneView } from './camera.ts';
export type { SceneView } from './camera.ts';
export { findScene, scenes } from './catalog.ts';
export { bodyStates, hashWorld } from './state-hash.ts';
export { seededRandom } from './random.ts';
export { grab } from './samples/drag-and-throw.ts';
