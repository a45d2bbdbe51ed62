import {
  MAX_FORCE as FORCES_MAX_FORCE,
  MIN_FORCE as FORCES_MIN_FORCE,
  MAX_MASS,
  MIN_MASS,
} from '../screens/forces/forces-scene.ts';
import { MAX_FORCE, MIN_FORCE } from '../screens/inertia/inertia-scene.ts';
import {
  MAX_MASS as LAB_MAX_MASS,
  MAX_SPEED as LAB_MAX_SPEED,
  MIN_MASS as LAB_MIN_MASS,
} from '../screens/reactions/reactions-scene.ts';
import { SCREENS, type ScreenId } from './screens.ts';

/**
 * Preset links: a teacher's link such as `#forces?mA=1&mB=2&F=3` opens a screen in exactly that
 * setup. The part after `?` is URL query syntax; each screen takes the names listed in
 * {@link PRESET_FIELDS}, each with its range or choices. A name the screen does not know, or a
 * value outside its range, is left out and reported in `problems` (the screen keeps its default
 * there): a mistyped link still opens the screen.
 */

/** A number in [min, max], or one of some words. */
export type PresetField =
  | { readonly kind: 'number'; readonly min: number; readonly max: number }
  | { readonly kind: 'choice'; readonly choices: readonly string[] };

const number = (min: number, max: number): PresetField => ({ kind: 'number', min, max });
const choice = (...choices: string[]): PresetField => ({ kind: 'choice', choices });
const onOff = choice('0', '1');

/**
 * What each screen's link may set. Inertia: the force F (N) and its direction `angle` (degrees,
 * 0 right, 90 up), wall elasticity `e` and `surface`. Forces: the masses `mA`, `mB` (kg) and
 * the force `F` (N) on both, or `FA`, `FB` each. Reactions, the collision lab: masses `mA`, `mB`
 * (kg), velocities `vA`, `vB` (m/s, along x) and `vAy`, `vBy` (down the screen), elasticity `e`,
 * `walls` and `tilt` (1 on, 0 off), collision arrows `arrows` (impulse or force) over the
 * contact time `dt` (s).
 */
export const PRESET_FIELDS: Readonly<Record<ScreenId, Readonly<Record<string, PresetField>>>> = {
  inertia: {
    F: number(MIN_FORCE, MAX_FORCE),
    angle: number(0, 360),
    e: number(0, 1),
    surface: choice('ice', 'wood'),
  },
  forces: {
    mA: number(MIN_MASS, MAX_MASS),
    mB: number(MIN_MASS, MAX_MASS),
    F: number(FORCES_MIN_FORCE, FORCES_MAX_FORCE),
    FA: number(FORCES_MIN_FORCE, FORCES_MAX_FORCE),
    FB: number(FORCES_MIN_FORCE, FORCES_MAX_FORCE),
  },
  reactions: {
    mA: number(LAB_MIN_MASS, LAB_MAX_MASS),
    mB: number(LAB_MIN_MASS, LAB_MAX_MASS),
    vA: number(-LAB_MAX_SPEED, LAB_MAX_SPEED),
    vB: number(-LAB_MAX_SPEED, LAB_MAX_SPEED),
    vAy: number(-LAB_MAX_SPEED, LAB_MAX_SPEED),
    vBy: number(-LAB_MAX_SPEED, LAB_MAX_SPEED),
    e: number(0, 1),
    walls: onOff,
    tilt: onOff,
    arrows: choice('impulse', 'force'),
    dt: choice('0.001', '0.01', '0.1'),
  },
};

/** A parsed preset link. */
export interface Preset {
  /** The screen the link names, or null when it names none. */
  readonly screen: ScreenId | null;
  /** The accepted values: numbers for number fields, the word for choices. */
  readonly values: Readonly<Record<string, number | string>>;
  /** What was left out, and why ("mA=abc: not a number"). */
  readonly problems: readonly string[];
}

/** A plain decimal with an optional sign (point or comma); no exponents, hex or words. */
const DECIMAL = /^[-+−]?(\d+([.,]\d*)?|[.,]\d+)$/;

/** Reads a location hash such as `#reactions?mA=1&vA=2`. */
export function parsePreset(hash: string): Preset {
  const text = hash.replace(/^#/, '');
  const mark = text.indexOf('?');
  const id = mark < 0 ? text : text.slice(0, mark);
  const screen = SCREENS.find((item) => item.id === id)?.id ?? null;
  const values: Record<string, number | string> = {};
  const problems: string[] = [];
  if (screen === null || mark < 0) return { screen, values, problems };
  const fields = PRESET_FIELDS[screen];
  for (const [name, raw] of new URLSearchParams(text.slice(mark + 1))) {
    const field = Object.hasOwn(fields, name) ? fields[name] : undefined;
    if (field === undefined) {
      problems.push(`${name}: not a setting of ${screen}`);
      continue;
    }
    const value = raw.trim();
    if (field.kind === 'choice') {
      if (field.choices.includes(value)) values[name] = value;
      else problems.push(`${name}=${raw}: one of ${field.choices.join(', ')}`);
      continue;
    }
    if (!DECIMAL.test(value)) {
      problems.push(`${name}=${raw}: not a number`);
      continue;
    }
    const parsed = Number(value.replace(',', '.').replace('−', '-'));
    if (parsed < field.min || parsed > field.max) {
      problems.push(`${name}=${raw}: outside ${field.min} to ${field.max}`);
      continue;
    }
    values[name] = parsed;
  }
  return { screen, values, problems };
}

/** The preset of the page's address for `screen` (empty when the link names another screen). */
export function presetFor(screen: ScreenId, hash: string = location.hash): Preset['values'] {
  const preset = parsePreset(hash);
  return preset.screen === screen ? preset.values : {};
}

/** A number of a preset, or `fallback` when the link did not set it. */
export function presetNumber(values: Preset['values'], name: string, fallback: number): number {
  const value = values[name];
  return typeof value === 'number' ? value : fallback;
}

/** The link that opens `screen` with `values` (the inverse of {@link parsePreset}). */
export function presetLink(
  screen: ScreenId,
  values: Readonly<Record<string, number | string>>,
): string {
  const query = new URLSearchParams();
  for (const [name, value] of Object.entries(values)) query.set(name, String(value));
  const text = query.toString();
  return text === '' ? `#${screen}` : `#${screen}?${text}`;
}

/**
 * What a Forces link sets for squares A and B: each mass (kg) and force (N), undefined where the
 * link leaves the default (`F` sets both forces, `FA` and `FB` one each).
 */
export function forcesPreset(values: Preset['values']): {
  readonly masses: readonly [number | undefined, number | undefined];
  readonly forces: readonly [number | undefined, number | undefined];
} {
  const read = (name: string): number | undefined =>
    typeof values[name] === 'number' ? values[name] : undefined;
  const both = read('F');
  return {
    masses: [read('mA'), read('mB')],
    forces: [read('FA') ?? both, read('FB') ?? both],
  };
}
