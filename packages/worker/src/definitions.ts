import {
  Body,
  PhysicalError,
  checkJointOptions,
  box,
  capsule,
  particle,
  polygon,
  regularPolygon,
  wall,
  type BodyOptions,
  type BoxOptions,
  type CapsuleOptions,
  type DistanceJointOptions,
  type MouseJointOptions,
  type ParticleOptions,
  type PolygonOptions,
  type PrismaticJointOptions,
  type RegularPolygonOptions,
  type RevoluteJointOptions,
  type WallOptions,
  type WeldJointOptions,
} from '@physical/engine';
import type { BodyId } from './ids.ts';
import { PageJoint } from './page-joint.ts';
import { plainCopy } from './plain-copy.ts';

// A body or joint crosses to the worker as its definition (the factory's name and options), and
// both sides build it with the same engine factory: the page first, so bad input throws the
// engine's own PhysicalError there, then the worker, so both worlds hold the very same body.

/** Listener options cannot cross to a worker (functions do not clone). */
export type Crossing<T> = Omit<T, 'onMove' | 'onCollision'>;

/**
 * A body for a worker world: the name of an engine factory (`kind`) and its options. `'body'` is
 * `new Body(options)`; the others are `box`, `particle`, `capsule`, `regularPolygon`, `polygon`
 * and `wall`. `userData` stays on the page (it is never posted).
 */
export type BodyDefinition<UserData = unknown> =
  | ({ readonly kind: 'body' } & Crossing<BodyOptions<UserData>>)
  | ({ readonly kind: 'box' } & Crossing<BoxOptions<UserData>>)
  | ({ readonly kind: 'particle' } & Crossing<ParticleOptions<UserData>>)
  | ({ readonly kind: 'capsule' } & Crossing<CapsuleOptions<UserData>>)
  | ({ readonly kind: 'regularPolygon' } & Crossing<RegularPolygonOptions<UserData>>)
  | ({ readonly kind: 'polygon' } & Crossing<PolygonOptions<UserData>>)
  | ({ readonly kind: 'wall' } & Crossing<WallOptions<UserData>>);

/** Replaces the joint options' bodies by ids. */
export type WithIds<T, Keys extends string> = Omit<T, Keys | 'userData'> & {
  readonly [K in Keys]: BodyId;
};

/**
 * A joint for a worker world: the name of an engine joint factory (`kind`) and its options, with
 * body ids in place of bodies.
 */
export type JointDefinition =
  | ({ readonly kind: 'revolute' } & WithIds<RevoluteJointOptions, 'bodyA' | 'bodyB'>)
  | ({ readonly kind: 'prismatic' } & WithIds<PrismaticJointOptions, 'bodyA' | 'bodyB'>)
  | ({ readonly kind: 'distance' } & WithIds<DistanceJointOptions, 'bodyA' | 'bodyB'>)
  | ({ readonly kind: 'weld' } & WithIds<WeldJointOptions, 'bodyA' | 'bodyB'>)
  | ({ readonly kind: 'mouse' } & WithIds<MouseJointOptions, 'body'>);

const BODY_KINDS = ['body', 'box', 'particle', 'capsule', 'regularPolygon', 'polygon', 'wall'];
export const JOINT_KINDS: readonly string[] = [
  'revolute',
  'prismatic',
  'distance',
  'weld',
  'mouse',
];

export function requireDefinition(
  definition: unknown,
  kinds: readonly string[],
): asserts definition is { kind: string } {
  if (definition === null || typeof definition !== 'object') {
    throw new PhysicalError(
      'definition',
      `must be an object with a kind, got ${String(definition)}.`,
    );
  }
  const kind = (definition as { kind?: unknown }).kind;
  if (typeof kind !== 'string' || !kinds.includes(kind)) {
    throw new PhysicalError('kind', `must be one of ${kinds.join(', ')}, got ${String(kind)}.`);
  }
  for (const field of ['onMove', 'onCollision']) {
    if ((definition as Record<string, unknown>)[field] !== undefined) {
      throw new PhysicalError(
        field,
        `cannot cross to a worker (functions do not clone): listen with workerWorld.on(...).`,
      );
    }
  }
}

/**
 * Builds the engine body a definition describes, with the engine's factory (throws its
 * PhysicalError on bad input). The page and the worker both call it.
 */
export function buildBody(definition: BodyDefinition): Body {
  requireDefinition(definition, BODY_KINDS);
  const { kind, ...options } = definition;
  switch (kind) {
    case 'body':
      return new Body(options as BodyOptions);
    case 'box':
      return box(options as BoxOptions);
    case 'particle':
      return particle(options as ParticleOptions);
    case 'capsule':
      return capsule(options as CapsuleOptions);
    case 'regularPolygon':
      return regularPolygon(options as RegularPolygonOptions);
    case 'polygon':
      return polygon(options as PolygonOptions);
    case 'wall':
      return wall(options as WallOptions);
  }
}

/** The page copy or worker body of a joint option's id (a PhysicalError naming `field` if none). */
export function resolve(field: string, id: BodyId, bodyOf: (id: BodyId) => Body): Body {
  return bodyOf(id) ?? missing(field, id);
}

function missing(field: string, id: unknown): never {
  throw new PhysicalError(
    field,
    `must be the id of a body in this worker world, got ${String(id)}.`,
  );
}

/**
 * Checks a body definition on the page and builds the page's copy: `posted` is the plain copy the
 * worker receives (without `userData`, which stays on the page), and the page's body is built
 * from those very values, so a definition the page accepts is one the worker accepts.
 */
export function prepareBody(definition: BodyDefinition): { posted: BodyDefinition; body: Body } {
  requireDefinition(definition, BODY_KINDS);
  const posted = plainCopy(withoutUserData(definition), '') as BodyDefinition;
  const body = buildBody(
    'userData' in definition
      ? ({ ...posted, userData: (definition as { userData?: unknown }).userData } as BodyDefinition)
      : posted,
  );
  return { posted, body };
}

/**
 * As {@link prepareBody}, for a joint between the bodies `bodyOf` resolves: checked with the
 * engine's own joint checks (the page builds no engine joint: their solver passes are the
 * worker's), and copied as a {@link PageJoint} to draw.
 */
export function prepareJoint(
  definition: JointDefinition,
  bodyOf: (id: BodyId) => Body,
): { posted: JointDefinition; joint: PageJoint } {
  requireDefinition(definition, JOINT_KINDS);
  const posted = plainCopy(withoutUserData(definition), '') as JointDefinition;
  if (posted.kind === 'mouse') {
    const { kind, body, ...rest } = posted;
    const resolved = resolve('body', body, bodyOf);
    return {
      posted,
      joint: new PageJoint(
        kind,
        resolved,
        resolved,
        checkJointOptions(kind, { ...rest, body: resolved }),
      ),
    };
  }
  const { kind, bodyA, bodyB, ...rest } = posted;
  const options = {
    ...rest,
    bodyA: resolve('bodyA', bodyA, bodyOf),
    bodyB: resolve('bodyB', bodyB, bodyOf),
  };
  return {
    posted,
    joint: new PageJoint(
      kind,
      options.bodyA,
      options.bodyB,
      checkJointOptions(kind, options as never),
    ),
  };
}

function withoutUserData(definition: object): object {
  const rest = { ...definition } as Record<string, unknown>;
  delete rest['userData'];
  return rest;
}

export function withoutKind<T extends object>(options: T): Omit<T, 'kind'> {
  const rest = { ...options } as Record<string, unknown>;
  delete rest['kind'];
  return rest as Omit<T, 'kind'>;
}
