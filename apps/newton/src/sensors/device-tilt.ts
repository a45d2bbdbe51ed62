/** How far the device leans, as a push direction on screen: x right, y down, each in [-1, 1]. */
export interface Tilt {
  readonly x: number;
  readonly y: number;
}

const clamp = (value: number): number => Math.min(1, Math.max(-1, value));

/**
 * The tilt for a device orientation (degrees, as in DeviceOrientationEvent) and the screen's
 * rotation (screen.orientation.angle): leaning the right edge down (gamma > 0) pushes right,
 * leaning the top edge up (beta > 0) pushes down the screen, as a marble would roll.
 */
export function tiltFromOrientation(beta: number, gamma: number, screenAngle = 0): Tilt {
  const dx = Math.sin((gamma * Math.PI) / 180);
  const dy = Math.sin((beta * Math.PI) / 180);
  const a = (screenAngle * Math.PI) / 180;
  const x = dx * Math.cos(a) + dy * Math.sin(a);
  const y = -dx * Math.sin(a) + dy * Math.cos(a);
  const round = (value: number): number => Math.round(clamp(value) * 1000) / 1000;
  return { x: round(x), y: round(y) };
}

interface PermissionRequester {
  requestPermission?: () => Promise<'granted' | 'denied'>;
}

/** True where the browser asks the user before it reports orientation (iOS Safari). */
export function tiltNeedsPermission(): boolean {
  return (
    typeof DeviceOrientationEvent !== 'undefined' &&
    typeof (DeviceOrientationEvent as unknown as PermissionRequester).requestPermission ===
      'function'
  );
}

/** Asks for orientation access (call from a tap); true when granted or not needed. */
export async function requestTiltPermission(): Promise<boolean> {
  if (!tiltNeedsPermission()) return true;
  try {
    const request = (DeviceOrientationEvent as unknown as PermissionRequester).requestPermission!;
    return (await request()) === 'granted';
  } catch {
    return false;
  }
}

/**
 * Calls `onTilt` with every device-orientation reading; returns the function that stops
 * listening. Readings without angles (desktops without a sensor) are ignored.
 */
export function watchDeviceTilt(onTilt: (tilt: Tilt) => void): () => void {
  if (typeof window === 'undefined') return () => undefined;
  const listener = (event: DeviceOrientationEvent): void => {
    if (event.beta === null || event.gamma === null) return;
    const angle = typeof screen !== 'undefined' ? (screen.orientation?.angle ?? 0) : 0;
    onTilt(tiltFromOrientation(event.beta, event.gamma, angle));
  };
  window.addEventListener('deviceorientation', listener);
  return () => window.removeEventListener('deviceorientation', listener);
}
