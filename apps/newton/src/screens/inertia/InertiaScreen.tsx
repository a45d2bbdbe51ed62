import { Box, Button, ToggleButton, ToggleButtonGroup } from '@mui/material';
import { drawArrow, type OverlayDrawer, type PhysicalCanvasElement } from '@physical/canvas';
import type { Force } from '@physical/engine';
import { PhysicalCanvas } from '@physical/react';
import { useCallback, useEffect, useLayoutEffect, useMemo, useRef, useState } from 'react';
import { useAnnouncer } from '../../app/Announcer.tsx';
import { useOrientationRebuild } from '../../app/use-orientation-rebuild.ts';
import { Readout } from '../../app/Readout.tsx';
import { ScreenLayout } from '../../app/ScreenLayout.tsx';
import { simulatedTime, useSimulation } from '../../app/use-simulation.ts';
import { useTicker } from '../../app/use-ticker.ts';
import { TimeSeries } from '../../graphs/time-series.ts';
import { TimeSeriesGraph } from '../../graphs/TimeSeriesGraph.tsx';
import { clipToWalls } from '../../app/clip-to-walls.ts';
import { ElasticitySlider } from '../../app/ElasticitySlider.tsx';
import { Stopwatch } from '../../app/Stopwatch.tsx';
import { useI18n } from '../../i18n/i18n.tsx';
import { directionName } from './direction-name.ts';
import { ForceDialog } from './ForceDialog.tsx';
import {
  REST_SPEED,
  WALL_NAMES,
  applyConstantForce,
  createInertiaScene,
  forceVector,
  sceneSizeFor,
  screenAngle,
  setElasticity,
  setSurface,
  type InertiaScene,
  type Surface,
} from './inertia-scene.ts';

/** Metres of arrow per newton, and seconds of motion a velocity arrow shows. */
const FORCE_ARROW_SCALE = 0.4;
const VELOCITY_ARROW_SCALE = 0.5;
const MARGIN = 0.15;

