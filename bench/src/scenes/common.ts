import type { BodyDesc, MaterialDesc, ShapeDesc } from '../types.ts';

export const BOX2D_MATERIAL: Required<MaterialDesc> = { density: 1, friction: 0.6, restitution: 0 };

export function box(hw: number, hh: number, cx = 0, cy = 0, angle = 0): ShapeDesc {
  return { kind: 'box', hw, hh, cx, cy, angle };
}

export function dynamicBox(x: number, y: number, hw: number, hh = hw): BodyDesc {
  return { type: 'dynamic', x, y, shapes: [box(hw, hh)] };
}

/** Options every scene builder takes. `small` is Box2D's debug size (used by --quick). */
export interface SceneOptions {
  readonly small: boolean;
}
