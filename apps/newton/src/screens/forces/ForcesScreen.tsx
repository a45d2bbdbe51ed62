import { Box, Button, FormControlLabel, Switch, Typography } from '@mui/material';
import type { PhysicalCanvasElement } from '@physical/canvas';
import type { Force, World } from '@physical/engine';
import { useCallback, useMemo, useReducer, useRef, useState } from 'react';
import { useAnnouncer } from '../../app/Announcer.tsx';
import { forcesPreset, presetFor } from '../../app/presets.ts';
import { MuiTheme } from '../../app/MuiTheme.tsx';
import { ScreenLayout } from '../../app/ScreenLayout.tsx';
import { SQUARE_COLORS } from '../../app/theme.ts';
import { simulatedTime, useSimulation } from '../../app/use-simulation.ts';
import { useTicker } from '../../app/use-ticker.ts';
import { TimeSeries } from '../../graphs/time-series.ts';
import { TimeSeriesGraph } from '../../graphs/TimeSeriesGraph.tsx';
import { useI18n } from '../../i18n/i18n.tsx';
import { DataTools } from '../../lab/DataTools.tsx';
import { Ruler } from '../../lab/Ruler.tsx';
import { useRewind, type Measured } from '../../lab/use-rewind.ts';
import {
  adoptTrack,
  createForcesTrack,
  displacement,
  drawMysteryMass,
  isMysteryFound,
  measuredAcceleration,
  startTrack,
  trackState,
  type ForcesTrack,
  type SquareSettings,
  type TrackState,
} from './forces-scene.ts';
import { MysteryMass } from './MysteryMass.tsx';
import { SquareDialog } from './SquareDialog.tsx';
import { TrackView } from './TrackView.tsx';

const NAMES = ['A', 'B'] as const;
/** The same force on 1 kg and on 2 kg: the learner sees the heavier one accelerate half as fast. */
const DEFAULTS: readonly SquareSettings[] = [
  { mass: 1, force: 2 },
  { mass: 2, force: 2 },
];

/** The squares a preset link asks for: its masses and forces. */
function presetSquares(defaults: readonly SquareSettings[]): readonly SquareSettings[] {
  const preset = forcesPreset(presetFor('forces'));
  return defaults.map((square, index) => ({
    mass: preset.masses[index] ?? square.mass,
    force: preset.forces[index] ?? square.force,
  }));
}

/**
 * What each square gets: with "same force", B is pushed by A's force, whatever its mass; with a
 * mystery mass (kg), B has that hidden mass and A's force (the learner finds the mass from F / a).
 */
function effectiveSettings(
  settings: readonly SquareSettings[],
  sameForce: boolean,
  mysteryMass: number | null,
): readonly SquareSettings[] {
  if (!sameForce && mysteryMass === null) return settings;
  return [settings[0]!, { mass: mysteryMass ?? settings[1]!.mass, force: settings[0]!.force }];
}

/**
 * What track `index` measured at its world's time, for the CSV: displacement, velocity, the
 * acceleration Δv / Δt and the force, and the square's momentum and kinetic energy (left out
 * while its mass is the learner's mystery to find: p / v would give it away).
 */
function measureTrack(track: ForcesTrack, index: number, hiddenMass: boolean): Measured[] {
  const name = NAMES[index]!;
  const v = track.square.linearVelocity.x;
  const m = track.square.mass;
  // At rest at the stop the square does not accelerate (the readout keeps the last run value).
  const a = track.finishedAt !== null ? 0 : (measuredAcceleration(track) ?? Number.NaN);
  const values: Measured[] = [
    { name: `${name} x`, unit: 'm', value: displacement(track) },
    { name: `${name} v`, unit: 'm/s', value: v },
    { name: `${name} a`, unit: 'm/s^2', value: a },
    // The square's only force is the learner's F, while the run lasts.
    { name: `${name} F`, unit: 'N', value: track.square.forces.length > 0 ? track.force : 0 },
  ];
  if (!(hiddenMass && index === 1)) {
    values.push(
      { name: `${name} p`, unit: 'kg m/s', value: m * v },
      { name: `${name} KE`, unit: 'J', value: 0.5 * m * v * v },
    );
  }
  return values;
}

