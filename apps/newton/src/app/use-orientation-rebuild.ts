import { useEffect, type RefObject } from 'react';

/** How far (as a ratio) a world's aspect may drift from the one its host asks for. */
const ASPECT_TOLERANCE = 1.2;

/**
 * Calls `rebuild` when the host's shape turns from portrait to landscape or back (a phone
 * rotated), so a world sized to the old shape is not left letterboxed in the new one.
 *
 * With `sizeFor` (the world size a host of a given size gets), it also rebuilds when the host's
 * shape moves clearly away from the world's without turning over: a phone rotated to portrait
 * whose panel takes much of the height can leave the host still wider than tall.
 */
export function useOrientationRebuild(
  host: RefObject<HTMLElement | null>,
  scene: { width: number; height: number } | null,
  rebuild: () => void,
  sizeFor?: (width: number, height: number) => { width: number; height: number },
): void {
  useEffect(() => {
    const element = host.current;
    if (element === null || scene === null) return;
    const sceneWide = scene.width > scene.height;
    const sceneAspect = scene.width / scene.height;
    const observer = new ResizeObserver(() => {
      const { clientWidth: width, clientHeight: height } = element;
      if (width === 0 || height === 0) return; // hidden screen: wait until it shows
      if (sizeFor !== undefined) {
        // Against the size a new world would get, so a rebuilt world never asks again.
        const target = sizeFor(width, height);
        const ratio = target.width / target.height / sceneAspect;
        if (ratio > ASPECT_TOLERANCE || ratio < 1 / ASPECT_TOLERANCE) rebuild();
        return;
      }
      // A clear change of shape only: near-square hosts do not flip back and forth.
      if (sceneWide ? height > width * 1.1 : width > height * 1.1) rebuild();
    });
    observer.observe(element);
    return () => observer.disconnect();
  }, [host, scene, rebuild, sizeFor]);
}
