import { type Body, World, particle, wall } from '@physical/engine';
import { defineScene } from '../scene.ts';

/** Category bits: the ground keeps the default category 1. */
const BLUE = 0x0002;
const RED = 0x0004;
/** The red team shares a negative group: its members never collide with each other. */
const RED_GROUP = -1;
const RADIUS = 0.3;

type Team = 'red' | 'blue';

/** Contacts counted over the whole run, kept on the ground's userData. */
interface Tally {
  /** Contacts between two balls of one team: the filters forbid them. */
  sameTeam: number;
  /** Contacts between a red and a blue ball. */
  acrossTeams: number;
}

const FILLS: Readonly<Record<Team, string>> = { red: '#ef5350', blue: '#42a5f5' };

function teamOf(body: Body): Team | null {
  const team = body.userData as Team | undefined;
  return team === 'red' || team === 'blue' ? team : null;
}

/**
 * Two teams of balls thrown at each other. Blue balls leave their own category out of their
 * mask; red balls share a negative group. Each team passes through itself and collides with the
 * other and with the ground.
 */
export default defineScene({
  id: 'collision-filtering',
  title: 'Collision filtering',
  description:
    'Red and blue balls thrown at each other. Blue filters its own team out with category and mask bits, red with a shared negative group: each team overlaps itself freely but bounces off the other team.',
  parameters: [
    { name: 'perTeam', label: 'Balls per team', min: 2, max: 20, step: 1, default: 12 },
    { name: 'speed', label: 'Throw speed (m/s)', min: 0, max: 10, step: 0.5, default: 4 },
  ],
  camera: { x: -0.5, y: -7, width: 13, height: 7.5 },
  pixelsPerMeter: 40,
  steps: 240,
  build({ perTeam, speed }) {
    const world = new World();
    const tally: Tally = { sameTeam: 0, acrossTeams: 0 };
    world.add(wall({ from: { x: -0.5, y: 0 }, to: { x: 12.5, y: 0 }, userData: tally }));
    world.add(wall({ from: { x: 0, y: 0 }, to: { x: 0, y: -7 } }));
    world.add(wall({ from: { x: 12, y: -7 }, to: { x: 12, y: 0 } }));
    world.on('contactBegin', ({ bodyA, bodyB }) => {
      const a = teamOf(bodyA);
      const b = teamOf(bodyB);
      if (a === null || b === null) return;
      if (a === b) tally.sameTeam++;
      else tally.acrossTeams++;
    });
    // Each team starts as a block of balls closer than a diameter apart: overlapping, which only
    // its filter allows.
    const columns = 4;
    for (let i = 0; i < perTeam; i++) {
      const dx = (i % columns) * 0.45;
      const dy = Math.floor(i / columns) * 0.45;
      world.add(
        particle<Team>({
          position: { x: 1 + dx, y: -1 - dy },
          radius: RADIUS,
          linearVelocity: { x: speed, y: 0 },
          userData: 'red',
          filter: { category: RED, group: RED_GROUP },
        }),
      );
      world.add(
        particle<Team>({
          position: { x: 11 - dx, y: -1 - dy },
          radius: RADIUS,
          linearVelocity: { x: -speed, y: 0 },
          userData: 'blue',
          filter: { category: BLUE, mask: ~BLUE >>> 0 },
        }),
      );
    }
    return world;
  },
  fill(body) {
    const team = teamOf(body);
    return team === null ? null : FILLS[team];
  },
  check(world) {
    const tally = world.bodies[0]!.userData as Tally;
    if (tally.sameTeam > 0) return `${tally.sameTeam} contacts between balls of one team`;
    if (tally.acrossTeams === 0) return 'no red ball ever touched a blue one';
    // The other team is solid: no red and blue ball sink into each other (5 mm slop, 2 cm margin).
    const balls = world.bodies.filter((body) => teamOf(body) !== null);
    let overlappingTeammates = 0;
    for (let i = 0; i < balls.length; i++) {
      for (let j = i + 1; j < balls.length; j++) {
        const a = balls[i]!;
        const b = balls[j]!;
        const gap =
          Math.hypot(a.position.x - b.position.x, a.position.y - b.position.y) - 2 * RADIUS;
        if (teamOf(a) !== teamOf(b) && gap < -0.02) {
          return `a red and a blue ball overlap by ${(-gap * 100).toFixed(1)} cm`;
        }
        if (teamOf(a) === teamOf(b) && gap < -0.05) overlappingTeammates++;
      }
    }
    if (overlappingTeammates === 0) return 'no two balls of one team overlap: did they collide?';
    return null;
  },
});
