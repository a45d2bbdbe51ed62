import { describe, expect, it } from 'vitest';
import { World, particle, takeSnapshot } from '@physical/engine';
import { MeasurementLog, csvCell, formatNumber } from '../src/lab/measurement-log.ts';
import { SnapshotHistory } from '../src/lab/snapshot-history.ts';
import { observeSteps } from '../src/lab/step-hook.ts';
import { TimeSeries } from '../src/graphs/time-series.ts';

function fallingWorld(): World {
  const world = new World();
  const ball = world.add(particle({ position: { x: 0, y: 0 }, radius: 0.2 }));
  ball.linearVelocity = { x: 1, y: 0 };
  return world;
}

describe('observeSteps', () => {
  it('calls before and after around every step, whoever steps, until removed', () => {
    const world = fallingWorld();
    const seen: string[] = [];
    const stop = observeSteps(world, {
      before: () => seen.push(`before ${world.steps}`),
      after: () => seen.push(`after ${world.steps}`),
    });
    world.step(1 / 60);
    world.step(1 / 60);
    expect(seen).toEqual(['before 0', 'after 1', 'before 1', 'after 2']);
    stop();
    world.step(1 / 60);
    expect(seen).toHaveLength(4);
    expect(Object.hasOwn(world, 'step')).toBe(false);
  });
});

describe('SnapshotHistory', () => {
  it('restores a world that steps on bit for bit as the original did', () => {
    const world = fallingWorld();
    const history = new SnapshotHistory<string>({ capacity: 10 });
    for (let i = 0; i < 5; i++) {
      world.step(1 / 60);
      history.record(world, world.steps / 60, `step ${world.steps}`);
    }
    const { world: back, entry } = history.restore(1);
    expect(entry.data).toBe('step 2');
    expect(back.steps).toBe(2);
    for (let i = 0; i < 3; i++) back.step(1 / 60);
    expect(takeSnapshot(back)).toEqual(takeSnapshot(world));
  });

  it('keeps the newest `capacity` entries and forgets the future after a rewind', () => {
    const world = fallingWorld();
    const history = new SnapshotHistory<number>({ capacity: 3 });
    for (let i = 0; i < 5; i++) {
      world.step(1 / 60);
      history.record(world, i, i);
    }
    expect(history.length).toBe(3);
    expect(history.entry(0)!.data).toBe(2);
    history.truncateAfter(0);
    expect(history.length).toBe(1);
    expect(history.last!.data).toBe(2);
    expect(() => history.restore(5)).toThrow(/no entry 5/);
    expect(() => new SnapshotHistory({ capacity: 1 })).toThrow(/capacity/);
    expect(() => new SnapshotHistory({ capacity: 4, interval: 5 })).toThrow(/interval/);
  });

  it('with a snapshot every few steps, replays the steps between: the same world at every step', () => {
    const world = fallingWorld();
    const sparse = new SnapshotHistory<number>({ capacity: 20, interval: 4 });
    const every = new SnapshotHistory<number>({ capacity: 20 });
    for (let i = 0; i < 12; i++) {
      world.step(1 / 60);
      sparse.record(world, world.steps / 60, world.steps);
      every.record(world, world.steps / 60, world.steps);
    }
    expect([...Array(12).keys()].filter((i) => sparse.entry(i)!.snapshot !== null)).toEqual([
      0, 4, 8,
    ]);
    for (const index of [0, 3, 5, 11]) {
      const { world: replayed, entry } = sparse.restore(index);
      expect(entry.data).toBe(index + 1);
      expect(takeSnapshot(replayed)).toEqual(takeSnapshot(every.restore(index).world));
    }
    // Full: the oldest kept entry still has a snapshot to replay from.
    const small = new SnapshotHistory<number>({ capacity: 5, interval: 4 });
    for (let i = 0; i < 9; i++) {
      world.step(1 / 60);
      small.record(world, i, i);
    }
    expect(small.entry(0)!.snapshot).not.toBeNull();
    expect(small.length).toBeLessThanOrEqual(5 + 3);
    expect(small.restore(small.length - 1).entry.data).toBe(8);
  });
});

