import { listenToCanvasDrags } from '../../app/canvas-drag.ts';
import { CANVAS_PIXEL_RATIO } from '../../app/theme.ts';
import {
  ARROW_COLORS,
  drawArrow,
  type OverlayDrawer,
  type PhysicalCanvasElement,
} from '@physical/canvas';
import type { Force, World } from '@physical/engine';
import { PhysicalCanvas } from '@physical/react';
import {
  Suspense,
  lazy,
  useCallback,
  useEffect,
  useLayoutEffect,
  useMemo,
  useRef,
  useState,
} from 'react';
import { useAnnouncer } from '../../app/Announcer.tsx';
import { presetFor, presetNumber } from '../../app/presets.ts';
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
import { DataTools } from '../../lab/DataTools.tsx';
import { Ruler } from '../../lab/Ruler.tsx';
import { useRewind, type Measured } from '../../lab/use-rewind.ts';
import { Button } from '../../ui/Button.tsx';
import { Switch } from '../../ui/Switch.tsx';
import { ToggleButtons } from '../../ui/ToggleButtons.tsx';
import { PUSH_KEYS, pushFromDrag, pushFromKeys, startsPush } from './body-push.ts';
import { directionName } from './direction-name.ts';
import {
  REST_SPEED,
  WALL_NAMES,
  adoptWorld,
  applyConstantForce,
  createInertiaScene,
  forceVector,
  forcesOn,
  labMotion,
  returnBody,
  sceneSizeFor,
  screenAngle,
  setElasticity,
  setSurface,
  type InertiaScene,
  type Surface,
} from './inertia-scene.ts';

// The force dialog is MUI's: it loads (with MUI) the first time it opens.
const ForceDialog = lazy(() =>
  import('./ForceDialog.tsx').then((module) => ({ default: module.ForceDialog })),
);

/** Metres of arrow per newton, and seconds of motion a velocity arrow shows. */
const FORCE_ARROW_SCALE = 0.4;
const VELOCITY_ARROW_SCALE = 0.5;
const MARGIN = 0.15;
/**
 * Colours of the friction, wall and net-force arrows (the applied force is the canvas' force
 * colour).
 */
const FRICTION_COLOR = '#b39ddb';
const WALL_COLOR = '#90caf9';
const NET_COLOR = '#fff59d';
/** Newtons below this read as none: a sum of forces this small is zero on screen. */
const NO_FORCE = 0.005;

/**
 * What a saved moment keeps beside the world: the learner's constant force (its place among the
 * body's forces, and its setting) and the place of a push by hand, -1 for none.
 */
interface MomentData {
  readonly constantAt: number;
  readonly pushAt: number;
  readonly angle: number;
  readonly magnitude: number;
}

/**
 * What the polygon measured at its world's time, for the CSV: position and velocity (x to the
 * right, y up, from the floor's left end), the acceleration Δv / Δt over the step just taken
 * (none for the first moment), its momentum and kinetic energy.
 */
function measureBody(
  scene: InertiaScene,
  before: { vx: number; vy: number } | null,
  dt: number,
): Measured[] {
  const { x, y, vx, vy } = labMotion(scene);
  const m = scene.body.mass;
  return [
    { name: 'x', unit: 'm', value: x },
    { name: 'y', unit: 'm', value: y },
    { name: 'vx', unit: 'm/s', value: vx },
    { name: 'vy', unit: 'm/s', value: vy },
    { name: 'ax', unit: 'm/s^2', value: before === null ? Number.NaN : (vx - before.vx) / dt },
    { name: 'ay', unit: 'm/s^2', value: before === null ? Number.NaN : (vy - before.vy) / dt },
    { name: 'px', unit: 'kg m/s', value: m * vx },
    { name: 'py', unit: 'kg m/s', value: m * vy },
    { name: 'KE', unit: 'J', value: 0.5 * m * (vx * vx + vy * vy) },
  ];
}

