import { describe, expect, it } from 'vitest';
import { AnnouncementQueue } from '../src/app/announcement-queue.ts';

describe('AnnouncementQueue', () => {
  it('speaks urgent messages first, then the others, oldest first', () => {
    const queue = new AnnouncementQueue();
    queue.push('a');
    queue.push('full', true);
    queue.push('b');
    expect([queue.next(), queue.next(), queue.next(), queue.next()]).toEqual([
      'full',
      'a',
      'b',
      null,
    ]);
    expect(queue.empty).toBe(true);
  });

  it('keeps the newest two of a burst, and a repeated text once, at the end', () => {
    const queue = new AnnouncementQueue();
    for (const text of ['1', '2', '3', '4']) queue.push(text);
    expect([queue.next(), queue.next()]).toEqual(['3', '4']);
    queue.push('x');
    queue.push('y');
    queue.push('x');
    expect([queue.next(), queue.next(), queue.next()]).toEqual(['y', 'x', null]);
  });

  it('writes a message sent as a function only when it is spoken, with what it was sent with', () => {
    const queue = new AnnouncementQueue();
    let written = 0;
    // A crowd: one collision a step for ten seconds, each with its own impulse.
    for (let step = 0; step < 600; step++) {
      const impulse = step / 100;
      queue.push(() => {
        written++;
        return `collided, ${impulse.toFixed(2)} N s`;
      });
    }
    expect(written).toBe(0);
    expect(queue.next()).toBe('collided, 5.98 N s');
    expect(queue.next()).toBe('collided, 5.99 N s');
    expect(written).toBe(2);
    expect(queue.next()).toBeNull();
  });

  it('keeps urgent messages apart from a crowd of others', () => {
    const queue = new AnnouncementQueue();
    queue.push('the box is full', true);
    for (let step = 0; step < 100; step++) queue.push(() => `collision ${step}`);
    expect(queue.next()).toBe('the box is full');
    expect(queue.next()).toBe('collision 98');
  });
});