/** The second law: two squares, each pushed by the learner's force F, their accelerations measured. */
export function ForcesScreen({ active }: { active: boolean }) {
  const { t, unit } = useI18n();
  const sim = useSimulation();
  // A preset link (#forces?mA=1&mB=2&F=3) chooses the first setup.
  const [initial] = useState(() => presetSquares(DEFAULTS));
  const [settings, setSettings] = useState<readonly SquareSettings[]>(initial);
  const [sameForce, setSameForce] = useState(false);
  // B's hidden mass (kg) while the mystery is on; revealed once the learner finds it.
  const [mysteryMass, setMysteryMass] = useState<number | null>(null);
  const [mysteryFound, setMysteryFound] = useState(false);
  const [tracks, setTracks] = useState<readonly ForcesTrack[]>(() =>
    initial.map((value) => createForcesTrack(value)),
  );
  const [started, setStarted] = useState(false);
  // Re-renders when a square reaches the stop (whether all have is read from the tracks).
  const [, squareFinished] = useReducer((count: number) => count + 1, 0);
  const [editing, setEditing] = useState<number | null>(null);
  const forces = useRef<Force[]>([]);
  const canvases = useRef<(PhysicalCanvasElement | null)[]>([null, null]);
  const [ruler, setRuler] = useState(false);
  const rulerCanvas = useCallback(() => canvases.current[0] ?? null, []);
  const series = useMemo(
    () =>
      NAMES.map(() => ({
        position: new TimeSeries(6),
        velocity: new TimeSeries(6),
        acceleration: new TimeSeries(6),
        force: new TimeSeries(6),
      })),
    [],
  );
  const { announce, region } = useAnnouncer('forces');
  const tracksRef = useRef(tracks);
  tracksRef.current = tracks;
  const hiddenRef = useRef(false);
  hiddenRef.current = mysteryMass !== null && !mysteryFound;

  /** What a square's arrival at the stop tells: the screen re-renders, the time is announced. */
  const finishOf = (index: number) => (): void => {
    squareFinished();
    announce(
      t('forces.reachedEnd', {
        name: NAMES[index]!,
        time: unit(tracksRef.current[index]?.finishedAt ?? 0, 's', 2, 2),
      }),
    );
  };
  const finishRef = useRef(finishOf);
  finishRef.current = finishOf;

  // Step back, scrub and CSV: both tracks' worlds saved each step, restored side by side.
  const worlds = useMemo(() => tracks.map((track) => track.world), [tracks]);
  const rewind = useRewind<TrackState>({
    worlds,
    data: (index) => trackState(tracksRef.current[index]!),
    measure: (index) => measureTrack(tracksRef.current[index]!, index, hiddenRef.current),
    adopt: (restored: readonly World[], states: readonly TrackState[]) => {
      const next = restored.map((world, index) =>
        adoptTrack(tracksRef.current[index]!, world, states[index]!, () =>
          finishRef.current(index)(),
        ),
      );
      forces.current = next.flatMap((track) => track.square.forces.slice(0, 1));
      next.forEach((track, index) => {
        const time = simulatedTime(track.world);
        for (const item of Object.values(series[index]!)) item.truncateAfter(time);
      });
      tracksRef.current = next;
      setTracks(next);
    },
    pause: () => sim.setPaused(true),
  });
  const clearRewind = rewind.clear;
  // Paused too: a step the canvases took as the pause came in shows (a step back starts there).
  useTicker(active && started, 100, () =>
    tracksRef.current.map((track) => `${track.world.steps}:${track.finishedAt}`).join(','),
  );

  const rebuild = useCallback(
    (next: readonly SquareSettings[], same: boolean, mystery: number | null) => {
      for (const force of forces.current) force.remove();
      forces.current = [];
      for (const item of series) {
        item.position.clear();
        item.velocity.clear();
        item.acceleration.clear();
        item.force.clear();
      }
      setStarted(false);
      clearRewind();
      setTracks(effectiveSettings(next, same, mystery).map((value) => createForcesTrack(value)));
    },
    [series, clearRewind],
  );

  const start = (): void => {
    if (started) return;
    forces.current = tracks.map((track, index) => startTrack(track, finishOf(index)));
    // The saved first moment has the forces on: stepping back to it goes on with them.
    rewind.restart();
    setStarted(true);
    announce(
      t('forces.started', {
        a: unit(tracks[0]!.force, 'N', 2),
        b: unit(tracks[1]!.force, 'N', 2),
      }),
    );
    for (const canvas of canvases.current) canvas?.invalidate();
  };

  const confirm = (value: SquareSettings): void => {
    if (editing === null) return;
    const next = settings.map((old, index) => (index === editing ? value : old));
    setSettings(next);
    setEditing(null);
    rebuild(next, sameForce, mysteryMass);
  };

  const allFinished = tracks.every((track) => track.finishedAt !== null);
  // The run's clock: the track still running (a finished square rests, and its world stops).
  const time = Math.max(...tracks.map((track) => simulatedTime(track.world)));
  const graph = (
    title: string,
    unitName: string,
    key: 'position' | 'velocity' | 'acceleration' | 'force',
  ) => (
    <TimeSeriesGraph
      title={title}
      unit={unitName}
      window={6}
      height={72}
      lines={series.map((item, index) => ({
        series: item[key],
        color: SQUARE_COLORS[index]!,
        label: NAMES[index]!,
        dashed: index === 1,
      }))}
    />
  );
  // x(t) and v(t) beside a(t) and F(t): the cause and its effect on one time axis.
  const graphs = (
    <Box
      data-graphs="forces"
      sx={{ display: 'grid', gridTemplateColumns: 'repeat(2, minmax(0, 1fr))', gap: 1 }}
    >
      {graph(t('forces.position'), 'm', 'position')}
      {graph(t('forces.velocity'), 'm/s', 'velocity')}
      {graph(t('forces.accelerationGraph'), 'm/s²', 'acceleration')}
      {graph(t('forces.forceGraph'), 'N', 'force')}
    </Box>
  );

  return (
    <MuiTheme>
      <ScreenLayout
        id="forces"
        active={active}
        law={t('forces.law')}
        stage={
          <>
            <Box sx={{ flex: 1, display: 'flex', flexDirection: 'column', gap: 0.5, minWidth: 0 }}>
              {tracks.map((track, index) => (
                <TrackView
                  key={index}
                  ref={(element) => {
                    canvases.current[index] = element;
                  }}
                  name={NAMES[index]!}
                  track={track}
                  color={SQUARE_COLORS[index]!}
                  // The clock starts with the motion: the tracks do not step before Start.
                  paused={sim.paused || !started}
                  timeScale={sim.timeScale}
                  position={series[index]!.position}
                  velocity={series[index]!.velocity}
                  acceleration={series[index]!.acceleration}
                  force={series[index]!.force}
                  hiddenMass={index === 1 && mysteryMass !== null && !mysteryFound}
                  onEdit={() => {
                    // B's mass is the mystery: only A's force can be set.
                    if (index === 1 && mysteryMass !== null) announce(t('forces.mysteryLocked'));
                    else setEditing(index);
                  }}
                  onPauseChange={sim.setPaused}
                  forceOn={started && track.finishedAt === null}
                />
              ))}
            </Box>
            {ruler && <Ruler canvas={rulerCanvas} version={tracks} />}
          </>
        }
        panel={
          <>
            {region}
            {graphs}
            <Box sx={{ px: 0.5 }}>
              <FormControlLabel
                sx={{ minHeight: 48, mr: 0 }}
                control={
                  <Switch
                    checked={sameForce || mysteryMass !== null}
                    disabled={mysteryMass !== null}
                    onChange={(_event, value) => {
                      setSameForce(value);
                      rebuild(settings, value, mysteryMass);
                    }}
                    slotProps={{ input: { 'data-control': 'same-force' } as object }}
                  />
                }
                label={<Typography variant="body2">{t('forces.sameForce')}</Typography>}
              />
              <FormControlLabel
                sx={{ minHeight: 48, mr: 0 }}
                control={
                  <Switch
                    checked={ruler}
                    onChange={(_event, value) => setRuler(value)}
                    slotProps={{ input: { 'data-control': 'show-ruler' } as object }}
                  />
                }
                label={<Typography variant="body2">{t('lab.showRuler')}</Typography>}
              />
            </Box>
            <DataTools
              rewind={rewind}
              fileName="newton-forces.csv"
              live={active && started && !sim.paused}
              announce={announce}
            />
            <MysteryMass
              mass={mysteryMass}
              found={mysteryFound}
              onToggle={(on) => {
                const mass = on ? drawMysteryMass() : null;
                setMysteryMass(mass);
                setMysteryFound(false);
                rebuild(settings, sameForce, mass);
                announce(t(on ? 'forces.mysteryOn' : 'forces.mysteryOff'));
              }}
              onGuess={(guess) => {
                if (mysteryMass === null) return;
                const found = isMysteryFound(guess, mysteryMass);
                if (found) setMysteryFound(true);
                announce(
                  found
                    ? t('forces.mysteryRight', { mass: unit(mysteryMass, 'kg', 1) })
                    : t('forces.mysteryWrong', { guess: unit(guess, 'kg', 2) }),
                );
              }}
            />
            <Typography variant="body2" sx={{ color: 'text.secondary', px: 0.5 }}>
              {t('forces.edit')}
            </Typography>
            <SquareDialog
              open={editing !== null}
              name={editing === null ? '' : NAMES[editing]!}
              settings={settings[editing ?? 0]!}
              onClose={() => setEditing(null)}
              onConfirm={confirm}
            />
          </>
        }
        actions={
          <Button
            variant="contained"
            onClick={start}
            disabled={started}
            sx={{ minHeight: 48, flex: 1 }}
            data-action="start"
          >
            {allFinished ? t('forces.finished') : started ? t('forces.running') : t('forces.start')}
          </Button>
        }
        controls={{
          paused: sim.paused,
          slow: sim.slow,
          time,
          onTogglePlay: sim.togglePlay,
          onToggleSlow: sim.toggleSlow,
          onStep: () => {
            if (!started) return;
            sim.step(
              tracks.map((track, index) => ({
                world: track.world,
                canvas: canvases.current[index] ?? null,
              })),
            );
          },
          onReset: () => rebuild(settings, sameForce, mysteryMass),
          onResetAll: () => {
            setRuler(false);
            setSettings(DEFAULTS);
            setSameForce(false);
            setMysteryMass(null);
            setMysteryFound(false);
            rebuild(DEFAULTS, false, null);
          },
        }}
      />
    </MuiTheme>
  );
}