/** The first law: a polygon at rest until a force acts, then gliding at constant velocity. */
export function InertiaScreen({ active }: { active: boolean }) {
  const { t, unit, number } = useI18n();
  const sim = useSimulation();
  const canvasRef = useRef<PhysicalCanvasElement | null>(null);
  const hostRef = useRef<HTMLDivElement | null>(null);
  const [scene, setScene] = useState<InertiaScene | null>(null);
  const sceneRef = useRef<InertiaScene | null>(null);
  sceneRef.current = scene;
  const [angle, setAngle] = useState(0);
  const [magnitude, setMagnitude] = useState(1);
  const forceRef = useRef<Force | null>(null);
  const [applied, setApplied] = useState(false);
  const [dialogOpen, setDialogOpen] = useState(false);
  const [elasticity, setElasticityState] = useState(1);
  const [surface, setSurfaceState] = useState<Surface>('ice');
  const settingsRef = useRef({ elasticity, surface });
  settingsRef.current = { elasticity, surface };
  const speed = useMemo(() => new TimeSeries(10), []);
  const { announce, region } = useAnnouncer('inertia');
  // Re-render only when what the readouts show changed: nothing renders at rest.
  useTicker(active && !sim.paused, 100, () => {
    const body = sceneRef.current?.body;
    if (body === undefined) return '';
    const v = body.linearVelocity;
    return `${v.x.toFixed(3)},${v.y.toFixed(3)}`;
  });

  const build = useCallback(() => {
    const host = hostRef.current;
    const size = sceneSizeFor(host?.clientWidth ?? 0, host?.clientHeight ?? 0);
    forceRef.current = null;
    setApplied(false);
    speed.clear();
    setScene(createInertiaScene(size.width, size.height, settingsRef.current));
  }, [speed]);

  const resetAll = useCallback(() => {
    setAngle(0);
    setMagnitude(1);
    setElasticityState(1);
    setSurfaceState('ice');
    settingsRef.current = { elasticity: 1, surface: 'ice' };
    build();
  }, [build]);

  useLayoutEffect(() => {
    if (active && scene === null) build();
  }, [active, scene, build]);
  useOrientationRebuild(hostRef, active ? scene : null, build);

  // Described state: what just happened, at a human pace.
  useEffect(() => {
    if (scene === null) return;
    return scene.world.on('collision', (event) => {
      const wallIndex = scene.walls.findIndex(
        (item) => item === event.bodyA || item === event.bodyB,
      );
      if (wallIndex < 0 || event.approachSpeed < 0.02) return;
      announce(
        t('inertia.hitWall', {
          wall: t(`wall.${WALL_NAMES[wallIndex]!}`),
          speed: unit(event.approachSpeed, 'm/s', 2),
        }),
      );
    });
  }, [scene, announce, t, unit]);

  const drawOverlay = useCallback<OverlayDrawer>(
    (context, canvas) => {
      const current = sceneRef.current;
      if (current === null) return;
      const time = simulatedTime(current.world);
      const velocity = current.body.linearVelocity;
      if (speed.times.length === 0 || time > speed.lastTime) {
        speed.push(time, Math.hypot(velocity.x, velocity.y));
      }
      const scale = canvas.viewport.scale;
      const centre = current.body.position;
      clipToWalls(context, current.width, current.height);
      drawArrow(
        context,
        scale,
        centre,
        { x: velocity.x * VELOCITY_ARROW_SCALE, y: velocity.y * VELOCITY_ARROW_SCALE },
        { kind: 'velocity', width: 2 },
      );
      const force = forceRef.current;
      if (force !== null) {
        drawArrow(
          context,
          scale,
          centre,
          { x: force.x * FORCE_ARROW_SCALE, y: force.y * FORCE_ARROW_SCALE },
          { kind: 'force', width: 3 },
        );
      }
      context.restore();
    },
    [speed],
  );

  const toggleForce = (): void => {
    if (scene === null) return;
    if (forceRef.current !== null) {
      forceRef.current.remove();
      forceRef.current = null;
      setApplied(false);
      announce(t('inertia.forceStopped'));
    } else {
      forceRef.current = applyConstantForce(scene, angle, magnitude);
      setApplied(true);
      announce(
        t('inertia.forceStarted', {
          force: unit(magnitude, 'N', 1),
          angle: number(angle, 0),
          name: t(directionName(angle)),
        }),
      );
    }
    canvasRef.current?.invalidate();
  };

  const confirmForce = (newAngle: number, newMagnitude: number): void => {
    setAngle(newAngle);
    setMagnitude(newMagnitude);
    setDialogOpen(false);
    forceRef.current?.setVector(forceVector(newAngle, newMagnitude));
    canvasRef.current?.invalidate();
  };

  const velocity = scene?.body.linearVelocity ?? { x: 0, y: 0 };
  const rawSpeed = Math.hypot(velocity.x, velocity.y);
  // Pressed against a wall the solver leaves a jitter of a few mm/s: that is rest.
  const moving = rawSpeed > REST_SPEED;
  const currentSpeed = moving ? rawSpeed : 0;
  const description =
    scene === null
      ? t('inertia.canvas')
      : t('inertia.describe', {
          sides: scene.sides,
          width: number(scene.width, 1),
          height: number(scene.height, 1),
          motion: moving
            ? t('inertia.describeMoving', {
                speed: unit(currentSpeed, 'm/s', 2),
                angle: number(screenAngle(velocity), 0),
              })
            : t('inertia.describeRest'),
          force: applied
            ? t('inertia.describeForce', {
                force: unit(magnitude, 'N', 1),
                angle: number(angle, 0),
              })
            : t('inertia.describeNoForce'),
        });
  const viewBox =
    scene === null
      ? null
      : {
          x: -MARGIN,
          y: -MARGIN,
          width: scene.width + 2 * MARGIN,
          height: scene.height + 2 * MARGIN,
        };

  return (
    <ScreenLayout
      id="inertia"
      active={active}
      law={t('inertia.law')}
      stage={
        <Box ref={hostRef} sx={{ flex: 1, minWidth: 0, display: 'flex' }}>
          <PhysicalCanvas
            ref={canvasRef}
            paused={sim.paused}
            world={scene?.world ?? null}
            fit="contain"
            viewBox={viewBox}
            timeScale={sim.timeScale}
            drawOverlay={drawOverlay}
            onPauseChange={({ paused }) => sim.setPaused(paused)}
            aria-label={description}
            style={{ flex: 1, height: 'auto', minHeight: 0 }}
          />
        </Box>
      }
      panel={
        <>
          {region}
          <Box sx={{ display: 'grid', gridTemplateColumns: 'repeat(4, auto)', gap: 1.5, px: 0.5 }}>
            <Readout
              name="speed"
              label={t('inertia.speed')}
              value={unit(currentSpeed, 'm/s', 3, 3)}
            />
            <Readout
              name="direction"
              label={t('inertia.direction')}
              value={moving ? `${number(screenAngle(velocity), 0)}°` : '–'}
            />
            <Readout
              name="force"
              label={t('inertia.force')}
              value={
                applied ? `${unit(magnitude, 'N', 1)}, ${number(angle, 0)}°` : t('inertia.forceOff')
              }
            />
            <Readout
              name="mass"
              label={t('inertia.mass')}
              value={scene === null ? '–' : unit(scene.body.mass, 'kg', 2)}
            />
          </Box>
          <TimeSeriesGraph
            title={t('inertia.graph')}
            unit="m/s"
            lines={[{ series: speed, color: '#64ffda', label: t('inertia.speed') }]}
            height={90}
          />
          <Stopwatch
            time={() => (scene === null ? 0 : simulatedTime(scene.world))}
            visible={active}
            paused={sim.paused}
            timeScale={sim.timeScale}
            announce={announce}
          />
          <Box sx={{ display: 'flex', gap: 1.5, alignItems: 'center', px: 0.5 }}>
            <ElasticitySlider
              id="inertia-elasticity-label"
              label={t('inertia.elasticity')}
              value={elasticity}
              onChange={(next) => {
                setElasticityState(next);
                if (scene !== null) setElasticity(scene, next);
              }}
            />
            <ToggleButtonGroup
              exclusive
              value={surface}
              aria-label={t('inertia.surface')}
              onChange={(_event, value: Surface | null) => {
                if (value === null) return;
                setSurfaceState(value);
                if (scene !== null) {
                  setSurface(scene, value);
                  canvasRef.current?.invalidate();
                }
                announce(t(value === 'ice' ? 'inertia.onIce' : 'inertia.onWood'));
              }}
            >
              <ToggleButton value="ice" data-surface="ice" sx={{ minHeight: 48, minWidth: 56 }}>
                {t('inertia.ice')}
              </ToggleButton>
              <ToggleButton value="wood" data-surface="wood" sx={{ minHeight: 48, minWidth: 56 }}>
                {t('inertia.wood')}
              </ToggleButton>
            </ToggleButtonGroup>
          </Box>
          <Box sx={{ display: 'flex', gap: 1, py: 0.5 }}>
            <Button
              variant="outlined"
              onClick={() => setDialogOpen(true)}
              sx={{ flex: 1, minHeight: 48 }}
              data-action="change-force"
            >
              {t('inertia.changeForce')}
            </Button>
            <Button
              variant="contained"
              color={applied ? 'secondary' : 'primary'}
              onClick={toggleForce}
              sx={{ flex: 1, minHeight: 48 }}
              data-action="toggle-force"
              aria-pressed={applied}
            >
              {applied ? t('inertia.stop') : t('inertia.apply')}
            </Button>
          </Box>
          <ForceDialog
            open={dialogOpen}
            angle={angle}
            magnitude={magnitude}
            sides={scene?.sides ?? 6}
            onClose={() => setDialogOpen(false)}
            onConfirm={confirmForce}
          />
        </>
      }
      controls={{
        paused: sim.paused,
        slow: sim.slow,
        time: scene === null ? 0 : simulatedTime(scene.world),
        onTogglePlay: sim.togglePlay,
        onToggleSlow: sim.toggleSlow,
        onStep: () =>
          scene !== null && sim.step([{ world: scene.world, canvas: canvasRef.current }]),
        onReset: build,
        onResetAll: resetAll,
      }}
    />
  );
}
