/** The particles' names: bold, black on the particle's colour. */
const FONT_PX = 13;
const FONT = `700 ${FONT_PX}px Roboto, system-ui, sans-serif`;
/** Most sprites kept: a crowd's names, at a few pixel ratios. */
const MAX_SPRITES = 256;

interface Sprite {
  readonly image: HTMLCanvasElement;
  /** Its size in CSS px. */
  readonly width: number;
  readonly height: number;
}

/**
 * The particles' names drawn once each into a small canvas of their own, then copied onto the
 * tray each frame (`drawImage`): shaping and rasterising text anew for every name in every frame
 * cost a slow phone more than copying a few hundred pixels. A sprite is made at the canvas's
 * device pixels per CSS px, so it stays sharp; a new ratio makes new sprites.
 */
export class LabelSprites {
  private readonly sprites = new Map<string, Sprite>();
  private ratio = 0;

  /**
   * Draws `label` centred on (`x`, `y`) in world metres, on a context whose transform is world
   * metres at `scale` CSS px per metre and `ratio` device px per CSS px.
   */
  draw(
    context: CanvasRenderingContext2D,
    label: string,
    x: number,
    y: number,
    scale: number,
    ratio: number,
  ): void {
    const sprite = this.sprite(label, ratio);
    if (sprite === null) return;
    const width = sprite.width / scale;
    const height = sprite.height / scale;
    context.drawImage(sprite.image, x - width / 2, y - height / 2, width, height);
  }

  private sprite(label: string, ratio: number): Sprite | null {
    if (ratio !== this.ratio) {
      this.sprites.clear();
      this.ratio = ratio;
    }
    const cached = this.sprites.get(label);
    if (cached !== undefined) return cached;
    if (typeof document === 'undefined') return null;
    const image = document.createElement('canvas');
    const context = image.getContext('2d');
    if (context === null) return null;
    context.font = FONT;
    const width = Math.ceil(context.measureText(label).width) + 2;
    const height = Math.ceil(FONT_PX * 1.4);
    image.width = Math.ceil(width * ratio);
    image.height = Math.ceil(height * ratio);
    // Resizing the canvas reset its state: the font again, at the device pixels.
    context.scale(ratio, ratio);
    context.font = FONT;
    context.fillStyle = '#000000';
    context.textAlign = 'center';
    context.textBaseline = 'middle';
    context.fillText(label, width / 2, height / 2);
    const sprite = { image, width, height };
    if (this.sprites.size >= MAX_SPRITES) this.sprites.clear();
    this.sprites.set(label, sprite);
    return sprite;
  }
}
