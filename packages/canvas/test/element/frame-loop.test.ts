import { describe, expect, it } from 'vitest';
import { FrameLoop, ManualFrameScheduler, type FrameLoopTarget } from '../../src/index.ts';

/** A target that records steps and renders, settled when told. */
function recorder(settled: () => boolean = () => false) {
  const steps: number[] = [];
  const renders: { alpha: number; elapsed: number }[] = [];
  const target: FrameLoopTarget = {
    step: (dt) => steps.push(dt),
    render: (alpha, elapsed) => renders.push({ alpha, elapsed }),
    isSettled: settled,
  };
  return { steps, renders, target };
}

function started(target: FrameLoopTarget, scheduler = new ManualFrameScheduler()) {
  const loop = new FrameLoop(target, scheduler);
  loop.invalidate();
  scheduler.advance(0); // first frame: no time
  return { loop, scheduler };
}

describe('FrameLoop', () => {
  it.each([60, 90, 120, 144, 30])('takes 60 steps of 1/60 s for 1 s of frames at %i Hz', (rate) => {
    const { steps, target } = recorder();
    const { scheduler } = started(target);
    for (let i = 0; i < rate; i++) scheduler.advance(1000 / rate);
    expect(steps.length).toBe(60);
    expect(new Set(steps)).toEqual(new Set([1 / 60]));
  });

  it('interpolates: alpha is the leftover fraction of a step', () => {
    const { steps, renders, target } = recorder();
    const { scheduler } = started(target);
    scheduler.advance(1000 / 120);
    expect(steps.length).toBe(0);
    expect(renders.at(-1)!.alpha).toBeCloseTo(0.5, 9);
    scheduler.advance(1000 / 120);
    expect(steps.length).toBe(1);
    expect(renders.at(-1)!.alpha).toBeCloseTo(0, 6);
  });

  it('caps catch-up steps after a stall and drops the backlog', () => {
    const { steps, target } = recorder();
    const { loop, scheduler } = started(target);
    loop.maxStepsPerFrame = 3;
    scheduler.advance(5000);
    expect(steps.length).toBe(3);
    scheduler.advance(1000 / 60);
    expect(steps.length).toBe(4);
  });

  it('takes no steps while the target cannot step, and drops that time', () => {
    const { steps, target } = recorder();
    let busy = true;
    const { scheduler } = started({ ...target, canStep: () => !busy });
    for (let i = 0; i < 30; i++) scheduler.advance(1000 / 60);
    expect(steps.length).toBe(0);
    busy = false;
    // The busy half second is not replayed: one frame gives one step.
    scheduler.advance(1000 / 60);
    expect(steps.length).toBe(1);
  });

  it('stops a catch-up as soon as the target becomes busy', () => {
    const { steps, target } = recorder();
    const { scheduler } = started({ ...target, canStep: () => steps.length < 1 });
    scheduler.advance(4000 / 60); // four steps owed; the target is busy after the first
    expect(steps.length).toBe(1);
  });

  it('scales time: a quarter speed takes 15 steps per second', () => {
    const { steps, target } = recorder();
    const { loop, scheduler } = started(target);
    loop.timeScale = 0.25;
    for (let i = 0; i < 60; i++) scheduler.advance(1000 / 60);
    expect(steps.length).toBe(15);
  });

  it('takes no steps while paused, renders at alpha 1 and stops when settled', () => {
    let paused = false;
    const { steps, renders, target } = recorder(() => paused);
    const { loop, scheduler } = started(target);
    loop.paused = paused = true;
    scheduler.advance(100);
    expect(steps.length).toBe(0);
    expect(renders.at(-1)).toEqual({ alpha: 1, elapsed: 0 });
    expect(scheduler.hasPendingFrame).toBe(false);
  });

  it('stepOnce takes exactly one fixed step while paused and renders the new state', () => {
    const { steps, renders, target } = recorder(() => true);
    const { loop, scheduler } = started(target);
    loop.paused = true;
    loop.fixedStep = 1 / 120;
    scheduler.advance(1000);
    expect(steps).toEqual([]);
    const before = { frames: loop.frameCount, renders: renders.length };
    loop.stepOnce();
    expect(steps).toEqual([1 / 120]);
    expect(loop.stepCount).toBe(1);
    expect(renders.length).toBe(before.renders + 1);
    expect(renders.at(-1)).toEqual({ alpha: 1, elapsed: 0 });
    expect(loop.frameCount).toBe(before.frames + 1);
    // Paused time still adds no steps afterwards.
    loop.invalidate();
    scheduler.advance(1000);
    expect(steps.length).toBe(1);
  });

  it('requests no frames once settled, and resumes without a jump', () => {
    let settled = false;
    const { steps, target } = recorder(() => settled);
    const { loop, scheduler } = started(target);
    scheduler.advance(1000 / 60);
    settled = true;
    scheduler.advance(1000 / 60);
    const requests = scheduler.requests;
    expect(scheduler.hasPendingFrame).toBe(false);
    expect(scheduler.advance(10_000)).toBe(false);
    expect(scheduler.requests).toBe(requests);
    settled = false;
    const before = steps.length;
    loop.invalidate();
    scheduler.advance(5000); // 5 s later: the first frame back counts no time
    expect(steps.length).toBe(before);
    scheduler.advance(1000 / 60);
    expect(steps.length).toBe(before + 1);
  });

  it('suspends for each reason and resumes only when all are lifted, without a jump', () => {
    const { steps, target } = recorder();
    const { loop, scheduler } = started(target);
    scheduler.advance(1000 / 60);
    loop.suspend('hidden');
    loop.suspend('offscreen');
    expect(scheduler.hasPendingFrame).toBe(false);
    loop.invalidate();
    expect(scheduler.hasPendingFrame).toBe(false);
    loop.resume('hidden');
    expect(scheduler.hasPendingFrame).toBe(false);
    loop.resume('offscreen');
    const before = steps.length;
    scheduler.advance(3000);
    expect(steps.length).toBe(before);
  });
});
