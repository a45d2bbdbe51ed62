import { describe, expect, it } from 'vitest';
import { World, box, wall } from '@physical/engine';

// A world's first step makes every contact at once (a 5,050-box pyramid: 15,000). The manager's
// lists of the step's new pairs and begins are flat shape ids sized with the shapes and the
// contacts (contact-manager.ts: reservePairs, collide), so no list grows one pair or one begin at
// a time; the begins still name their shapes, in the order the narrow phase found them.

type Manager = ReturnType<World['internals']>['contactManager'];

function manager(world: World): Manager {
  return (world.internals() as { contactManager: Manager }).contactManager;
}

/** A stack of `rows` rows of boxes on the ground, each row resting on the one below. */
function stack(rows: number, columns: number): World {
  const world = new World({ enableSleep: false });
  world.add(wall({ from: { x: -20, y: 0 }, to: { x: 20, y: 0 } }));
  for (let r = 0; r < rows; r++) {
    for (let c = 0; c < columns; c++) {
      world.add(box({ position: { x: c * 1.01 - columns / 2, y: -0.5 - r }, width: 1, height: 1 }));
    }
  }
  return world;
}

describe('ContactManager sizes its lists of new pairs and begins with the contacts', () => {
  it('reports every begin of a first step with its shapes, without growing the list after', () => {
    const world = stack(10, 12);
    const begins: string[] = [];
    world.on('contactBegin', (event) => {
      begins.push(`${event.shapeA.id}:${event.shapeB.id}`);
    });
    const contacts = manager(world);
    world.step(1 / 60);
    // Every box touches the one below it (or the ground); the side gaps are 0.01 m.
    expect(contacts.count).toBeGreaterThanOrEqual(120);
    expect(contacts.beganCount).toBe(begins.length);
    expect(begins.length).toBeGreaterThanOrEqual(120);
    expect(new Set(begins).size).toBe(begins.length);
    for (let i = 0; i < contacts.beganCount; i++) {
      expect(`${contacts.beganShapeA(i).id}:${contacts.beganShapeB(i).id}`).toBe(begins[i]);
    }
    // Room for a begin of every contact was made before the narrow phase, once.
    expect(contacts.beganIds.length).toBeGreaterThanOrEqual(2 * contacts.count);
    const list = contacts.beganIds;
    for (let i = 0; i < 30; i++) world.step(1 / 60);
    expect(contacts.beganIds).toBe(list);
  });
});
