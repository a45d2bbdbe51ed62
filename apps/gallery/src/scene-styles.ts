import type { BodyStyle, StyleResolver } from '@physical/canvas';
import type { Scene } from '@physical/scenes';

/**
 * The canvas `styleFor` of a scene that colours bodies (`scene.fill`), or null. The canvas asks
 * every frame, so one style object per colour is kept and handed back.
 */
export function sceneStyleFor(scene: Scene): StyleResolver | null {
  const fill = scene.fill;
  if (fill === undefined) return null;
  const styles = new Map<string, BodyStyle>();
  return (body) => {
    const colour = fill(body);
    if (colour === null) return null;
    let style = styles.get(colour);
    if (style === undefined) {
      style = { fill: colour };
      styles.set(colour, style);
    }
    return style;
  };
}
