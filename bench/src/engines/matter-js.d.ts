// The part of matter-js 0.20's API the bench uses (the package ships no types; @types/matter-js is
// not installed). Checked against node_modules/matter-js/build/matter.js.
declare module 'matter-js' {
  interface Vector {
    x: number;
    y: number;
  }
  interface BodyOptions {
    isStatic?: boolean;
    angle?: number;
    density?: number;
    friction?: number;
    restitution?: number;
    frictionAir?: number;
    parts?: MatterBody[];
  }
  interface MatterBody {
    position: Vector;
    angle: number;
    parts: MatterBody[];
    isStatic: boolean;
  }
  interface MatterEngine {
    world: object;
    gravity: { x: number; y: number; scale: number };
    enableSleeping: boolean;
    positionIterations: number;
    velocityIterations: number;
    constraintIterations: number;
  }
  const Matter: {
    Engine: {
      create(options?: object): MatterEngine;
      update(engine: MatterEngine, delta?: number): void;
    };
    Bodies: {
      rectangle(x: number, y: number, w: number, h: number, options?: BodyOptions): MatterBody;
      circle(x: number, y: number, radius: number, options?: BodyOptions): MatterBody;
      fromVertices(x: number, y: number, sets: Vector[][], options?: BodyOptions): MatterBody;
    };
    Body: {
      create(options: BodyOptions): MatterBody;
      setPosition(body: MatterBody, position: Vector, updateVelocity?: boolean): void;
      setAngle(body: MatterBody, angle: number, updateVelocity?: boolean): void;
      setVelocity(body: MatterBody, velocity: Vector): void;
      setAngularVelocity(body: MatterBody, velocity: number): void;
    };
    Composite: { add(composite: object, bodies: MatterBody | MatterBody[]): void };
    Sleeping: { set(body: MatterBody, asleep: boolean): void };
  };
  export default Matter;
  export type { MatterBody, MatterEngine, Vector, BodyOptions };
}
