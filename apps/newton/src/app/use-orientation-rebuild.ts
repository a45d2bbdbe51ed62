import { useEffect, type RefObject } from 'react';

/**
 * Calls `rebuild` when the host's shape turns from portrait to landscape or back (a phone
 * rotated), so a world sized to the old shape is not left letterboxed in the new one.
 */
export function useOrientationRebuild(
  host: RefObject<HTMLElement | null>,
  scene: { width: number; height: number } | null,
  rebuild: () => void,
): void {
  useEffect(() => {
    const element = host.current;
    if (element === null || scene === null) return;
    const sceneWide = scene.width > scene.height;
    const observer = new ResizeObserver(() => {
      const { clientWidth: width, clientHeight: height } = element;
      if (width === 0 || height === 0) return; // hidden screen: wait until it shows
      // A clear change of shape only: near-square hosts do not flip back and forth.
      if (sceneWide ? height > width * 1.1 : width > height * 1.1) rebuild();
    });
    observer.observe(element);
    return () => observer.disconnect();
  }, [host, scene, rebuild]);
}