/** The first law: a polygon at rest until a force acts, then gliding at constant velocity. */
export function InertiaScreen({ active }: { active: boolean }) {
  const { t, unit, number } = useI18n();
  const sim = useSimulation();
  const canvasRef = useRef<PhysicalCanvasElement | null>(null);
  const hostRef = useRef<HTMLDivElement | null>(null);
  const [scene, setScene] = useState<InertiaScene | null>(null);
  const sceneRef = useRef<InertiaScene | null>(null);
  sceneRef.current = scene;
  // A preset link (#inertia?F=2&angle=90&e=0.5&surface=wood) chooses the first setup.
  const [preset] = useState(() => presetFor('inertia'));
  const [angle, setAngle] = useState(() => presetNumber(preset, 'angle', 0));
  const [magnitude, setMagnitude] = useState(() => presetNumber(preset, 'F', 1));
  const forceRef = useRef<Force | null>(null);
  const [applied, setApplied] = useState(false);
  // A push by hand (a drag from the body, or held arrow keys): its force, while it lasts.
  const pushRef = useRef<Force | null>(null);
  const [push, setPushState] = useState<{ x: number; y: number } | null>(null);
  const [dialogOpen, setDialogOpen] = useState(false);
  const [dialogShown, setDialogShown] = useState(false);
  const [elasticity, setElasticityState] = useState(() => presetNumber(preset, 'e', 1));
  const [surface, setSurfaceState] = useState<Surface>(() =>
    preset['surface'] === 'wood' ? 'wood' : 'ice',
  );
  const settingsRef = useRef({ elasticity, surface });
  settingsRef.current = { elasticity, surface };
  // What the canvas shows besides the body: the arrows, and the values written beside them.
  const [show, setShow] = useState({ vectors: true, values: true, ruler: false });
  const rulerCanvas = useCallback(() => canvasRef.current, []);
  const showRef = useRef(show);
  showRef.current = show;
  useEffect(() => {
    canvasRef.current?.invalidate();
  }, [show]);
  const speed = useMemo(() => new TimeSeries(10), []);
  const { announce, region } = useAnnouncer('inertia');
  const forceSettingRef = useRef({ angle, magnitude });
  forceSettingRef.current = { angle, magnitude };
  /** The velocity just before the step being taken, for the CSV's Δv / Δt. */
  const velocityBefore = useRef<{ vx: number; vy: number } | null>(null);

  // Step back, scrub and CSV: the world saved each step, restored with the forces it had.
  const worlds = useMemo(() => (scene === null ? null : [scene.world]), [scene]);
  const rewind = useRewind<MomentData>({
    worlds,
    data: () => {
      const forces = sceneRef.current!.body.forces;
      return {
        constantAt: forceRef.current === null ? -1 : forces.indexOf(forceRef.current),
        pushAt: pushRef.current === null ? -1 : forces.indexOf(pushRef.current),
        ...forceSettingRef.current,
      };
    },
    before: () => {
      velocityBefore.current = sceneRef.current === null ? null : labMotion(sceneRef.current);
    },
    measure: () => {
      const before = velocityBefore.current;
      velocityBefore.current = null;
      return measureBody(sceneRef.current!, before, sceneRef.current!.world.lastStepDuration);
    },
    adopt: ([world]: readonly World[], [data]: readonly MomentData[], time: number) => {
      const current = sceneRef.current;
      if (current === null || world === undefined || data === undefined) return;
      const next = adoptWorld(current, world);
      const forces = next.body.forces;
      const constant = data.constantAt < 0 ? null : forces[data.constantAt]!;
      // A push lasts while a finger holds the body: none holds it at a moment stepped back to.
      if (data.pushAt >= 0) forces[data.pushAt]!.remove();
      forceRef.current = constant;
      pushRef.current = null;
      setPushState(null);
      setApplied(constant !== null);
      if (constant !== null) {
        setAngle(data.angle);
        setMagnitude(data.magnitude);
      }
      speed.truncateAfter(time);
      // The push taken away: the moment shown is no longer its saved snapshot.
      if (data.pushAt >= 0) worldChanged();
      sceneRef.current = next;
      setScene(next);
    },
    pause: () => sim.setPaused(true),
  });
  const clearRewind = rewind.clear;
  const worldChanged = rewind.changed;
  // The overlay draws labels in the current language without re-creating itself.
  const labelsRef = useRef({
    applied: (value: number) => `F ${value}`,
    friction: (value: number) => `${value}`,
    wall: (value: number) => `${value}`,
    net: (value: number) => `${value}`,
    balanced: 'ΣF = 0 N',
    grid: '1 m',
  });
  labelsRef.current = {
    applied: (value) => `F = ${unit(value, 'N', 2)}`,
    friction: (value) => t('inertia.frictionLabel', { force: unit(value, 'N', 2) }),
    wall: (value) => t('inertia.wallLabel', { force: unit(value, 'N', 2) }),
    net: (value) => `ΣF = ${unit(value, 'N', 2)}`,
    balanced: t('forces.balanced'),
    grid: t('inertia.grid'),
  };
  // Re-render only when what the readouts show changed: nothing renders at rest. Paused too: a
  // step the canvas took as the pause came in shows, so a step back starts from the time shown.
  useTicker(active, 100, () => {
    const current = sceneRef.current;
    if (current === null) return '';
    const v = current.body.linearVelocity;
    const p = current.body.position;
    // The walls' push too: after an impact it settles to what holds a pinned body.
    const wall = forcesOn(current, null).wall;
    return `${current.world.steps}:${v.x},${v.y},${wall.x.toFixed(2)},${wall.y.toFixed(2)},${p.x},${p.y}`;
  });

  const build = useCallback(() => {
    const host = hostRef.current;
    const size = sceneSizeFor(host?.clientWidth ?? 0, host?.clientHeight ?? 0);
    forceRef.current = null;
    pushRef.current = null;
    setApplied(false);
    setPushState(null);
    speed.clear();
    clearRewind();
    setScene(createInertiaScene(size.width, size.height, settingsRef.current));
  }, [speed, clearRewind]);

  const resetAll = useCallback(() => {
    setAngle(0);
    setMagnitude(1);
    setElasticityState(1);
    setSurfaceState('ice');
    settingsRef.current = { elasticity: 1, surface: 'ice' };
    setShow({ vectors: true, values: true, ruler: false });
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
      // A reference grid, one metre apart, to read distances and directions against.
      context.strokeStyle = 'rgba(255, 255, 255, 0.09)';
      context.lineWidth = 1 / scale;
      context.beginPath();
      for (let x = 1; x < current.width; x++) {
        context.moveTo(x, 0);
        context.lineTo(x, current.height);
      }
      for (let y = 1; y < current.height; y++) {
        context.moveTo(0, y);
        context.lineTo(current.width, y);
      }
      context.stroke();
      const { vectors, values } = showRef.current;
      if (vectors) {
        drawArrow(
          context,
          scale,
          centre,
          { x: velocity.x * VELOCITY_ARROW_SCALE, y: velocity.y * VELOCITY_ARROW_SCALE },
          { kind: 'velocity', width: 2 },
        );
      }
      // Every force on the body, its value beside it, and their sum (dashed colour of its own).
      // The applied force: the constant one and a push by hand, summed.
      const constant = forceRef.current;
      const pushing = pushRef.current;
      const forces = forcesOn(
        current,
        constant === null && pushing === null
          ? null
          : {
              x: (constant?.x ?? 0) + (pushing?.x ?? 0),
              y: (constant?.y ?? 0) + (pushing?.y ?? 0),
            },
      );
      const labels = labelsRef.current;
      const texts: { at: { x: number; y: number }; text: string; color: string }[] = [];
      const arrow = (
        vector: { x: number; y: number },
        color: string,
        width: number,
        text: string,
      ) => {
        const size = Math.hypot(vector.x, vector.y);
        if (size < NO_FORCE) return;
        const tip = { x: vector.x * FORCE_ARROW_SCALE, y: vector.y * FORCE_ARROW_SCALE };
        if (vectors) drawArrow(context, scale, centre, tip, { color, width });
        if (values) texts.push({ at: { x: centre.x + tip.x, y: centre.y + tip.y }, text, color });
      };
      arrow(
        forces.applied,
        ARROW_COLORS.force,
        3,
        labels.applied(Math.hypot(forces.applied.x, forces.applied.y)),
      );
      arrow(
        forces.friction,
        FRICTION_COLOR,
        3,
        labels.friction(Math.hypot(forces.friction.x, forces.friction.y)),
      );
      arrow(forces.wall, WALL_COLOR, 3, labels.wall(Math.hypot(forces.wall.x, forces.wall.y)));
      const net = Math.hypot(forces.net.x, forces.net.y);
      // The sum gets its own arrow when more than one force acts (otherwise it is that force).
      const acting = [forces.applied, forces.friction, forces.wall].filter(
        (force) => Math.hypot(force.x, force.y) >= NO_FORCE,
      ).length;
      if (acting > 1) arrow(forces.net, NET_COLOR, 2, labels.net(net));
      context.restore();
      // Labels in CSS pixels, kept inside the canvas.
      const ratio = canvas.viewport.devicePixelRatio;
      context.save();
      context.setTransform(ratio, 0, 0, ratio, 0, 0);
      context.font = '600 14px system-ui, sans-serif';
      context.textBaseline = 'middle';
      const cssWidth = context.canvas.width / ratio;
      const cssHeight = context.canvas.height / ratio;
      if (net < NO_FORCE && values) {
        texts.push({
          at: { x: centre.x, y: centre.y - 0.75 },
          text: labels.balanced,
          color: 'rgba(255, 255, 255, 0.85)',
        });
      }
      // Inside the walls (and the canvas), whatever room the canvas leaves around the box.
      const inTop = canvas.worldToScreen({ x: 0, y: 0 });
      const inBottom = canvas.worldToScreen({ x: current.width, y: current.height });
      const minX = Math.max(4, inTop.x + 4);
      const maxX = Math.min(cssWidth, inBottom.x) - 4;
      const minY = Math.max(10, inTop.y + 10);
      const maxY = Math.min(cssHeight, inBottom.y) - 10;
      for (const { at, text, color } of texts) {
        const point = canvas.worldToScreen(at);
        const width = context.measureText(text).width;
        context.fillStyle = color;
        context.fillText(
          text,
          Math.max(minX, Math.min(maxX - width, point.x + 6)),
          Math.max(minY, Math.min(maxY, point.y - 10)),
        );
      }
      // The grid's scale, in the top-left corner inside the walls.
      const corner = canvas.worldToScreen({ x: 0, y: 0 });
      context.font = '13px system-ui, sans-serif';
      context.fillStyle = 'rgba(255, 255, 255, 0.6)';
      context.fillText(labels.grid, corner.x + 6, corner.y + 12);
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
      worldChanged();
    } else {
      forceRef.current = applyConstantForce(scene, angle, magnitude);
      worldChanged();
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

  const returnObject = (): void => {
    if (scene === null) return;
    returnBody(scene);
    worldChanged();
    speed.clear();
    announce(t('inertia.returned'));
    canvasRef.current?.invalidate();
  };

  /** Starts, changes or (with null) releases the push by hand. */
  const setPush = useCallback(
    (vector: { x: number; y: number } | null): void => {
      const current = sceneRef.current;
      if (current === null) return;
      worldChanged();
      const old = pushRef.current;
      if (vector === null || (vector.x === 0 && vector.y === 0)) {
        if (old === null) return;
        old.remove();
        pushRef.current = null;
        setPushState(null);
        announce(t('inertia.pushReleased'));
      } else {
        if (old === null) {
          pushRef.current = current.body.applyForce(vector, { duration: 'constant' });
          current.body.wake();
          announce(
            t('inertia.pushStarted', {
              force: unit(Math.hypot(vector.x, vector.y), 'N', 1),
              angle: number(screenAngle(vector), 0),
            }),
          );
        } else old.setVector(vector);
        setPushState(vector);
      }
      canvasRef.current?.invalidate();
    },
    [announce, t, unit, number, worldChanged],
  );

  // A press on the body and a pull push it: the way the finger moved, harder the farther, until
  // the finger lets go. Presses elsewhere go on to the canvas.
  useEffect(() => {
    const host = hostRef.current;
    if (host === null || scene === null) return;
    let start = { x: 0, y: 0 };
    return listenToCanvasDrags(host, (x, y) => canvasRef.current?.clientToWorld(x, y), {
      press: (point) => {
        if (!startsPush(scene.body.position, point)) return false;
        start = point;
        return true;
      },
      move: (point) => setPush(pushFromDrag(start, point)),
      release: () => setPush(null),
    });
  }, [scene, setPush]);

  // The keyboard's push: arrow keys held on the focused canvas push that way until let go.
  useEffect(() => {
    const canvas = canvasRef.current;
    if (canvas === null || scene === null) return;
    const held = new Set<string>();
    const onKeyDown = (event: KeyboardEvent): void => {
      if (PUSH_KEYS[event.key] === undefined) return;
      event.preventDefault();
      if (held.has(event.key)) return;
      held.add(event.key);
      setPush(pushFromKeys(held));
    };
    const onKeyUp = (event: KeyboardEvent): void => {
      if (!held.delete(event.key)) return;
      setPush(held.size === 0 ? null : pushFromKeys(held));
    };
    const onBlur = (): void => {
      held.clear();
      setPush(null);
    };
    canvas.addEventListener('keydown', onKeyDown);
    canvas.addEventListener('keyup', onKeyUp);
    canvas.addEventListener('blur', onBlur);
    return () => {
      canvas.removeEventListener('keydown', onKeyDown);
      canvas.removeEventListener('keyup', onKeyUp);
      canvas.removeEventListener('blur', onBlur);
    };
  }, [scene, setPush]);

  const confirmForce = (newAngle: number, newMagnitude: number): void => {
    setAngle(newAngle);
    setMagnitude(newMagnitude);
    setDialogOpen(false);
    forceRef.current?.setVector(forceVector(newAngle, newMagnitude));
    worldChanged();
    canvasRef.current?.invalidate();
  };

  const velocity = scene?.body.linearVelocity ?? { x: 0, y: 0 };
  const rawSpeed = Math.hypot(velocity.x, velocity.y);
  // Pressed against a wall the solver leaves a jitter of a few mm/s: that is rest.
  const moving = rawSpeed > REST_SPEED;
  const currentSpeed = moving ? rawSpeed : 0;
  const constant = applied ? forceVector(angle, magnitude) : null;
  const forces =
    scene === null
      ? null
      : forcesOn(
          scene,
          constant === null && push === null
            ? null
            : { x: (constant?.x ?? 0) + (push?.x ?? 0), y: (constant?.y ?? 0) + (push?.y ?? 0) },
        );
  const frictionSize = forces === null ? 0 : Math.hypot(forces.friction.x, forces.friction.y);
  const wallSize = forces === null ? 0 : Math.hypot(forces.wall.x, forces.wall.y);
  const netSize = forces === null ? 0 : Math.hypot(forces.net.x, forces.net.y);
  const netDescription =
    netSize < NO_FORCE
      ? t('inertia.describeBalanced')
      : t('inertia.describeNet', {
          force: unit(netSize, 'N', 2),
          angle: number(screenAngle(forces!.net), 0),
          friction: unit(frictionSize, 'N', 2),
          wall: unit(wallSize, 'N', 2),
        });
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
          force: [
            applied
              ? t('inertia.describeForce', {
                  force: unit(magnitude, 'N', 1),
                  angle: number(angle, 0),
                })
              : push === null
                ? t('inertia.describeNoForce')
                : '',
            push === null
              ? ''
              : t('inertia.describePush', {
                  force: unit(Math.hypot(push.x, push.y), 'N', 1),
                  angle: number(screenAngle(push), 0),
                }),
          ]
            .filter((part) => part !== '')
            .join(' '),
        }) +
        ' ' +
        netDescription;
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
        <>
          {/* The finger pushes the body: the browser must not take the drag for a pan. */}
          <div ref={hostRef} className="inertia-host">
            <PhysicalCanvas
              drag={false}
              maxPixelRatio={CANVAS_PIXEL_RATIO}
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
          </div>
          {show.ruler && <Ruler canvas={rulerCanvas} version={scene} />}
        </>
      }
      panel={
        <>
          {region}
          <div className="readouts">
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
                push !== null
                  ? t('inertia.pushValue', {
                      force: unit(Math.hypot(push.x, push.y), 'N', 1),
                      angle: number(screenAngle(push), 0),
                    })
                  : applied
                    ? `${unit(magnitude, 'N', 1)}, ${number(angle, 0)}°`
                    : t('inertia.forceOff')
              }
            />
            <Readout
              name="mass"
              label={t('inertia.mass')}
              value={scene === null ? '–' : unit(scene.body.mass, 'kg', 2)}
            />
            <Readout
              name="x"
              label={t('inertia.x')}
              value={scene === null ? '–' : unit(labMotion(scene).x, 'm', 2, 2)}
            />
            <Readout
              name="y"
              label={t('inertia.y')}
              value={scene === null ? '–' : unit(labMotion(scene).y, 'm', 2, 2)}
            />
          </div>
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
          <div className="panel-row">
            <ElasticitySlider
              id="inertia-elasticity-label"
              label={t('inertia.elasticity')}
              value={elasticity}
              onChange={(next) => {
                setElasticityState(next);
                if (scene !== null) setElasticity(scene, next);
                worldChanged();
              }}
            />
            <ToggleButtons
              label={t('inertia.surface')}
              value={surface}
              onChange={(value: Surface) => {
                setSurfaceState(value);
                if (scene !== null) {
                  setSurface(scene, value);
                  worldChanged();
                  canvasRef.current?.invalidate();
                }
                announce(t(value === 'ice' ? 'inertia.onIce' : 'inertia.onWood'));
              }}
              choices={(['ice', 'wood'] as const).map((value) => ({
                value,
                label: t(value === 'ice' ? 'inertia.ice' : 'inertia.wood'),
                attributes: { 'data-surface': value },
              }))}
            />
          </div>
          <div className="switches">
            {(['vectors', 'values', 'ruler'] as const).map((name) => (
              <Switch
                key={name}
                checked={show[name]}
                onChange={(value) => setShow((old) => ({ ...old, [name]: value }))}
                control={`show-${name}`}
                label={t(`inertia.show.${name}`)}
              />
            ))}
          </div>
          <DataTools
            rewind={rewind}
            fileName="newton-inertia.csv"
            live={active && !sim.paused}
            announce={announce}
          />
          {dialogShown && (
            <Suspense fallback={null}>
              <ForceDialog
                open={dialogOpen}
                angle={angle}
                magnitude={magnitude}
                sides={scene?.sides ?? 6}
                onClose={() => setDialogOpen(false)}
                onConfirm={confirmForce}
              />
            </Suspense>
          )}
        </>
      }
      actions={
        <>
          <Button
            variant="outlined"
            grow
            onClick={() => {
              setDialogOpen(true);
              setDialogShown(true);
            }}
            data-action="change-force"
          >
            {t('inertia.changeForce')}
          </Button>
          <Button
            variant="contained"
            color={applied ? 'secondary' : 'primary'}
            onClick={toggleForce}
            grow
            data-action="toggle-force"
            aria-pressed={applied}
          >
            {applied ? t('inertia.stop') : t('inertia.apply')}
          </Button>
          <Button
            variant="outlined"
            onClick={returnObject}
            className="ui-button--compact"
            data-action="return"
          >
            {t('inertia.return')}
          </Button>
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
