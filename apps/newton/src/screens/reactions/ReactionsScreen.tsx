import {
  Box,
  Button,
  FormControlLabel,
  MenuItem,
  Switch,
  Tab,
  Tabs,
  TextField,
  ToggleButton,
  ToggleButtonGroup,
  Typography,
} from '@mui/material';
import {
  ARROW_COLORS,
  ArrowBatch,
  drawArrow,
  type OverlayDrawer,
  type PhysicalCanvasElement,
  type StyleResolver,
  type Viewport,
} from '@physical/canvas';
import type { Body, World } from '@physical/engine';
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
import { REDUCED_MOTION } from '../../app/theme.ts';
import { usePixelRatioGovernor } from '../../app/use-pixel-ratio-governor.ts';
import { AddIcon, DeleteIcon, PhoneTiltIcon } from '../../app/icons.tsx';
import { useOrientationRebuild } from '../../app/use-orientation-rebuild.ts';
import { presetFor } from '../../app/presets.ts';
import { Readout } from '../../app/Readout.tsx';
import { MuiTheme } from '../../app/MuiTheme.tsx';
import { SIDE_BY_SIDE, ScreenLayout } from '../../app/ScreenLayout.tsx';
import { STEP, simulatedTime, useSimulation } from '../../app/use-simulation.ts';
import { Live } from '../../app/Live.tsx';
import { LiveText } from '../../app/LiveText.tsx';
import { listenToCanvasDrags } from '../../app/canvas-drag.ts';
import { clipToWalls } from '../../app/clip-to-walls.ts';
import { ElasticitySlider } from '../../app/ElasticitySlider.tsx';
import { useI18n, type MessageKey } from '../../i18n/i18n.tsx';
import { DataTools } from '../../lab/DataTools.tsx';
import { useRewind } from '../../lab/use-rewind.ts';
import {
  requestTiltPermission,
  tiltNeedsPermission,
  watchDeviceTilt,
  type Tilt,
} from '../../sensors/device-tilt.ts';
import { sceneSizeFor, screenAngle } from '../inertia/inertia-scene.ts';
import {
  CONTACT_TIMES,
  CollisionArrows,
  DEFAULT_CONTACT_TIME,
  averageForce,
  type ArrowMeasure,
} from './collision-arrows.ts';
import { CollisionRecorder, totalMomentumOf, type CollisionRecord } from './collision-lab.ts';
import { drawReactionArrows } from './draw-reaction-arrows.ts';
import { LabResults } from './LabResults.tsx';
import { LabelSprites } from './label-sprites.ts';
import { DiscSprites } from './disc-sprites.ts';
import { StepBlend } from './step-blend.ts';
import { IconButton as UiIconButton } from '../../ui/IconButton.tsx';
import { ParticleColumns } from './particle-columns.ts';
import { LabSetup, type LabField, type LabRow } from './LabSetup.tsx';
import {
  DEFAULT_ELASTICITY,
  adoptWorld,
  applyTilt,
  clearParticles,
  createReactionsScene,
  freeSpot,
  isFull,
  labelsByIndex,
  setElasticity,
  setParticleMass,
  setTilt,
  setTiltOn,
  setUpLab,
  setWallsOn,
  spawnParticle,
  trayAcceleration,
  type LabParticle,
  type ReactionsScene,
} from './reactions-scene.ts';
import { TILT_STEP, TiltPad } from './TiltPad.tsx';
import {
  HANDLE_REACH,
  VELOCITY_ARROW_SCALE,
  handlePoint,
  velocityFromHandle,
} from './velocity-handle.ts';

const MARGIN = 0.1;
const clampTilt = (value: number): number =>
  Math.round(Math.min(1, Math.max(-1, value)) * 100) / 100;
/** Outlines (colour, CSS px) of the selected particle and of the lab's other chosen one. */
const SELECTED_OUTLINE = { color: '#ffffff', width: 3 } as const;
const CHOSEN_OUTLINE = { color: '#82b1ff', width: 2 } as const;
/** Metres of arrow per kg m/s of momentum. */
const MOMENTUM_ARROW_SCALE = 0.5;
/** The momentum arrows' batch, reused every frame. */
const momentumArrows = new ArrowBatch();
/** The particles' names as bitmaps, made once each. */
const labelSprites = new LabelSprites();
/**
 * The particles are drawn by the overlay (DiscSprites: bitmaps copied at whole pixels, a third of
 * the cost of filling 50 discs on a phone that rasterises on its CPU), in their palette colour and
 * without the default's dark outline (50 translucent outlines cost as much as the discs, and the
 * particles never overlap); the canvas draws the walls.
 */
const PARTICLE_STYLE = { visible: false } as const;
/** The canvas's style of each body: the particles (the only moving bodies) are the overlay's. */
const styleFor: StyleResolver = (body) => (body.type === 'dynamic' ? PARTICLE_STYLE : undefined);
/** The particles' discs, made once per colour and size. */
const discSprites = new DiscSprites();
/** The particles' positions before the last step, to draw them between steps (slow motion). */
const stepBlend = new StepBlend();
/** Where the overlay draws a particle this frame (scratch). */
const drawnAt = { x: 0, y: 0 };
/** The chosen particles' velocity arrows, which a learner drags. */
const HANDLE_COLOR = '#ffffff';
const HANDLE_ARROW = { color: HANDLE_COLOR, width: 2 } as const;
/** Scratch points of the handles' arrows, rewritten each frame. */
const handleTip = { x: 0, y: 0 };
const handleStart = { x: 0, y: 0 };
const handleVector = { x: 0, y: 0 };
/** Milliseconds between two writes of the arrow count (`data-arrows`). */
const ARROW_COUNT_MS = 250;
/** Saved steps to rewind through: the last 5 s at 60 steps a second. */
const HISTORY_STEPS = 300;
/**
 * A world snapshot every 0.5 s; stepping back replays from the one before. A snapshot of 50
 * particles took 8.8 ms against 1.3 ms for their step (a loaded 2-core machine): one a step
 * would cost the frame rate, one every 30 steps costs 0.3 ms a step.
 */
