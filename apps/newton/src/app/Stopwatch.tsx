import { useEffect, useReducer, useRef, useState } from 'react';
import { useI18n } from '../i18n/i18n.tsx';
import { Button } from '../ui/Button.tsx';

/** Props of {@link Stopwatch}. */
export interface StopwatchProps {
  /** Reads the simulated time now (s). */
  readonly time: () => number;
  /** False while the screen is hidden: no time is counted then. */
  readonly visible: boolean;
  /** True while the simulation is paused: no time passes. */
  readonly paused: boolean;
  /** Simulated seconds per real second (slow motion: 0.25). */
  readonly timeScale: number;
  /** Says what just happened (the screen's announcer). */
  readonly announce?: (message: string) => void;
}

/** How often a running stopwatch counts and redraws (ms). */
const TICK_MS = 50;

/**
 * A stopwatch the learner starts and stops (PhET's). It counts the simulation's time: while the
 * world steps, the simulated seconds that passed; while everything rests (the app then takes no
 * steps, to save the battery), real seconds times the time scale, which is what the simulation
 * would have counted. So it stops when the simulation is paused and runs slowly in slow motion,
 * like everything on screen. Restarting the scene (its clock back at 0) keeps what was measured.
 */
export function Stopwatch({ time, visible, paused, timeScale, announce }: StopwatchProps) {
  const { t, unit } = useI18n();
  const [running, setRunning] = useState(false);
  const [, redraw] = useReducer((count: number) => count + 1, 0);
  const state = useRef({ elapsed: 0, lastSim: 0, lastWall: 0 });
  const live = useRef({ time, paused, timeScale });
  live.current = { time, paused, timeScale };

  // Adds the time since the last count (see the component's comment for which time).
  const count = (): void => {
    const current = state.current;
    const sim = live.current.time();
    const wall = performance.now();
    const simulated = sim - current.lastSim;
    const real = live.current.paused
      ? 0
      : ((wall - current.lastWall) / 1000) * live.current.timeScale;
    // A negative step is a restarted scene: its clock went back; count real time then too.
    current.elapsed += simulated > 0 ? simulated : real;
    current.lastSim = sim;
    current.lastWall = wall;
  };

  useEffect(() => {
    if (!running || !visible) return;
    state.current.lastSim = live.current.time();
    state.current.lastWall = performance.now();
    const id = setInterval(() => {
      count();
      redraw();
    }, TICK_MS);
    return () => clearInterval(id);
    // count reads only refs: the interval restarts only when running or visibility change.
  }, [running, visible]);

  const elapsed = state.current.elapsed;
  const toggle = (): void => {
    if (running) {
      if (visible) count();
      const measured = state.current.elapsed;
      announce?.(t('stopwatch.stopped', { value: unit(measured, 's', 2, 2) }));
    }
    setRunning(!running);
  };
  const reset = (): void => {
    state.current.elapsed = 0;
    setRunning(false);
    redraw();
  };

  return (
    <div role="group" aria-label={t('stopwatch.title')} className="stopwatch">
      <div className="ui-caption ui-secondary">{t('stopwatch.title')}</div>
      <div
        className="ui-body2 ui-numbers stopwatch__value"
        data-readout="stopwatch"
        aria-live="off"
      >
        {unit(elapsed, 's', 2, 2)}
      </div>
      <Button
        variant="outlined"
        onClick={toggle}
        aria-pressed={running}
        data-action="stopwatch"
        className="stopwatch__toggle"
      >
        {running ? t('stopwatch.stop') : t('stopwatch.start')}
      </Button>
      <Button onClick={reset} data-action="stopwatch-reset">
        {t('stopwatch.reset')}
      </Button>
    </div>
  );
}
