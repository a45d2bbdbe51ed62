/** Debug overlays, each off by default. The attribute form is a space-separated list of names. */
export interface DebugOverlays {
  /** Contact points of touching shapes (dots). */
  contacts: boolean;
  /** Contact normals, from A to B (short lines at each contact point). */
  normals: boolean;
  /** Bounding boxes of shapes. */
  aabbs: boolean;
  /** Centres of mass (crosshairs). */
  centers: boolean;
  /** Velocity vectors of dynamic and kinematic bodies, from the centre of mass. */
  velocities: boolean;
  /** Sleeping bodies drawn dimmed. */
  sleep: boolean;
}

/** Names accepted in the `debug` attribute. */
export const DEBUG_OVERLAY_NAMES: readonly (keyof DebugOverlays)[] = [
  'contacts',
  'normals',
  'aabbs',
  'centers',
  'velocities',
  'sleep',
];

/** Every overlay off. */
export function noDebugOverlays(): DebugOverlays {
  return {
    contacts: false,
    normals: false,
    aabbs: false,
    centers: false,
    velocities: false,
    sleep: false,
  };
}
