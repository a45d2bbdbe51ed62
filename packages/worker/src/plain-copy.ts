import { PhysicalError } from '@physical/engine';

// What crosses to the worker is a plain copy made on the page before anything is checked or
// changed: the page builds its copy of a body from the very values the worker receives. A
// structured clone keeps only own data properties, so a `Vec2Like` whose `x` and `y` are class
// getters would arrive as `{}` and the worker would refuse what the page accepted; functions and
// symbols do not clone at all (a DataCloneError after the page had already changed its copy).

/** Deepest nesting copied; deeper is refused (a cycle, or not a definition). */
const MAX_DEPTH = 32;

/**
 * A copy of `value` that a structured clone carries unchanged: primitives as they are, arrays and
 * objects rebuilt from their (own or inherited getter) properties, read once. Throws a
 * PhysicalError naming the path of a value that cannot cross (a function, a symbol, a cycle);
 * `field` is the path of `value` itself ('' for a definition, whose keys are then the options).
 */
export function plainCopy(value: unknown, field: string): unknown {
  return copy(value, field, 0);
}

/** A `Vec2Like` read once into `{ x, y }`; anything else as it is (for the engine to refuse). */
export function plainVector(value: unknown): unknown {
  if (value === null || typeof value !== 'object') return value;
  const v = value as { x?: unknown; y?: unknown };
  return { x: v.x, y: v.y };
}

function copy(value: unknown, field: string, depth: number): unknown {
  switch (typeof value) {
    case 'function':
      throw new PhysicalError(field, 'cannot cross to a worker (functions do not clone).');
    case 'symbol':
      throw new PhysicalError(field, 'cannot cross to a worker (symbols do not clone).');
    case 'object':
      break;
    default:
      return value;
  }
  if (value === null) return null;
  if (depth >= MAX_DEPTH) {
    throw new PhysicalError(field, `is nested more than ${MAX_DEPTH} deep (a cycle?).`);
  }
  if (Array.isArray(value)) {
    // Holes become undefined, which the engine reads the same way.
    const out: unknown[] = [];
    for (let i = 0; i < value.length; i++) out.push(copy(value[i], `${field}[${i}]`, depth + 1));
    return out;
  }
  if (ArrayBuffer.isView(value) || value instanceof ArrayBuffer) {
    throw new PhysicalError(field, 'must be a plain object or array, not binary data.');
  }
  const out: Record<string, unknown> = {};
  for (const key of propertyNames(value)) {
    // A key named __proto__ would set the copy's prototype; no option has that name.
    if (key === '__proto__') continue;
    const path = field === '' ? key : `${field}.${key}`;
    out[key] = copy((value as Record<string, unknown>)[key], path, depth + 1);
  }
  return out;
}

/** Own enumerable keys, plus the getters of a class instance's prototypes (a `Vec2` class). */
function propertyNames(value: object): string[] {
  const names = Object.keys(value);
  for (
    let proto = Object.getPrototypeOf(value) as object | null;
    proto !== null && proto !== Object.prototype;
    proto = Object.getPrototypeOf(proto) as object | null
  ) {
    for (const [key, descriptor] of Object.entries(Object.getOwnPropertyDescriptors(proto))) {
      if (descriptor.get !== undefined && !names.includes(key)) names.push(key);
    }
  }
  return names;
}
