import { Box, Button, Typography } from '@mui/material';
import type { PhysicalCanvasElement } from '@physical/canvas';
import type { Force } from '@physical/engine';
import { useCallback, useMemo, useRef, useState } from 'react';
import { ScreenLayout } from '../../app/ScreenLayout.tsx';
import { SQUARE_COLORS } from '../../app/theme.ts';
import { simulatedTime, useSimulation } from '../../app/use-simulation.ts';
import { useTicker } from '../../app/use-ticker.ts';
import { TimeSeries } from '../../graphs/time-series.ts';
import { TimeSeriesGraph } from '../../graphs/TimeSeriesGraph.tsx';
import { useI18n } from '../../i18n/i18n.tsx';
import {
  createForcesTrack,
  startTrack,
  type ForcesTrack,
  type SquareSettings,
} from './forces-scene.ts';
import { SquareDialog } from './SquareDialog.tsx';
import { TrackView } from './TrackView.tsx';

const NAMES = ['A', 'B'] as const;
const DEFAULTS: readonly SquareSettings[] = [
  { mass: 1, acceleration: 2 },
  { mass: 2, acceleration: 2 },
];

/** The second law: two squares, each pushed by F = m a, moving side by side. */
export function ForcesScreen({ active }: { active: boolean }) {
  const { t } = useI18n();
  const sim = useSimulation();
  const [settings, setSettings] = useState<readonly SquareSettings[]>(DEFAULTS);
  const [tracks, setTracks] = useState<readonly ForcesTrack[]>(() =>
    DEFAULTS.map((value) => createForcesTrack(value)),
  );
  const [started, setStarted] = useState(false);
  const [editing, setEditing] = useState<number | null>(null);
  const forces = useRef<Force[]>([]);
  const canvases = useRef<(PhysicalCanvasElement | null)[]>([null, null]);
  const series = useMemo(
    () => NAMES.map(() => ({ position: new TimeSeries(6), velocity: new TimeSeries(6) })),
    [],
  );
  useTicker(active && !sim.paused);

  const rebuild = useCallback(
    (next: readonly SquareSettings[]) => {
      for (const force of forces.current) force.remove();
      forces.current = [];
      for (const { position, velocity } of series) {
        position.clear();
        velocity.clear();
      }
      setStarted(false);
      setTracks(next.map((value) => createForcesTrack(value)));
    },
    [series],
  );

  const start = (): void => {
    if (started) return;
    forces.current = tracks.map((track) => startTrack(track));
    setStarted(true);
    for (const canvas of canvases.current) canvas?.invalidate();
  };

  const confirm = (value: SquareSettings): void => {
    if (editing === null) return;
    const next = settings.map((old, index) => (index === editing ? value : old));
    setSettings(next);
    setEditing(null);
    rebuild(next);
  };

  return (
    <ScreenLayout
      id="forces"
      active={active}
      law={t('forces.law')}
      stage={
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
              paused={sim.paused}
              timeScale={sim.timeScale}
              position={series[index]!.position}
              velocity={series[index]!.velocity}
              onEdit={() => setEditing(index)}
              onPauseChange={sim.setPaused}
            />
          ))}
          <Box sx={{ display: 'flex', gap: 1, px: 1, pt: 0.5, mt: 'auto' }}>
            <TimeSeriesGraph
              title={t('forces.position')}
              unit="m"
              window={6}
              height={140}
              lines={series.map((item, index) => ({
                series: item.position,
                color: SQUARE_COLORS[index]!,
                label: NAMES[index]!,
                dashed: index === 1,
              }))}
            />
            <TimeSeriesGraph
              title={t('forces.velocity')}
              unit="m/s"
              window={6}
              height={140}
              lines={series.map((item, index) => ({
                series: item.velocity,
                color: SQUARE_COLORS[index]!,
                label: NAMES[index]!,
                dashed: index === 1,
              }))}
            />
          </Box>
        </Box>
      }
      panel={
        <>
          <Box sx={{ display: 'flex', gap: 1, alignItems: 'center', py: 0.5 }}>
            <Typography variant="caption" sx={{ flex: 1, color: 'text.secondary' }}>
              {t('forces.edit')}
            </Typography>
            <Button
              variant="contained"
              onClick={start}
              disabled={started}
              sx={{ minHeight: 44, minWidth: 120 }}
              data-action="start"
            >
              {started ? t('forces.running') : t('forces.start')}
            </Button>
          </Box>
          <SquareDialog
            open={editing !== null}
            name={editing === null ? '' : NAMES[editing]!}
            settings={settings[editing ?? 0]!}
            onClose={() => setEditing(null)}
            onConfirm={confirm}
          />
        </>
      }
      controls={{
        paused: sim.paused,
        slow: sim.slow,
        time: simulatedTime(tracks[0]!.world),
        onTogglePlay: sim.togglePlay,
        onToggleSlow: sim.toggleSlow,
        onStep: () =>
          sim.step(
            tracks.map((track, index) => ({
              world: track.world,
              canvas: canvases.current[index] ?? null,
            })),
          ),
        onReset: () => rebuild(settings),
      }}
    />
  );
}
