import { describe, expect, it } from 'vitest';
import { World, box, type Shape } from '@physical/engine';

// A contact whose fat boxes part is kept while its shapes stay within KEEP_GAP (0.4 m, four fat
// margins) of each other (contact-manager.ts), so a pair that parts and meets again by
// re-fattening alone is not ended and made again. Apps must not see it: a kept contact that does
// not touch reports nothing, and touching still begins and ends as before.

type Internals = ReturnType<World['internals']>;

/** A shape's fat box, read from the shape table (shape-table.ts: from offset 4 of its row). */
function fatBox(shape: Shape): { minX: number; minY: number; maxX: number; maxY: number } {
  const d = shape.table.data;
  const p = shape.row * 8 + 4;
  return { minX: d[p]!, minY: d[p + 1]!, maxX: d[p + 2]!, maxY: d[p + 3]! };
}

const DT = 1 / 60;
/** 0.6 m/s is 0.01 m a step. */
const SPEED = 0.6;

function manager(world: World): Internals['contactManager'] {
  return (world.internals() as Internals).contactManager;
}

/** The tight gap between two 0.5 m boxes on the x axis (m). */
function gap(a: { position: { x: number } }, b: { position: { x: number } }): number {
  return Math.abs(b.position.x - a.position.x) - 0.5;
}

describe('ContactManager keeps a pair whose fat boxes parted while its shapes stay near', () => {
  it('keeps one contact, reporting nothing, until the gap passes 0.4 m', () => {
    const world = new World({ gravity: { x: 0, y: 0 }, enableSleep: false });
    const a = world.add(box({ position: { x: 0, y: 0 }, width: 0.5, height: 0.5 }));
    // Tight gap 0.15 m: the fat boxes (0.1 m each side) overlap, so the first step makes a contact.
    const b = world.add(
      box({
        position: { x: 0.65, y: 0 },
        width: 0.5,
        height: 0.5,
        linearVelocity: { x: SPEED, y: 0 },
      }),
    );
    let events = 0;
    world.on('contactBegin', () => events++);
    world.on('contactEnd', () => events++);
    const contacts = manager(world);
    const made = contacts.made;
    world.step(DT);
    expect(contacts.made - made).toBe(1);
    const pair = [contacts.shapeA(0), contacts.shapeB(0)];
    // B leaves its fat box after 0.1 m (10 steps); its new fat box then misses A's.
    for (let i = 0; i < 14; i++) world.step(DT);
    expect(gap(a, b)).toBeGreaterThan(0.28);
    const sa = fatBox(a.shapes[0]!);
    const sb = fatBox(b.shapes[0]!);
    expect(sb.minX).toBeGreaterThan(sa.maxX);
    expect(contacts.count).toBe(1);
    expect([contacts.shapeA(0), contacts.shapeB(0)]).toEqual(pair);
    expect(contacts.destroyed).toBe(0);
    // Past 0.4 m (at about step 26) it ends.
    for (let i = 0; i < 15; i++) world.step(DT);
    expect(gap(a, b)).toBeGreaterThan(0.42);
    expect(contacts.count).toBe(0);
    expect(contacts.destroyed).toBe(1);
    expect(contacts.made - made).toBe(1);
    expect(events).toBe(0);
  });

  it('reports touching begin and end as before while the pair is kept', () => {
    const world = new World({ gravity: { x: 0, y: 0 }, enableSleep: false });
    const wall = world.add(
      box({ type: 'static', position: { x: 0, y: 0 }, width: 0.5, height: 0.5 }),
    );
    const mover = world.add(box({ position: { x: 0.7, y: 0 }, width: 0.5, height: 0.5 }));
    const begins: number[] = [];
    const ends: number[] = [];
    let step = 0;
    world.on('contactBegin', () => begins.push(step));
    world.on('contactEnd', () => ends.push(step));
    const contacts = manager(world);
    const made = contacts.made;
    const drive = (vx: number, steps: number): void => {
      for (let i = 0; i < steps; i++) {
        mover.linearVelocity = { x: vx, y: 0 };
        world.step(DT);
        step++;
      }
    };
    // Toward the wall until it rests on it, then away to 0.3 m (fat boxes parted), then back.
    drive(-SPEED, 40);
    expect(begins.length).toBe(1);
    expect(ends.length).toBe(0);
    drive(SPEED, 30);
    expect(gap(wall, mover)).toBeGreaterThan(0.28);
    expect(fatBox(mover.shapes[0]!).minX).toBeGreaterThan(fatBox(wall.shapes[0]!).maxX);
    expect(ends.length).toBe(1);
    expect(contacts.count).toBe(1);
    drive(-SPEED, 40);
    expect(begins.length).toBe(2);
    expect(ends.length).toBe(1);
    // One contact made for the whole approach, parting and return.
    expect(contacts.made - made).toBe(1);
    expect(contacts.destroyed).toBe(0);
  });
});
