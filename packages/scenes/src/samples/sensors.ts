import { type Body, World, box, particle, wall } from '@physical/engine';
import { defineScene } from '../scene.ts';

const ZONE_X = 6;
const ZONE_Y = -3.5;
const ZONE_HEIGHT = 1;
const RADIUS = 0.25;
const DROP_Y = -7;

/** What a ball records about the zone: where it started, how often it went in and out. */
interface Visits {
  readonly startX: number;
  entered: number;
  left: number;
  inside: boolean;
}

/** The zone's own tally, kept on the sensor body. */
interface Tally {
  readonly width: number;
  entered: number;
  left: number;
}

const INSIDE_FILL = '#ffeb3b';
const CROSSED_FILL = '#ef5350';
const ZONE_FILL = 'rgba(255, 235, 59, 0.18)';

/**
 * A row of balls falls onto the floor; a sensor band hangs over the middle of it. The sensor
 * never pushes: the balls under it fall straight through, and each passage is one sensorBegin
 * then one sensorEnd.
 */
export default defineScene({
  id: 'sensors',
  title: 'Sensor zone',
  description:
    'Balls fall through a sensor band, which never pushes them. sensorBegin colours a ball yellow and counts it in, sensorEnd marks it red and counts it out: each ball under the band passes once.',
  parameters: [
    { name: 'count', label: 'Balls', min: 2, max: 16, step: 1, default: 12 },
    { name: 'width', label: 'Zone width (m)', min: 1, max: 10, step: 0.5, default: 6 },
  ],
  camera: { x: -0.5, y: -8, width: 13, height: 8.5 },
  pixelsPerMeter: 40,
  steps: 180,
  build({ count, width }) {
    const world = new World();
    world.add(wall({ from: { x: -0.5, y: 0 }, to: { x: 12.5, y: 0 } }));
    const tally: Tally = { width, entered: 0, left: 0 };
    const zone = world.add(
      box<Tally>({
        type: 'static',
        position: { x: ZONE_X, y: ZONE_Y },
        width,
        height: ZONE_HEIGHT,
        sensor: true,
        userData: tally,
      }),
    );
    zone.on('sensorBegin', ({ visitorBody }) => {
      tally.entered++;
      const visits = visitorBody.userData as Visits;
      visits.entered++;
      visits.inside = true;
    });
    zone.on('sensorEnd', ({ visitorBody }) => {
      tally.left++;
      const visits = visitorBody.userData as Visits;
      visits.left++;
      visits.inside = false;
    });
    for (let i = 0; i < count; i++) {
      const x = 0.5 + (i * 11) / (count - 1);
      world.add(
        particle<Visits>({
          position: { x, y: DROP_Y },
          radius: RADIUS,
          restitution: 0,
          userData: { startX: x, entered: 0, left: 0, inside: false },
        }),
      );
    }
    return world;
  },
  fill(body: Body) {
    if (body.type === 'static') return body.shapes[0]?.sensor === true ? ZONE_FILL : null;
    const visits = body.userData as Visits | undefined;
    if (visits === undefined || visits.entered === 0) return null;
    return visits.inside ? INSIDE_FILL : CROSSED_FILL;
  },
  check(world) {
    let tally: Tally | undefined;
    let crossed = 0;
    for (const body of world.bodies) {
      if (body.type === 'static') {
        if (body.shapes[0]?.sensor === true) tally = body.userData as Tally;
        continue;
      }
      const visits = body.userData as Visits;
      if (body.position.y < ZONE_Y + ZONE_HEIGHT / 2 + RADIUS) {
        return `a ball starting at x = ${visits.startX.toFixed(2)} m has not fallen past the zone`;
      }
      // Falling straight down, a ball meets the band when its x is within half a width plus
      // its radius of the band's centre.
      const under =
        tally !== undefined && Math.abs(visits.startX - ZONE_X) < tally.width / 2 + RADIUS;
      const expected = under ? 1 : 0;
      if (visits.entered !== expected || visits.left !== expected) {
        return `the ball from x = ${visits.startX.toFixed(2)} m entered ${visits.entered} and left ${visits.left} times, expected ${expected}`;
      }
      crossed += expected;
    }
    if (tally === undefined) return 'no sensor zone';
    if (crossed === 0) return 'no ball crossed the zone';
    if (tally.entered !== crossed || tally.left !== crossed) {
      return `the zone counted ${tally.entered} in and ${tally.left} out, ${crossed} balls crossed it`;
    }
    return null;
  },
});
