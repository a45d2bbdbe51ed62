// The samples' own Math calls, made the same in every engine for this test. A sample is an app:
// it places bodies with Math.sin and Math.cos, whose last bit each engine's math library decides
// (the engine's determinism does not cover an app's own Math calls). So that two engines build
// the same worlds, the test bundle sends the samples' calls here; the engine's code is bundled
// untouched, so any Math call left in the step would still show.
import { hypot } from '../../../engine/src/math/hypot.ts';
import { atan2, cosSin } from '../../../engine/src/math/trigonometry.ts';

const rotation = new Float64Array(2);

export const portableMath = {
  sin(angle: number): number {
    cosSin(angle, rotation);
    return rotation[1]!;
  },
  cos(angle: number): number {
    cosSin(angle, rotation);
    return rotation[0]!;
  },
  tan(angle: number): number {
    cosSin(angle, rotation);
    return rotation[1]! / rotation[0]!;
  },
  atan2,
  hypot,
};