const SNAPSHOT_INTERVAL = 30;
/** The collision lab's first setup: a light particle overtaking... no, meeting a heavy one. */
const DEFAULT_LAB: readonly LabParticle[] = [
  { mass: 1, vx: 1.5 },
  { mass: 2, vx: -0.5 },
];
const PANEL_TABS = ['tray', 'setup', 'results', 'options', 'data'] as const;
type PanelTab = (typeof PANEL_TABS)[number];
const TAB_LABELS: Record<PanelTab, MessageKey> = {
  tray: 'reactions.tabTray',
  setup: 'reactions.tabSetup',
  results: 'reactions.tabResults',
  options: 'reactions.tabOptions',
  data: 'reactions.tabData',
};

/** The settings of the screen (what Reset all returns to its defaults). */
interface Settings {
  readonly elasticity: number;
  readonly wallsOn: boolean;
  readonly tiltOn: boolean;
  readonly measure: ArrowMeasure;
  readonly contactTime: number;
  /** The collision lab's particles, or null for an empty box. */
  readonly lab: readonly LabParticle[] | null;
}

const DEFAULT_SETTINGS: Settings = {
  elasticity: DEFAULT_ELASTICITY,
  wallsOn: true,
  tiltOn: true,
  measure: 'impulse',
  contactTime: DEFAULT_CONTACT_TIME,
  lab: null,
};

/** The settings a preset link (`#reactions?mA=1&vA=2...`) asks for, or null without one. */
function settingsFromPreset(hash: string): Settings | null {
  const values = presetFor('reactions', hash);
  if (Object.keys(values).length === 0) return null;
  const num = (name: string, fallback: number): number =>
    typeof values[name] === 'number' ? values[name] : fallback;
  return {
    elasticity: num('e', DEFAULT_ELASTICITY),
    wallsOn: values['walls'] !== '0',
    tiltOn: values['tilt'] !== '0',
    measure: values['arrows'] === 'force' ? 'force' : 'impulse',
    contactTime: typeof values['dt'] === 'string' ? Number(values['dt']) : DEFAULT_CONTACT_TIME,
    lab: [
      {
        mass: num('mA', DEFAULT_LAB[0]!.mass),
        vx: num('vA', DEFAULT_LAB[0]!.vx),
        vy: num('vAy', 0),
      },
      {
        mass: num('mB', DEFAULT_LAB[1]!.mass),
        vx: num('vB', DEFAULT_LAB[1]!.vx),
        vy: num('vBy', 0),
      },
    ],
  };
}

/** What a saved moment keeps beside the world: the names by body index and the lab's record. */
interface MomentData {
  readonly labels: (string | null)[];
  readonly added: number;
  readonly chosen: readonly string[];
  readonly record: CollisionRecord | null;
  /** The tray's lean in this step, and whether it pushed (replayed, not snapshotted). */
  readonly tilt: Tilt;
  readonly tiltOn: boolean;
}

/** A key per record object: the results table renders when the record is another one. */
const recordKeys = new WeakMap<CollisionRecord, string>();
let recordCount = 0;
function recordKey(record: CollisionRecord | null): string {
  if (record === null) return '';
  let key = recordKeys.get(record);
  if (key === undefined) {
    key = String(++recordCount);
    recordKeys.set(record, key);
  }
  return key;
}

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
    target.closest(
      'input, textarea, select, [role="slider"], [role="dialog"], [role="menu"], [role="tab"], [role="listbox"]',
    ) !== null
  );
}

/**
 * Draws every particle (discs from `discSprites`), then the outlines of the lab's chosen ones:
 * the selected one white, the other blue. The context is in world metres, clipped to the tray.
 */
function drawParticles(
  context: CanvasRenderingContext2D,
  viewport: Viewport,
  scene: ReactionsScene,
  chosen: readonly Body[],
  selected: Body | null,
  fraction: number,
): void {
  discSprites.begin(context, viewport);
  let k = 0;
  for (const [body, info] of scene.particles) {
    const geometry = body.shapes[0]?.geometry;
    stepBlend.at(body, k++, fraction, drawnAt);
    if (geometry?.kind !== 'circle') continue;
    discSprites.add(drawnAt.x, drawnAt.y, geometry.radius, info.color);
  }
  discSprites.finish();
  k = 0;
  for (const body of scene.particles.keys()) {
    const outline =
      body === selected ? SELECTED_OUTLINE : chosen.includes(body) ? CHOSEN_OUTLINE : null;
    if (outline !== null) outlineParticle(context, viewport, body, k, fraction, outline);
    k++;
  }
}

function outlineParticle(
  context: CanvasRenderingContext2D,
  viewport: Viewport,
  body: Body,
  k: number,
  fraction: number,
  outline: { readonly color: string; readonly width: number },
): void {
  const geometry = body.shapes[0]?.geometry;
  if (geometry?.kind !== 'circle') return;
  stepBlend.at(body, k, fraction, drawnAt);
  context.beginPath();
  context.arc(drawnAt.x, drawnAt.y, geometry.radius, 0, 2 * Math.PI);
  context.lineWidth = outline.width / viewport.scale;
  context.strokeStyle = outline.color;
  context.stroke();
}

/**
 * The third law, and a collision lab: particles on a tray the phone tilts, equal and opposite
 * arrows at every collision; two chosen particles with typed or dragged masses and velocities,
 * their momentum and kinetic energy before and after they collide; step back, scrub and export.
 */
