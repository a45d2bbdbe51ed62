import { readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import { World, type WorldEvents } from '@physical/engine';

// Every key of WorldEvents, checked by the compiler both ways: a new event not listed here fails
// to compile, and so does a name that is not an event.
const EVERY_EVENT: Record<keyof WorldEvents, true> = {
  move: true,
  collision: true,
  contactBegin: true,
  contactEnd: true,
  sensorBegin: true,
  sensorEnd: true,
  bodyAdded: true,
  bodyRemoved: true,
  jointRemoved: true,
  wake: true,
};
const names = Object.keys(EVERY_EVENT) as (keyof WorldEvents)[];

/** The TSDoc comment right above `on<` in world.ts. */
function onDoc(): string {
  const source = readFileSync(new URL('../../src/world/world.ts', import.meta.url), 'utf8');
  const at = source.indexOf('  on<K extends keyof WorldEvents>');
  const start = source.lastIndexOf('/**', at);
  return source.slice(start, at);
}

describe('World.on', () => {
  it.each(names)("names '%s' in its TSDoc", (name) => {
    expect(onDoc()).toContain(`'${name}'`);
  });

  it.each(names)("accepts '%s' (every event of the map is one world.on takes)", (name) => {
    const world = new World();
    const remove = world.on(name, () => undefined);
    expect(typeof remove).toBe('function');
    remove();
  });
});
