import type { World } from '@physical/engine';

/** Called around each step of a world: `before` just before it, `after` once it is over. */
export interface StepObserver {
  readonly before?: () => void;
  readonly after?: () => void;
}

const observers = new WeakMap<World, Set<StepObserver>>();

/**
 * Calls `observer` around every step of `world`, whoever takes it (the canvas's frame loop, a
 * single step, a test): the lab tools record what each step did. The engine has no step event
 * (its events are about bodies and contacts), so the world's own `step` is wrapped, once per
 * world, and unwrapped when the last observer leaves. Returns the remover.
 */
export function observeSteps(world: World, observer: StepObserver): () => void {
  let set = observers.get(world);
  if (set === undefined) {
    const list = new Set<StepObserver>();
    set = list;
    observers.set(world, list);
    const step = world.step.bind(world);
    // An own property shadows World.prototype.step; deleting it restores the original.
    Object.defineProperty(world, 'step', {
      configurable: true,
      writable: true,
      value: (dt: number): void => {
        for (const item of list) item.before?.();
        step(dt);
        for (const item of list) item.after?.();
      },
    });
  }
  const current = set;
  current.add(observer);
  return () => {
    current.delete(observer);
    if (current.size === 0) {
      observers.delete(world);
      delete (world as unknown as Record<string, unknown>)['step'];
    }
  };
}