export function ReactionsScreen({ active }: { active: boolean }) {
  const { t, unit, number } = useI18n();
  const sim = useSimulation();
  // The overlay reads the time scale and the pause as they are at each frame.
  const simRef = useRef(sim);
  simRef.current = sim;
  const canvasRef = useRef<PhysicalCanvasElement | null>(null);
  const hostRef = useRef<HTMLDivElement | null>(null);
  const [scene, setScene] = useState<ReactionsScene | null>(null);
  const sceneRef = useRef<ReactionsScene | null>(null);
  sceneRef.current = scene;
  const arrows = useMemo(() => new CollisionArrows(), []);
  const recorder = useMemo(() => new CollisionRecorder(), []);
  /** The strongest impulse (N s) between two particles in this step: told after it. */
  const strongest = useRef(0);
  const columns = useMemo(() => new ParticleColumns(), []);
  /** Collision arrows drawn in the last frame. */
  const arrowCount = useRef(0);
  const [initialPreset] = useState(() => settingsFromPreset(location.hash));
  const [settings, setSettings] = useState<Settings>(initialPreset ?? DEFAULT_SETTINGS);
  const settingsRef = useRef(settings);
  settingsRef.current = settings;
  const [selected, setSelected] = useState<Body | null>(null);
  const [chosen, setChosen] = useState<readonly Body[]>([]);
  const chosenRef = useRef(chosen);
  chosenRef.current = chosen;
  const [sensorOn, setSensorOn] = useState(false);
  const [needsPermission] = useState(tiltButtonUseful);
  const [tab, setTab] = useState<PanelTab>(initialPreset !== null ? 'setup' : 'tray');
  /** Bumped when the setup's values change from outside the table (the fields refill). */
  const [version, bumpVersion] = useReducer((count: number) => count + 1, 0);
  const [description, setDescription] = useState('');
  const { announce, region } = useAnnouncer('reactions');
  const [, rerender] = useReducer((count: number) => count + 1, 0);
  // The live readouts rewrite their own text (LiveText) and the results table re-renders on its
  // own (Live) when the record changed: with 50 particles a re-render of the screen ten times a
  // second took most of a slow phone's frame time.
  const live = active && !sim.paused;
  // Fewer pixels once the canvas cannot draw its frames in time (a slow phone, many particles).
  const pixelRatio = usePixelRatioGovernor(canvasRef, live);
  const labelOf = useCallback(
    (body: Body): string => sceneRef.current?.particles.get(body)?.label ?? '?',
    [],
  );

  /** Makes `bodies` the lab's pair (from 0 to 2 particles) and starts a new record. */
  const choosePair = useCallback(
    (bodies: readonly Body[], current: ReactionsScene) => {
      setChosen(bodies);
      const [a, b] = bodies;
      recorder.setPair(
        a !== undefined && b !== undefined
          ? [a, b, current.particles.get(a)!.label, current.particles.get(b)!.label]
          : null,
      );
    },
    [recorder],
  );

  /** A description of what is on the tray, for screen readers (live, polite). */
  const describe = useCallback(
    (current: ReactionsScene | null = sceneRef.current) => {
      if (current === null) return;
      const parts = [t('reactions.describeCount', { count: current.particles.size })];
      for (const body of chosenRef.current) {
        const info = current.particles.get(body);
        if (info === undefined) continue;
        const v = body.linearVelocity;
        parts.push(
          t('reactions.describeParticle', {
            name: info.label,
            mass: unit(body.mass, 'kg', 3),
            vx: unit(v.x, 'm/s', 2),
            vy: unit(v.y, 'm/s', 2),
          }),
        );
      }
      const record = recorder.record;
      if (record !== null) {
        const before = totalMomentumOf(record.before);
        const after = totalMomentumOf(record.after);
        parts.push(
          t('reactions.describeRecord', {
            before: unit(before.x, 'kg·m/s', 3),
            after: unit(after.x, 'kg·m/s', 3),
          }),
        );
      }
      setDescription(parts.join(' '));
    },
    [t, unit, recorder],
  );

  // The labels and the chosen pair change only when particles come, go or are chosen: a moment
  // shares the last one's lists until then (one snapshot entry a step, and no new arrays a step).
  const lastMoment = useRef<{
    scene: ReactionsScene;
    added: number;
    size: number;
    pair: readonly Body[];
    labels: (string | null)[];
    chosen: string[];
  } | null>(null);
  const momentData = useCallback(
    (current: ReactionsScene): MomentData => {
      const pair = chosenRef.current;
      let last = lastMoment.current;
      if (
        last === null ||
        last.scene !== current ||
        last.added !== current.added ||
        last.size !== current.particles.size ||
        last.pair !== pair
      ) {
        last = {
          scene: current,
          added: current.added,
          size: current.particles.size,
          pair,
          labels: labelsByIndex(current),
          chosen: pair.map((body) => current.particles.get(body)?.label ?? ''),
        };
        lastMoment.current = last;
      }
      return {
        labels: last.labels,
        added: current.added,
        chosen: last.chosen,
        record: recorder.record,
        tilt: current.tilt,
        tiltOn: current.tiltOn,
      };
    },
    [recorder],
  );

  // Step back, scrub and CSV: the world saved each step, with the names and the lab's record.
  const worlds = useMemo(() => (scene === null ? null : [scene.world]), [scene]);
  const rewind = useRewind<MomentData>({
    worlds,
    capacity: HISTORY_STEPS,
    interval: SNAPSHOT_INTERVAL,
    data: () => momentData(sceneRef.current!),
    before: () => {
      // The lean of the tray as it is now, once a step (a phone in the hand sends a new one with
      // almost every frame): the step's data keeps it, and a replay puts it back.
      const current = sceneRef.current;
      if (current !== null) {
        setTilt(current, current.tilt);
        stepBlend.before(current.particles.keys());
      }
      recorder.beforeStep();
    },
    replay: (world, data) => applyTilt(world, data.tilt, data.tiltOn),
    // The lab's record of this step first: the saved moment keeps it.
    after: () => {
      stepBlend.after(performance.now());
      const current = sceneRef.current;
      if (current === null) return;
      announceCollisionRef.current();
      if (recorder.afterStep(simulatedTime(current.world) - STEP)) describe(current);
    },
    measure: () => columns.fill(sceneRef.current!.particles),
    adopt: ([world]: readonly World[], [data]: readonly MomentData[]) => {
      const current = sceneRef.current;
      if (current === null || world === undefined || data === undefined) return;
      const next = adoptWorld(current, world, data.labels, data.added);
      // The switches as they are now, not as they were.
      const now = settingsRef.current;
      setElasticity(next, now.elasticity);
      setWallsOn(next, now.wallsOn);
      next.tiltOn = now.tiltOn;
      setTilt(next, current.tilt);
      // Those switches may differ from the moment's: going on from here, it needs its own snapshot.
      worldChanged();
      const byLabel = new Map([...next.particles].map(([body, info]) => [info.label, body]));
      const pair = data.chosen.flatMap((label) => byLabel.get(label) ?? []);
      arrows.clear();
      choosePair(pair, next);
      recorder.record = data.record;
      setSelected(selected === null ? null : (byLabel.get(labelOf(selected)) ?? null));
      sceneRef.current = next;
      setScene(next);
      bumpVersion();
      describe(next);
    },
    pause: () => sim.setPaused(true),
  });
  const clearRewind = rewind.clear;
  const worldChanged = rewind.changed;

  /** A new scene with the settings (and the lab's particles, if any), paused for a lab. */
  const build = useCallback(
    (next: Settings = settingsRef.current) => {
      const host = hostRef.current;
      const size = sceneSizeFor(host?.clientWidth ?? 0, host?.clientHeight ?? 0);
      arrows.clear();
      clearRewind();
      setSelected(null);
      const created = createReactionsScene(size.width, size.height, next.elasticity);
      setWallsOn(created, next.wallsOn);
      setTiltOn(created, next.tiltOn);
      let pair: Body[] = [];
      if (next.lab !== null) {
        pair = setUpLab(created, next.lab);
        sim.setPaused(true);
      }
      sceneRef.current = created;
      choosePair(pair, created);
      setSelected(pair[0] ?? null);
      bumpVersion();
      setScene(created);
      describe(created);
    },
    [arrows, clearRewind, sim, choosePair, describe],
  );

  useLayoutEffect(() => {
    if (active && scene === null) build();
  }, [active, scene, build]);
  const rebuild = useCallback(() => build(), [build]);
  useOrientationRebuild(hostRef, active ? scene : null, rebuild, sceneSizeFor);

  // A preset link followed while the screen is up sets it up again.
  useEffect(() => {
    const onHash = (): void => {
      const next = settingsFromPreset(location.hash);
      if (next === null) return;
      setSettings(next);
      setTab('setup');
      build(next);
    };
    window.addEventListener('hashchange', onHash);
    return () => window.removeEventListener('hashchange', onHash);
  }, [build]);

  // Each collision: the arrows, the lab's record (its steps are recorded around each step by
  // the rewind hook) and what is announced.
  useEffect(() => {
    if (scene === null) return;
    const world = scene.world;
    return world.on('collision', (event) => {
      arrows.record(event, STEP, simulatedTime(world));
      recorder.collided(event);
      // Only the step's strongest collision is told (after the step): formatting a sentence for
      // each of a crowd's collisions cost more than the announcer, which keeps two, would use.
      if (
        event.normalImpulse > Math.max(0.02, strongest.current) &&
        scene.particles.has(event.bodyA) &&
        scene.particles.has(event.bodyB)
      ) {
        strongest.current = event.normalImpulse;
      }
      if (event.normalImpulse > 1e-4) {
        const a = scene.particles.get(event.bodyA);
        if (a !== undefined) a.lastImpulse = event.normalImpulse;
        const b = scene.particles.get(event.bodyB);
        if (b !== undefined) b.lastImpulse = event.normalImpulse;
      }
    });
  }, [scene, arrows, recorder]);

  /**
   * Tells the step's strongest collision between particles, if any. The sentence is written when
   * the announcer speaks it (at most one in ANNOUNCE_GAP_MS): a crowd collides in every step.
   */
  const announceCollision = (): void => {
    const impulse = strongest.current;
    if (impulse === 0) return;
    strongest.current = 0;
    const { measure, contactTime } = settingsRef.current;
    announce(() =>
      measure === 'impulse'
        ? t('reactions.collidedImpulse', { impulse: unit(impulse, 'N·s', 3) })
        : t('reactions.collidedForce', {
            force: unit(averageForce(impulse, contactTime), 'N', 1),
            time: unit(contactTime, 's', 3),
          }),
    );
  };
  const announceCollisionRef = useRef(announceCollision);
  announceCollisionRef.current = announceCollision;

  // Paused, or another particle chosen or set up: the description says how things are now.
  useEffect(() => {
    if (sim.paused) describe();
  }, [sim.paused, describe, chosen, version]);

  /**
   * Leans the tray: the next step takes the new lean (the rewind's `before`), and its saved
   * moment keeps it. On a phone in the hand the sensor's readings come with almost every frame,
   * each a little off the last: a snapshot of the world for each (to step back exactly) cost
   * 5 ms a frame at 4x CPU (50 particles), and gravity set at once woke the particles at each
   * reading. `render`: false for the sensor's readings (a render of the screen for each, MUI's tree, cost
   * a few milliseconds); the tray's acceleration readout reads the scene's tilt on its own
   * (LiveText). A key or a tap re-renders at once.
   */
  const changeTilt = useCallback(
    (next: Tilt, render = true) => {
      const current = sceneRef.current;
      if (render) rerender();
      if (current !== null) {
        current.tilt = next;
        // With every particle asleep the canvas takes no step, so no next step would take the
        // lean: lean the world now (a new gravity wakes the particles), and give the next
        // step's moment a snapshot of its own, since the change came between steps.
        if (current.world.awakeBodyCount === 0) {
          const { x, y } = current.world.gravity;
          setTilt(current, next);
          const now = current.world.gravity;
          if (now.x !== x || now.y !== y) worldChanged();
        }
        canvasRef.current?.invalidate();
      }
    },
    [worldChanged],
  );

  // Device orientation: listen while visible; where the browser asks first (iOS), readings
  // arrive once the learner allowed them with the button.
  useEffect(() => {
    if (!active) return;
    return watchDeviceTilt((value) => {
      setSensorOn(true);
      changeTilt(value, false);
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

  // The canvas is described by the live description (the React binding passes no aria props
  // but the label).
  useEffect(() => {
    canvasRef.current?.setAttribute('aria-describedby', 'reactions-description');
  }, [scene]);

  // The overlay draws the particles and outlines the selected one white, the other chosen blue.
  const selectedRef = useRef(selected);
  selectedRef.current = selected;
  useEffect(() => {
    canvasRef.current?.invalidate();
  }, [scene, selected, chosen]);

  /** Chooses a particle (a tap, or the keyboard): selected, and one of the lab's pair. */
  const choose = (body: Body): void => {
    if (scene === null) return;
    setSelected(body);
    const pair = chosen.includes(body) ? chosen : [...chosen, body].slice(-2);
    if (pair !== chosen) choosePair(pair, scene);
    bumpVersion();
    const info = scene.particles.get(body);
    if (info !== undefined) {
      announce(
        t('reactions.chosen', {
          name: info.label,
          mass: unit(body.mass, 'kg', 3),
          speed: unit(Math.hypot(body.linearVelocity.x, body.linearVelocity.y), 'm/s', 2),
        }),
        true,
      );
    }
  };

  /** The keyboard's way to choose: the next particle by name after the selected one. */
  const chooseNext = (): void => {
    if (scene === null || scene.particles.size === 0) return;
    const bodies = [...scene.particles.keys()];
    const index = selected === null ? -1 : bodies.indexOf(selected);
    choose(bodies[(index + 1) % bodies.length]!);
  };

  /** The lab's setup changes with what was typed: the chosen particle's mass or velocity. */
  const changeLab = (label: string, field: LabField, value: number): void => {
    if (scene === null) return;
    const body = [...scene.particles].find(([, info]) => info.label === label)?.[0];
    if (body === undefined) return;
    if (field === 'mass') setParticleMass(body, value);
    else {
      const v = body.linearVelocity;
      body.linearVelocity = field === 'vx' ? { x: value, y: v.y } : { x: v.x, y: value };
    }
    afterLabEdit();
  };

  /** After a typed or dragged change: a new record, the setup remembered for Restart. */
  const afterLabEdit = (): void => {
    const current = sceneRef.current;
    if (current === null) return;
    const pair = chosenRef.current;
    choosePair(pair, current);
    if (pair.length === 2) {
      const lab = pair.map((body) => ({
        mass: body.mass,
        vx: body.linearVelocity.x,
        vy: body.linearVelocity.y,
      }));
      setSettings((old) => ({ ...old, lab }));
    }
    // The saved moments led to another state: this is the new start.
    rewind.restart();
    canvasRef.current?.invalidate();
    describe(current);
    rerender();
  };

  // Dragging a chosen particle's velocity arrow sets its velocity (presses near a handle only;
  // every other press goes on to the canvas: taps add and choose particles).
  useEffect(() => {
    const host = hostRef.current;
    if (host === null || scene === null) return;
    let dragging: Body | null = null;
    return listenToCanvasDrags(host, (x, y) => canvasRef.current?.clientToWorld(x, y), {
      press: (point) => {
        dragging =
          chosenRef.current.find((body) => {
            const handle = handlePoint(body);
            return Math.hypot(handle.x - point.x, handle.y - point.y) <= HANDLE_REACH;
          }) ?? null;
        if (dragging === null) return false;
        sim.setPaused(true);
        setSelected(dragging);
        return true;
      },
      move: (point) => {
        if (dragging === null) return;
        dragging.linearVelocity = velocityFromHandle(dragging, point);
        canvasRef.current?.invalidate();
        rerender();
      },
      release: () => {
        dragging = null;
        bumpVersion();
        afterLabEdit();
      },
    });
    // afterLabEdit reads refs only: listening again on each render is not needed.
  }, [scene, sim.setPaused]);

  const drawOverlay = useCallback<OverlayDrawer>(
    (context, canvas) => {
      const current = sceneRef.current;
      if (current === null) return;
      const visible = arrows.visible(simulatedTime(current.world));
      const scale = canvas.viewport.scale;
      const { measure, contactTime } = settingsRef.current;
      clipToWalls(context, current.width, current.height);
      const lab = chosenRef.current;
      const fraction = stepBlend.fraction(
        performance.now(),
        (1000 * STEP) / simRef.current.timeScale,
        simRef.current.paused,
      );
      drawParticles(context, canvas.viewport, current, lab, selectedRef.current, fraction);
      // Momentum arrows m v of the other particles; the chosen ones' velocity arrows, to drag.
      // One batch (a few fills) for all of them: with 50 particles, 100 strokes and fills a
      // frame cost a slow phone more raster time than the particles themselves.
      momentumArrows.begin(context, 2, 1 / scale, ARROW_COLORS.velocity);
      for (const body of current.particles.keys()) {
        const v = body.linearVelocity;
        if (lab.includes(body)) continue;
        if (Math.hypot(v.x, v.y) < 0.02) continue;
        const position = body.position;
        momentumArrows.add(
          position.x,
          position.y,
          body.mass * v.x * MOMENTUM_ARROW_SCALE,
          body.mass * v.y * MOMENTUM_ARROW_SCALE,
        );
      }
      momentumArrows.finish();
      drawReactionArrows(context, scale, visible, measure, contactTime, REDUCED_MOTION);
      context.restore();
      // Outside the clip: a handle may sit past a wall, and must stay reachable. Scratch points
      // and one style object: the overlay allocates nothing a frame.
      for (const body of lab) {
        const tip = handlePoint(body, handleTip);
        const v = body.linearVelocity;
        if (Math.hypot(v.x, v.y) > 0.02) {
          handleVector.x = v.x * VELOCITY_ARROW_SCALE;
          handleVector.y = v.y * VELOCITY_ARROW_SCALE;
          handleStart.x = tip.x - handleVector.x;
          handleStart.y = tip.y - handleVector.y;
          drawArrow(context, scale, handleStart, handleVector, HANDLE_ARROW);
        }
        context.beginPath();
        context.arc(tip.x, tip.y, 9 / scale, 0, Math.PI * 2);
        context.fillStyle = 'rgba(255, 255, 255, 0.25)';
        context.fill();
        context.lineWidth = 1.5 / scale;
        context.strokeStyle = HANDLE_COLOR;
        context.stroke();
      }
      // Names on the particles (a handful: more would cover the tray), each a cached bitmap.
      if (current.particles.size <= 12) {
        const ratio = canvas.viewport.devicePixelRatio;
        let k = 0;
        for (const [body, info] of current.particles) {
          stepBlend.at(body, k++, fraction, drawnAt);
          labelSprites.draw(context, info.label, drawnAt.x, drawnAt.y, scale, ratio);
        }
      }
      arrowCount.current = visible.length * 2;
    },
    [arrows],
  );

  // How many collision arrows show, for tests and tools (`data-arrows`): written a few times a
  // second, not by each frame (an attribute written in a frame is a DOM change in every frame).
  useEffect(() => {
    if (!active) return;
    const id = setInterval(() => {
      const host = hostRef.current;
      const count = String(arrowCount.current);
      if (host !== null && host.dataset['arrows'] !== count) host.dataset['arrows'] = count;
    }, ARROW_COUNT_MS);
    return () => clearInterval(id);
  }, [active]);

  const add = (point: { x: number; y: number }): void => {
    if (scene === null) return;
    if (isFull(scene)) {
      announce(t('reactions.full'), true);
      return;
    }
    const body = spawnParticle(scene, point);
    worldChanged();
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
      choose(body);
      return;
    }
    add(point);
  };

  /** The keyboard's way to add: a random free-looking spot inside the box. */
  const addAnywhere = (): void => {
    if (scene === null) return;
    add(freeSpot(scene));
  };

  const changeSettings = (change: Partial<Settings>): void => {
    const next = { ...settingsRef.current, ...change };
    settingsRef.current = next;
    setSettings(next);
    const current = sceneRef.current;
    if (current === null) return;
    if (change.elasticity !== undefined) setElasticity(current, next.elasticity);
    if (change.wallsOn !== undefined) setWallsOn(current, next.wallsOn);
    if (change.tiltOn !== undefined) setTiltOn(current, next.tiltOn);
    if (
      change.elasticity !== undefined ||
      change.wallsOn !== undefined ||
      change.tiltOn !== undefined
    )
      worldChanged();
    canvasRef.current?.invalidate();
  };

  const info = selected === null ? undefined : scene?.particles.get(selected);
  /** The tray's acceleration g sin θ and its direction, from the scene's tilt now. */
  const pushText = (): string => {
    const current = sceneRef.current;
    const push =
      current !== null && settingsRef.current.tiltOn
        ? trayAcceleration(current.tilt)
        : { x: 0, y: 0 };
    const size = Math.hypot(push.x, push.y);
    return size < 1e-6
      ? unit(0, 'm/s²')
      : `${unit(size, 'm/s²', 2)}, ${number(screenAngle(push), 0)}°`;
  };
  const viewBox =
    scene === null
      ? null
      : {
          x: -MARGIN,
          y: -MARGIN,
          width: scene.width + 2 * MARGIN,
          height: scene.height + 2 * MARGIN,
        };
  const labRows: LabRow[] =
    scene === null
      ? []
      : chosen.map((body) => ({
          label: labelOf(body),
          mass: body.mass,
          vx: body.linearVelocity.x,
          vy: body.linearVelocity.y,
          selected: body === selected,
        }));
  const recordTotal = (moment: 'before' | 'after'): string => {
    const now = recorder.record;
    return now === null ? '–' : number(totalMomentumOf(now[moment]).x, 2, 2);
  };

  return (
    <MuiTheme>
      <ScreenLayout
        id="reactions"
        active={active}
        law={t('reactions.law')}
        stage={
          <Box ref={hostRef} data-arrows="0" sx={{ flex: 1, minWidth: 0, display: 'flex' }}>
            <PhysicalCanvas
              maxPixelRatio={pixelRatio}
              ref={canvasRef}
              styleFor={styleFor}
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
              id="reactions-description"
              aria-live="polite"
              data-description="reactions"
              sx={{
                position: 'absolute',
                width: '1px',
                height: '1px',
                overflow: 'hidden',
                clip: 'rect(0 0 0 0)',
                whiteSpace: 'nowrap',
              }}
            >
              {description}
            </Box>
            <Tabs
              value={tab}
              onChange={(_event, value: PanelTab) => setTab(value)}
              // Five whole labels: they share the row where it is wide enough, and where it is
              // not (a 375x667 phone in landscape gives the panel 220 px) the row scrolls sideways
              // rather than cut "Results" and "Ergebnis" to a few letters.
              variant="scrollable"
              scrollButtons={false}
              aria-label={t('reactions.panel')}
              sx={{
                minHeight: 48,
                '& .MuiTab-root': {
                  minHeight: 48,
                  minWidth: 0,
                  flex: '1 0 auto',
                  px: 1,
                  fontSize: '0.8125rem',
                  letterSpacing: 0,
                  whiteSpace: 'nowrap',
                },
              }}
            >
              {PANEL_TABS.map((id) => (
                <Tab
                  key={id}
                  value={id}
                  label={t(TAB_LABELS[id])}
                  id={`reactions-tab-${id}`}
                  aria-controls={`reactions-tabpanel-${id}`}
                  data-tab={id}
                />
              ))}
            </Tabs>
            <Box
              role="tabpanel"
              id={`reactions-tabpanel-${tab}`}
              aria-labelledby={`reactions-tab-${tab}`}
              sx={{
                display: 'flex',
                flexDirection: 'column',
                gap: 0.5,
                minHeight: 0,
                // A phone held upright: the panel keeps its height whatever the tab, so the tray
                // does not jump; what does not fit scrolls inside it. Short phones give it less:
                // the bars, the law, the tabs and the tray's least height take about 480 px.
                height: 'clamp(88px, calc(100dvh - 480px), 196px)',
                overflowY: 'auto',
                [`@media ${SIDE_BY_SIDE}`]: { height: 'auto', overflowY: 'visible' },
              }}
            >
              {tab === 'tray' && (
                <>
                  <Box
                    sx={{ minHeight: 40, px: 0.5, display: 'flex', alignItems: 'center' }}
                    data-readout="particle-info"
                  >
                    {selected !== null && info !== undefined ? (
                      <Box
                        sx={{
                          display: 'grid',
                          gridTemplateColumns: 'repeat(4, auto)',
                          gap: 1,
                          flex: 1,
                        }}
                      >
                        <Readout
                          name="particle-mass"
                          label={`${t('reactions.mass')} ${info.label}`}
                          value={unit(selected.mass, 'kg', 3)}
                        />
                        <Readout
                          name="particle-speed"
                          label={t('reactions.speed')}
                          value={
                            <LiveText
                              active={active}
                              text={() =>
                                unit(
                                  Math.hypot(selected.linearVelocity.x, selected.linearVelocity.y),
                                  'm/s',
                                  2,
                                  2,
                                )
                              }
                            />
                          }
                        />
                        <Readout
                          name="particle-impulse"
                          label={t('reactions.impulse')}
                          value={
                            <LiveText
                              active={active}
                              text={() =>
                                info.lastImpulse === null
                                  ? t('reactions.none')
                                  : unit(info.lastImpulse, 'N·s', 3)
                              }
                            />
                          }
                        />
                        <Readout
                          name="particle-position"
                          label={t('reactions.position')}
                          value={
                            <LiveText
                              active={active}
                              text={() =>
                                `${number(selected.position.x, 2, 2)}, ${number(selected.position.y, 2, 2)} m`
                              }
                            />
                          }
                        />
                      </Box>
                    ) : (
                      <Typography variant="body2" sx={{ color: 'text.secondary' }}>
                        {t('reactions.tapToInspect')}
                      </Typography>
                    )}
                  </Box>
                  {/* The readouts keep their text's width and go below the pad when it lacks room. */}
                  <Box sx={{ display: 'flex', flexWrap: 'wrap', alignItems: 'center', gap: 1 }}>
                    <Box sx={{ display: 'flex', flexDirection: 'column', gap: 0.5 }}>
                      {/*
                        Plain buttons (src/ui), not MUI's: a button focused from the keyboard ran
                        MUI's focus ripple, an endless animation that restyled the page in every
                        frame of the tray.
                      */}
                      <UiIconButton
                        aria-label={t('reactions.add')}
                        tip={t('reactions.add')}
                        onClick={addAnywhere}
                        data-action="add"
                        color="primary"
                      >
                        <AddIcon />
                      </UiIconButton>
                      <UiIconButton
                        aria-label={t('reactions.clear')}
                        tip={t('reactions.clear')}
                        onClick={() => {
                          if (scene === null) return;
                          setSelected(null);
                          clearParticles(scene);
                          worldChanged();
                          choosePair([], scene);
                          arrows.clear();
                          rerender();
                        }}
                        data-action="clear"
                      >
                        <DeleteIcon />
                      </UiIconButton>
                    </Box>
                    <TiltPad
                      onNudge={(dx, dy) => {
                        const now = sceneRef.current?.tilt ?? { x: 0, y: 0 };
                        changeTilt({ x: clampTilt(now.x + dx), y: clampTilt(now.y + dy) });
                      }}
                      onLevel={() => changeTilt({ x: 0, y: 0 })}
                    />
                    <Box
                      sx={{
                        display: 'flex',
                        flexDirection: 'column',
                        gap: 1,
                        flex: 1,
                        minWidth: 'auto',
                      }}
                    >
                      <Readout
                        name="push"
                        label={t('reactions.trayAcceleration')}
                        value={<LiveText active={active} ms={100} text={pushText} />}
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
                        label={t('reactions.momentumCollision')}
                        value={
                          <LiveText
                            active={active}
                            text={() =>
                              recorder.record === null
                                ? '–'
                                : `${recordTotal('before')} → ${recordTotal('after')}`
                            }
                          />
                        }
                      />
                    </Box>
                  </Box>
                </>
              )}
              {tab === 'setup' && (
                <>
                  <Box sx={{ display: 'flex', gap: 1 }}>
                    <Button
                      variant="contained"
                      sx={{ minHeight: 48, flex: 1 }}
                      data-action="lab-setup"
                      onClick={() => {
                        const next = {
                          ...settingsRef.current,
                          lab: settingsRef.current.lab ?? DEFAULT_LAB,
                        };
                        setSettings(next);
                        build(next);
                      }}
                    >
                      {t('lab.twoParticles')}
                    </Button>
                    <Button
                      variant="outlined"
                      sx={{ minHeight: 48, flex: 1 }}
                      data-action="choose"
                      onClick={chooseNext}
                      disabled={scene === null || scene.particles.size === 0}
                    >
                      {t('lab.chooseNext')}
                    </Button>
                  </Box>
                  <LabSetup rows={labRows} version={version} onChange={changeLab} />
                </>
              )}
              {tab === 'results' && (
                <Live active={live} watch={() => recordKey(recorder.record)}>
                  {() => <LabResults record={recorder.record} />}
                </Live>
              )}
              {tab === 'options' && (
                <>
                  <Box sx={{ display: 'flex', flexWrap: 'wrap', columnGap: 1, px: 0.5 }}>
                    <FormControlLabel
                      control={
                        <Switch
                          checked={settings.wallsOn}
                          onChange={(event) => changeSettings({ wallsOn: event.target.checked })}
                          slotProps={{ input: { 'data-control': 'walls' } as object }}
                        />
                      }
                      label={t('reactions.walls')}
                      sx={{ minHeight: 48, mr: 0 }}
                    />
                    <FormControlLabel
                      control={
                        <Switch
                          checked={settings.tiltOn}
                          onChange={(event) => changeSettings({ tiltOn: event.target.checked })}
                          slotProps={{ input: { 'data-control': 'tilt' } as object }}
                        />
                      }
                      label={t('reactions.tiltSwitch')}
                      sx={{ minHeight: 48, mr: 0 }}
                    />
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
                  </Box>
                  <Box sx={{ px: 0.5 }}>
                    <ElasticitySlider
                      id="reactions-elasticity-label"
                      label={t('reactions.elasticity')}
                      value={settings.elasticity}
                      onChange={(next) => changeSettings({ elasticity: next })}
                    />
                  </Box>
                  <Box sx={{ display: 'flex', gap: 1, alignItems: 'center', flexWrap: 'wrap' }}>
                    <ToggleButtonGroup
                      exclusive
                      size="small"
                      value={settings.measure}
                      aria-label={t('reactions.arrowsShow')}
                      onChange={(_event, value: ArrowMeasure | null) =>
                        value !== null && changeSettings({ measure: value })
                      }
                    >
                      <ToggleButton
                        value="impulse"
                        sx={{ minHeight: 48 }}
                        data-control="measure-impulse"
                      >
                        {t('reactions.showImpulse')}
                      </ToggleButton>
                      <ToggleButton
                        value="force"
                        sx={{ minHeight: 48 }}
                        data-control="measure-force"
                      >
                        {t('reactions.showForce')}
                      </ToggleButton>
                    </ToggleButtonGroup>
                    {settings.measure === 'force' && (
                      <TextField
                        select
                        size="small"
                        label={t('reactions.contactTime')}
                        value={settings.contactTime}
                        onChange={(event) =>
                          changeSettings({ contactTime: Number(event.target.value) })
                        }
                        sx={{ minWidth: 110 }}
                        slotProps={{
                          select: {
                            SelectDisplayProps: { 'data-control': 'contact-time' } as object,
                          },
                        }}
                      >
                        {CONTACT_TIMES.map((time) => (
                          <MenuItem key={time} value={time} sx={{ minHeight: 48 }}>
                            {unit(time, 's', 3)}
                          </MenuItem>
                        ))}
                      </TextField>
                    )}
                  </Box>
                  <Typography
                    variant="caption"
                    component="p"
                    sx={{ px: 0.5, m: 0 }}
                    data-legend="arrows"
                  >
                    <Box component="span" sx={{ color: ARROW_COLORS.force, fontWeight: 700 }}>
                      →
                    </Box>
                    <Box component="span" sx={{ color: ARROW_COLORS.impulse, fontWeight: 700 }}>
                      ←
                    </Box>{' '}
                    {settings.measure === 'impulse'
                      ? t('reactions.legendImpulse')
                      : t('reactions.legendForce', {
                          time: unit(settings.contactTime, 's', 3),
                        })}{' '}
                    <Box component="span" sx={{ color: ARROW_COLORS.velocity, fontWeight: 700 }}>
                      →
                    </Box>{' '}
                    {t('reactions.legendMomentum')}{' '}
                    <Box component="span" sx={{ color: HANDLE_COLOR, fontWeight: 700 }}>
                      →●
                    </Box>{' '}
                    {t('reactions.legendVelocity')}
                  </Typography>
                </>
              )}
              {tab === 'data' && (
                <DataTools
                  rewind={rewind}
                  fileName="newton-reactions.csv"
                  live={live}
                  announce={announce}
                />
              )}
            </Box>
          </>
        }
        controls={{
          paused: sim.paused,
          slow: sim.slow,
          time: () => (sceneRef.current === null ? 0 : simulatedTime(sceneRef.current.world)),
          onTogglePlay: sim.togglePlay,
          onToggleSlow: sim.toggleSlow,
          onStep: () =>
            scene !== null && sim.step([{ world: scene.world, canvas: canvasRef.current }]),
          onReset: () => build(),
          onResetAll: () => {
            setSettings(DEFAULT_SETTINGS);
            settingsRef.current = DEFAULT_SETTINGS;
            setTab('tray');
            sim.setPaused(false);
            build(DEFAULT_SETTINGS);
          },
        }}
      />
    </MuiTheme>
  );
}
