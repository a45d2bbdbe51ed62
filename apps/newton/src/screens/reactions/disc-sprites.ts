import { DYNAMIC_PALETTE, type Viewport } from '@physical/canvas';

/**
 * Most sprites kept: more than a full tray's particles (about 60), few enough to stay small
 * (at 3 device px per CSS px the largest disc's bitmap is 150 px square, 90 KB).
 */
const MAX_SPRITES = 128;

/** A disc's bitmap and half its side (device px). */
interface Sprite {
  readonly image: CanvasImageSource;
  readonly half: number;
}

/**
 * The particles' discs as small bitmaps, one per colour and size, copied onto the tray at whole
 * device pixels (`drawImage` without scaling). A phone that rasterises the canvas on its CPU fills
 * every anti-aliased disc anew in every frame: with 50 particles at 4x CPU slowdown that was 3 ms
 * of a frame's 15 (a trace of Reactions), and copying bitmaps at whole pixels cost a third of
 * filling the same discs (a page of 50 discs at 4x: 1.0-1.4 against 3.3 ms). Scaled or
 * sub-pixel copies cost as much as filling, so a disc is placed to the nearest device pixel (half
 * a pixel at most).
 *
 * Use: {@link begin} on the overlay's context (in world metres), {@link add} each disc,
 * {@link finish}. Nothing is allocated a frame once every size has its sprite.
 */
export class DiscSprites {
  /** By colour index and radius in quarter device pixels. */
  private readonly sprites = new Map<number, Sprite>();
  /** Device px per metre of the sprites kept, and of this frame. */
  private ratio = 0;
  private originX = 0;
  private originY = 0;
  private context: CanvasRenderingContext2D | null = null;

  /** Starts a frame's discs on `context`, whose transform is the canvas's world transform. */
  begin(context: CanvasRenderingContext2D, viewport: Viewport): void {
    const ratio = viewport.scale * viewport.devicePixelRatio;
    if (ratio !== this.ratio) {
      this.forget();
      this.ratio = ratio;
    }
    this.originX = viewport.originX;
    this.originY = viewport.originY;
    this.context = context;
    context.setTransform(1, 0, 0, 1, 0, 0);
  }

  /**
   * A disc of `radius` metres centred on (`x`, `y`) metres, in the colour `DYNAMIC_PALETTE[color]`
   * (the canvas's own colours for moving bodies).
   */
  add(x: number, y: number, radius: number, color: number): void {
    const sprite = this.sprite(color, radius * this.ratio);
    if (sprite === null) return;
    this.context!.drawImage(
      sprite.image,
      Math.round((x - this.originX) * this.ratio - sprite.half),
      Math.round((y - this.originY) * this.ratio - sprite.half),
    );
  }

  /** Puts the world transform back. */
  finish(): void {
    const ratio = this.ratio;
    this.context!.setTransform(ratio, 0, 0, ratio, -this.originX * ratio, -this.originY * ratio);
    this.context = null;
  }

  /** Drops every sprite, and frees the bitmaps' memory now rather than at a collection. */
  private forget(): void {
    for (const { image } of this.sprites.values()) {
      if (typeof ImageBitmap !== 'undefined' && image instanceof ImageBitmap) image.close();
    }
    this.sprites.clear();
  }

  /** The bitmap of a disc of `radius` device px in colour `color`, made the first time. */
  private sprite(color: number, radius: number): Sprite | null {
    // Quarter-pixel radii: a crowd of random sizes shares sprites, none visibly off.
    const quarters = Math.max(1, Math.round(radius * 4));
    const key = quarters * DYNAMIC_PALETTE.length + (color % DYNAMIC_PALETTE.length);
    const cached = this.sprites.get(key);
    if (cached !== undefined) return cached;
    // Even, so that the centre falls on a pixel corner as the disc's does when rounded.
    const size = 2 * Math.ceil(quarters / 4 + 1);
    const image = drawnImage(size, (context) => {
      context.fillStyle = DYNAMIC_PALETTE[color % DYNAMIC_PALETTE.length]!;
      context.beginPath();
      context.arc(size / 2, size / 2, quarters / 4, 0, 2 * Math.PI);
      context.fill();
    });
    if (image === null) return null;
    if (this.sprites.size >= MAX_SPRITES) this.forget();
    const sprite = { image, half: size / 2 };
    this.sprites.set(key, sprite);
    return sprite;
  }
}

/**
 * A `size` x `size` px image drawn by `draw`: an ImageBitmap where the browser has
 * OffscreenCanvas (copying a canvas element onto another takes a snapshot of it at every copy,
 * 40 % of the overlay's time in a profile of 50 discs), else a canvas element.
 */
function drawnImage(
  size: number,
  draw: (context: CanvasRenderingContext2D | OffscreenCanvasRenderingContext2D) => void,
): CanvasImageSource | null {
  if (typeof OffscreenCanvas !== 'undefined') {
    const canvas = new OffscreenCanvas(size, size);
    const context = canvas.getContext('2d');
    if (context === null) return null;
    draw(context);
    return canvas.transferToImageBitmap();
  }
  if (typeof document === 'undefined') return null;
  const canvas = document.createElement('canvas');
  canvas.width = size;
  canvas.height = size;
  const context = canvas.getContext('2d');
  if (context === null) return null;
  draw(context);
  return canvas;
}