describe('SnapshotHistory, changes between steps and worlds side by side', () => {
  it('gives a changed world a snapshot of its own, so a restore after a change made between steps has it', () => {
    const run = (mark: boolean) => {
      const world = fallingWorld();
      const ball = world.bodies[0]!;
      const history = new SnapshotHistory<number>({ capacity: 20, interval: 10 });
      history.record(world, 0, 0);
      // A push switched on between two steps, as a learner does.
      ball.applyForce({ x: 3, y: 0 }, { duration: 'constant' });
      if (mark) history.markChanged();
      for (let i = 1; i <= 5; i++) {
        world.step(1 / 60);
        history.record(world, i / 60, i);
      }
      return { world, restored: history.restore(5).world };
    };
    const marked = run(true);
    expect(takeSnapshot(marked.restored)).toEqual(takeSnapshot(marked.world));
    // Without the mark the steps are replayed from the snapshot before the push: it is missing.
    const unmarked = run(false);
    expect(unmarked.restored.bodies[0]!.position.x).toBeLessThan(
      unmarked.world.bodies[0]!.position.x,
    );
  });

  it('replays what the app sets before each step and keeps in its data: a new gravity every step needs no snapshot', () => {
    // A phone in the hand: the tray's lean (gravity) a little different before every step.
    const lean = (i: number) => ({ x: Math.sin(i * 0.7) * 0.3, y: 9.81 + Math.cos(i * 1.3) * 0.2 });
    const world = fallingWorld();
    const history = new SnapshotHistory<{ x: number; y: number }>({ capacity: 40, interval: 30 });
    history.record(world, 0, { ...world.gravity });
    const saved = [takeSnapshot(world)];
    for (let i = 1; i <= 25; i++) {
      const gravity = lean(i);
      world.gravity = gravity;
      world.step(1 / 60);
      history.record(world, i / 60, gravity);
      saved.push(takeSnapshot(world));
    }
    const replay = (restored: World, gravity: { x: number; y: number }): void => {
      restored.gravity = gravity;
    };
    for (const index of [1, 7, 25]) {
      expect(takeSnapshot(history.restore(index, replay).world)).toEqual(saved[index]);
    }
    // Without it the steps run with the gravity of the snapshot: another world.
    expect(takeSnapshot(history.restore(25).world)).not.toEqual(saved[25]);
  });

  it('finds the newest entry at or before a time (a world a step behind another)', () => {
    const world = fallingWorld();
    const history = new SnapshotHistory<number>({ capacity: 10 });
    for (let i = 0; i < 4; i++) {
      history.record(world, i / 60, i);
      world.step(1 / 60);
    }
    expect(history.indexAt(2 / 60)).toBe(2);
    expect(history.indexAt(2.5 / 60)).toBe(2);
    expect(history.indexAt(10)).toBe(3);
    expect(history.indexAt(-1)).toBe(-1);
  });
});

describe('TimeSeries', () => {
  it('forgets the samples after a time stepped back to, and takes new ones from there', () => {
    const series = new TimeSeries(10);
    for (let i = 0; i < 5; i++) series.push(i / 60, i);
    const version = series.version;
    series.truncateAfter(2 / 60);
    expect(series.times).toEqual([0, 1 / 60, 2 / 60]);
    expect(series.values).toEqual([0, 1, 2]);
    expect(series.version).toBeGreaterThan(version);
    series.push(3 / 60, 30);
    expect(series.values).toEqual([0, 1, 2, 30]);
  });
});

describe('MeasurementLog', () => {
  it('puts values measured at the same time into one row, and rows in time order', () => {
    const log = new MeasurementLog();
    log.add(0, [{ name: 'A x', unit: 'm', value: 0 }]);
    log.add(0, [{ name: 'B x', unit: 'm', value: 0 }]);
    log.add(2 / 60, [{ name: 'A x', unit: 'm', value: 2 }]);
    // B a step behind A: its values join the rows of their own times.
    log.add(1 / 60, [{ name: 'B x', unit: 'm', value: 1 }]);
    log.add(2 / 60, [{ name: 'B x', unit: 'm', value: 2 }]);
    expect(log.length).toBe(3);
    expect(log.toCsv()).toBe(
      't (s),A x (m),B x (m)\r\n0,0,0\r\n0.0166666667,,1\r\n0.0333333333,2,2\r\n',
    );
  });

  it('writes CSV with a header of names and units, empty cells where nothing was measured', () => {
    const log = new MeasurementLog();
    log.add(0, [{ name: 'A x', unit: 'm', value: 1 }]);
    log.add(1 / 60, [
      { name: 'A x', unit: 'm', value: 1.25 },
      { name: 'B v', unit: 'm/s', value: -0.5 },
    ]);
    expect(log.toCsv()).toBe('t (s),A x (m),B v (m/s)\r\n0,1,\r\n0.0166666667,1.25,-0.5\r\n');
  });

  it('drops the rows after a rewind and keeps at most maxRows', () => {
    const log = new MeasurementLog(3);
    for (let i = 0; i < 5; i++) log.add(i, [{ name: 'x', unit: 'm', value: i * 2 }]);
    expect(log.length).toBe(3);
    log.truncateAfter(3);
    expect(log.toCsv()).toBe('t (s),x (m)\r\n2,4\r\n3,6\r\n');
  });

  it('keeps the newest maxRows rows in order through growth and wrap-around, columns added late empty before', () => {
    const log = new MeasurementLog(300);
    for (let i = 0; i < 700; i++) {
      const values = [{ name: 'x', unit: 'm', value: i * 2 }];
      if (i >= 500) values.push({ name: 'y', unit: 'm', value: -i });
      log.add(i, values);
    }
    expect(log.length).toBe(300);
    const lines = log.toCsv().trimEnd().split('\r\n');
    expect(lines[0]).toBe('t (s),x (m),y (m)');
    expect(lines[1]).toBe('400,800,');
    expect(lines[101]).toBe('500,1000,-500');
    expect(lines[300]).toBe('699,1398,-699');
    // A world a step behind, after wrap-around: its older time goes into place.
    log.add(698.5, [{ name: 'x', unit: 'm', value: 7 }]);
    const after = log.toCsv().trimEnd().split('\r\n');
    expect(after[1]).toBe('401,802,');
    expect(after.slice(-3)).toEqual(['698,1396,-698', '698.5,7,', '699,1398,-699']);
  });

  it('formats numbers for any spreadsheet and quotes cells that need it', () => {
    expect(formatNumber(-0)).toBe('0');
    expect(formatNumber(1 / 3)).toBe('0.333333333');
    expect(formatNumber(Number.NaN)).toBe('');
    expect(csvCell('a, "b"')).toBe('"a, ""b"""');
    expect(csvCell('plain')).toBe('plain');
  });
});
