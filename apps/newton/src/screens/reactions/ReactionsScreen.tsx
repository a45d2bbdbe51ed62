import { Box, Button, IconButton, Tooltip, Typography } from '@mui/material';
import {
  ARROW_COLORS,
  drawArrow,
  type OverlayDrawer,
  type PhysicalCanvasElement,
} from '@physical/canvas';
import type { Body } from '@physical/engine';
import { PhysicalCanvas } from '@physical/react';
import {
  useCallback,
  useEffect,
  useLayoutEffect,
  useMemo,
  useReducer,
  useRef,
  useState,
} from 'react';
import { useAnnouncer } from '../../app/Announcer.tsx';
import { REDUCED_MOTION, CANVAS_PIXEL_RATIO } from '../../app/theme.ts';
import { AddIcon, DeleteIcon, PhoneTiltIcon } from '../../app/icons.tsx';
import { useOrientationRebuild } from '../../app/use-orientation-rebuild.ts';
import { Readout } from '../../app/Readout.tsx';
import { ScreenLayout } from '../../app/ScreenLayout.tsx';
import { STEP, simulatedTime, useSimulation } from '../../app/use-simulation.ts';
import { useTicker } from '../../app/use-ticker.ts';
import { clipToWalls } from '../../app/clip-to-walls.ts';
import { ElasticitySlider } from '../../app/ElasticitySlider.tsx';
import { useI18n } from '../../i18n/i18n.tsx';
import {
  requestTiltPermission,
  tiltNeedsPermission,
  watchDeviceTilt,
  type Tilt,
} from '../../sensors/device-tilt.ts';
import { sceneSizeFor, screenAngle } from '../inertia/inertia-scene.ts';
import { CollisionArrows, reactionArrowLength } from './collision-arrows.ts';
import {
  DEFAULT_ELASTICITY,
  clearParticles,
  createReactionsScene,
  trayAcceleration,
  setElasticity,
  setTilt,
  spawnParticle,
  freeSpot,
  isFull,
  totalMomentum,
  type ReactionsScene,
} from './reactions-scene.ts';
import { TILT_STEP, TiltPad } from './TiltPad.tsx';

const MARGIN = 0.1;
const clampTilt = (value: number): number =>
  Math.round(Math.min(1, Math.max(-1, value)) * 100) / 100;
const SELECTED_STYLE = { stroke: '#ffffff', lineWidth: 3 } as const;
/** Metres of arrow per kg m/s of momentum. */
const MOMENTUM_ARROW_SCALE = 0.5;

/** Where tilt can be asked for and makes sense: a touch device whose browser asks first (iOS). */
function tiltButtonUseful(): boolean {
  return (
    tiltNeedsPermission() &&
    typeof matchMedia === 'function' &&
    matchMedia('(pointer: coarse)').matches
  );
}

/** Keys that must keep their own meaning (text fields, sliders, dialogs). */
function ownsArrowKeys(target: EventTarget | null): boolean {
  if (!(target instanceof Element)) return false;
  return (
    target.closest('input, textarea, select, [role="slider"], [role="dialog"], [role="menu"]') !==
    null
  );
}

/** The third law: particles pushed by the tilt, equal and opposite arrows at every collision. */
export function ReactionsScreen({ active }: { active: boolean }) {
  const { t, unit, number } = useI18n();
  const sim = useSimulation();
  const canvasRef = useRef<PhysicalCanvasElement | null>(null);
  const hostRef = useRef<HTMLDivElement | null>(null);
  const [scene, setScene] = useState<ReactionsScene | null>(null);
  const sceneRef = useRef<ReactionsScene | null>(null);
  sceneRef.current = scene;
  const arrows = useMemo(() => new CollisionArrows(), []);
  const [selected, setSelected] = useState<Body | null>(null);
  const [tilt, setTiltState] = useState<Tilt>({ x: 0, y: 0 });
  const [sensorOn, setSensorOn] = useState(false);
  const [needsPermission] = useState(tiltButtonUseful);
  const [elasticity, setElasticityState] = useState(DEFAULT_ELASTICITY);
  const elasticityRef = useRef(elasticity);
  elasticityRef.current = elasticity;
  const { announce, region } = useAnnouncer('reactions');
  const [, rerender] = useReducer((count: number) => count + 1, 0);
  useTicker(active && !sim.paused, 100, () => {
    const current = sceneRef.current;
    if (current === null) return '';
    return `${current.world.steps}:${current.particles.size}:${current.world.awakeBodyCount}`;
  });

  const build = useCallback(() => {
    const host = hostRef.current;
    const size = sceneSizeFor(host?.clientWidth ?? 0, host?.clientHeight ?? 0);
    arrows.clear();
    setSelected(null);
    setTiltState({ x: 0, y: 0 });
    setScene(createReactionsScene(size.width, size.height, elasticityRef.current));
  }, [arrows]);

  useLayoutEffect(() => {
    if (active && scene === null) build();
  }, [active, scene, build]);
  useOrientationRebuild(hostRef, active ? scene : null, build);

  // The thesis's onCollision: record the arrows and each particle's last impulse.
  useEffect(() => {
    if (scene === null) return;
    return scene.world.on('collision', (event) => {
      arrows.record(event, STEP, simulatedTime(scene.world));
      if (
        event.normalImpulse > 0.02 &&
        scene.particles.has(event.bodyA) &&
        scene.particles.has(event.bodyB)
      ) {
        announce(t('reactions.collided', { force: unit(event.normalImpulse / STEP, 'N', 1) }));
      }
      for (const body of [event.bodyA, event.bodyB]) {
        const info = scene.particles.get(body);
        if (info !== undefined && event.normalImpulse > 1e-4)
          info.lastImpulse = event.normalImpulse;
      }
    });
  }, [scene, arrows, announce, t, unit]);

  const changeTilt = useCallback((next: Tilt) => {
    const current = sceneRef.current;
    setTiltState(next);
    if (current !== null) {
      setTilt(current, next);
      canvasRef.current?.invalidate();
    }
  }, []);

  // Device orientation: listen while visible; where the browser asks first (iOS), readings
  // arrive once the learner allowed them with the button.
  useEffect(() => {
    if (!active) return;
    return watchDeviceTilt((value) => {
      setSensorOn(true);
      changeTilt(value);
    });
  }, [active, changeTilt]);

  // Arrow keys tilt on a desktop.
  useEffect(() => {
    if (!active) return;
    const keys: Record<string, [number, number]> = {
      ArrowLeft: [-1, 0],
      ArrowRight: [1, 0],
      ArrowUp: [0, -1],
      ArrowDown: [0, 1],
    };
    const onKey = (event: KeyboardEvent): void => {
      const step = keys[event.key];
      if (step === undefined || event.defaultPrevented || ownsArrowKeys(event.target)) return;
      event.preventDefault();
      const current = sceneRef.current?.tilt ?? { x: 0, y: 0 };
      changeTilt({
        x: clampTilt(current.x + step[0] * TILT_STEP),
        y: clampTilt(current.y + step[1] * TILT_STEP),
      });
    };
    window.addEventListener('keydown', onKey);
    return () => window.removeEventListener('keydown', onKey);
  }, [active, changeTilt]);

  const select = (body: Body | null): void => {
    const canvas = canvasRef.current;
    if (canvas !== null && selected !== null) canvas.setStyle(selected, null);
    if (canvas !== null && body !== null) canvas.setStyle(body, SELECTED_STYLE);
    setSelected(body);
  };

  const drawOverlay = useCallback<OverlayDrawer>(
    (context, canvas) => {
      const current = sceneRef.current;
      if (current === null) return;
      const visible = arrows.visible(simulatedTime(current.world));
      const scale = canvas.viewport.scale;
      clipToWalls(context, current.width, current.height);
      // Momentum arrows: m v of each particle.
      for (const body of current.particles.keys()) {
        const v = body.linearVelocity;
        if (Math.hypot(v.x, v.y) < 0.02) continue;
        drawArrow(
          context,
          scale,
          body.position,
          {
            x: body.mass * v.x * MOMENTUM_ARROW_SCALE,
            y: body.mass * v.y * MOMENTUM_ARROW_SCALE,
          },
          { kind: 'velocity', width: 2 },
        );
      }
      for (const { arrow, opacity } of visible) {
        const length = reactionArrowLength(arrow.impulse);
        const from = { x: arrow.x, y: arrow.y };
        drawArrow(
          context,
          scale,
          from,
          { x: arrow.nx * length, y: arrow.ny * length },
          {
            kind: 'force',
            width: 3,
            opacity: REDUCED_MOTION ? 1 : opacity,
          },
        );
        drawArrow(
          context,
          scale,
          from,
          { x: -arrow.nx * length, y: -arrow.ny * length },
          {
            kind: 'impulse',
            width: 3,
            opacity: REDUCED_MOTION ? 1 : opacity,
          },
        );
      }
      context.restore();
      const host = hostRef.current;
      const count = String(visible.length * 2);
      if (host !== null && host.dataset['arrows'] !== count) host.dataset['arrows'] = count;
    },
    [arrows],
  );

  const add = (point: { x: number; y: number }): void => {
    if (scene === null) return;
    if (isFull(scene)) {
      announce(t('reactions.full'), true);
      return;
    }
    const body = spawnParticle(scene, point);
    canvasRef.current?.invalidate();
    rerender();
    announce(
      t('reactions.added', {
        mass: unit(body.mass, 'kg', 2),
        count: scene.particles.size,
      }),
      true,
    );
  };

  const onTap = (point: { x: number; y: number }, body: Body | null): void => {
    if (scene === null) return;
    if (body !== null && scene.particles.has(body)) {
      select(body);
      return;
    }
    add(point);
  };

  /** The keyboard's way to add: a random free-looking spot inside the box. */
  const addAnywhere = (): void => {
    if (scene === null) return;
    add(freeSpot(scene));
  };

  const info = selected === null ? undefined : scene?.particles.get(selected);
  const push = trayAcceleration(tilt);
  const pushSize = Math.hypot(push.x, push.y);
  const momentum = scene === null ? { x: 0, y: 0 } : totalMomentum(scene);
  const momentumSize = Math.hypot(momentum.x, momentum.y);
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
      id="reactions"
      active={active}
      law={t('reactions.law')}
      stage={
        <Box ref={hostRef} data-arrows="0" sx={{ flex: 1, minWidth: 0, display: 'flex' }}>
          <PhysicalCanvas
            maxPixelRatio={CANVAS_PIXEL_RATIO}
            ref={canvasRef}
            paused={sim.paused}
            world={scene?.world ?? null}
            fit="contain"
            viewBox={viewBox}
            timeScale={sim.timeScale}
            drawOverlay={drawOverlay}
            onBodyTap={({ body, point }) => onTap(point, body)}
            onBackgroundTap={({ point }) => onTap(point, null)}
            onPauseChange={({ paused }) => sim.setPaused(paused)}
            aria-label={t('reactions.canvas')}
            style={{ flex: 1, height: 'auto' }}
          />
        </Box>
      }
      panel={
        <>
          {region}
          <Box
            sx={{ minHeight: 44, px: 0.5, display: 'flex', alignItems: 'center' }}
            data-readout="particle-info"
          >
            {selected !== null && info !== undefined ? (
              <Box
                sx={{ display: 'grid', gridTemplateColumns: 'repeat(4, auto)', gap: 1.5, flex: 1 }}
              >
                <Readout
                  name="particle-mass"
                  label={t('reactions.mass')}
                  value={unit(selected.mass, 'kg', 3)}
                />
                <Readout
                  name="particle-speed"
                  label={t('reactions.speed')}
                  value={unit(
                    Math.hypot(selected.linearVelocity.x, selected.linearVelocity.y),
                    'm/s',
                    2,
                    2,
                  )}
                />
                <Readout
                  name="particle-impulse"
                  label={t('reactions.impulse')}
                  value={
                    info.lastImpulse === null
                      ? t('reactions.none')
                      : unit(info.lastImpulse, 'N·s', 3)
                  }
                />
                <Readout
                  name="particle-position"
                  label={t('reactions.position')}
                  value={`${number(selected.position.x, 2, 2)}, ${number(selected.position.y, 2, 2)} m`}
                />
              </Box>
            ) : (
              <Typography variant="body2" sx={{ color: 'text.secondary' }}>
                {t('reactions.tapToInspect')}
              </Typography>
            )}
          </Box>
          <Box sx={{ display: 'flex', alignItems: 'center', gap: 1.5 }}>
            <Tooltip title={t('reactions.add')}>
              <IconButton
                aria-label={t('reactions.add')}
                onClick={addAnywhere}
                data-action="add"
                color="primary"
                sx={{ width: 48, height: 48 }}
              >
                <AddIcon />
              </IconButton>
            </Tooltip>
            <TiltPad
              onNudge={(dx, dy) =>
                changeTilt({ x: clampTilt(tilt.x + dx), y: clampTilt(tilt.y + dy) })
              }
              onLevel={() => changeTilt({ x: 0, y: 0 })}
            />
            <Box sx={{ display: 'flex', flexDirection: 'column', gap: 1, flex: 1, minWidth: 0 }}>
              <Readout
                name="push"
                label={t('reactions.pushForce')}
                value={
                  pushSize < 1e-6
                    ? unit(0, 'm/s²')
                    : `${unit(pushSize, 'm/s²', 2)}, ${number(screenAngle(push), 0)}°`
                }
              />
              <Readout
                name="count"
                label={t('reactions.count')}
                value={
                  scene !== null && isFull(scene)
                    ? t('reactions.countFull', { count: scene.particles.size })
                    : String(scene?.particles.size ?? 0)
                }
              />
              <Readout
                name="momentum"
                label={t('reactions.momentum')}
                value={
                  momentumSize < 0.005
                    ? unit(0, 'kg·m/s', 2)
                    : `${unit(momentumSize, 'kg·m/s', 2)}, ${number(screenAngle(momentum), 0)}°`
                }
              />
            </Box>
            <Box
              sx={{ display: 'flex', flexDirection: 'column', alignItems: 'flex-end', gap: 0.5 }}
            >
              {needsPermission && !sensorOn && (
                <Button
                  variant="outlined"
                  sx={{ minHeight: 48 }}
                  startIcon={<PhoneTiltIcon />}
                  onClick={() => void requestTiltPermission()}
                >
                  {t('reactions.enableTilt')}
                </Button>
              )}
              <Tooltip title={t('reactions.clear')}>
                <IconButton
                  aria-label={t('reactions.clear')}
                  onClick={() => {
                    if (scene === null) return;
                    select(null);
                    clearParticles(scene);
                    arrows.clear();
                  }}
                  data-action="clear"
                  sx={{ width: 48, height: 48 }}
                >
                  <DeleteIcon />
                </IconButton>
              </Tooltip>
            </Box>
          </Box>
          <Box sx={{ display: 'flex', gap: 1.5, alignItems: 'center', px: 0.5 }}>
            <ElasticitySlider
              id="reactions-elasticity-label"
              label={t('reactions.elasticity')}
              value={elasticity}
              onChange={(next) => {
                setElasticityState(next);
                if (scene !== null) setElasticity(scene, next);
              }}
            />
          </Box>
          <Typography variant="caption" component="p" sx={{ px: 0.5, m: 0 }} data-legend="arrows">
            <Box component="span" sx={{ color: ARROW_COLORS.force, fontWeight: 700 }}>
              →
            </Box>
            <Box component="span" sx={{ color: ARROW_COLORS.impulse, fontWeight: 700 }}>
              ←
            </Box>{' '}
            {t('reactions.legend')}{' '}
            <Box component="span" sx={{ color: ARROW_COLORS.velocity, fontWeight: 700 }}>
              →
            </Box>{' '}
            {t('reactions.legendMomentum')}
          </Typography>
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
      }}
    />
  );
}
