import type { Body } from '@physical/engine';
import {
  defaultBodyStyle,
  resolveBodyStyle,
  type BodyStyle,
  type ResolvedBodyStyle,
} from '../draw/body-style.ts';

/** A function giving the style of a body, or null/undefined for the default. */
export type StyleResolver = (body: Body) => BodyStyle | null | undefined;

interface CacheEntry {
  source: BodyStyle | null | undefined;
  resolved: ResolvedBodyStyle;
}

/**
 * The element's styles per body, outside the engine: an explicit style set with `setStyle`
 * wins over the `styleFor` callback, which wins over the default of the body's type.
 *
 * Resolved styles are cached per body while the source object stays the same, and interned by
 * value (bodies that look alike share one resolved style), so the renderer can batch them.
 */
export class BodyStyles {
  /** Called for every body without an explicit style, every frame: return shared objects. */
  styleFor: StyleResolver | null = null;
  private readonly explicit = new WeakMap<Body, BodyStyle>();
  private cache = new WeakMap<Body, CacheEntry>();
  private readonly serials = new WeakMap<Body, number>();
  private readonly interned = new Map<string, ResolvedBodyStyle>();
  private nextSerial = 0;

  /** Sets (or with null, clears) the explicit style of a body. */
  set(body: Body, style: BodyStyle | null): void {
    if (style === null) this.explicit.delete(body);
    else this.explicit.set(body, style);
  }

  /** The explicit style of a body, if any. */
  get(body: Body): BodyStyle | undefined {
    return this.explicit.get(body);
  }

  /** Forgets every cached resolution (after `styleFor` changes). */
  invalidate(): void {
    this.cache = new WeakMap();
  }

  /** The style to draw a body with. */
  resolve(body: Body): ResolvedBodyStyle {
    const source = this.explicit.get(body) ?? this.styleFor?.(body);
    const cached = this.cache.get(body);
    if (cached !== undefined && cached.source === source) return cached.resolved;
    let serial = this.serials.get(body);
    if (serial === undefined) {
      serial = this.nextSerial++;
      this.serials.set(body, serial);
    }
    const resolved = this.intern(resolveBodyStyle(source, defaultBodyStyle(body, serial)));
    if (cached === undefined) this.cache.set(body, { source, resolved });
    else {
      cached.source = source;
      cached.resolved = resolved;
    }
    return resolved;
  }

  private intern(style: ResolvedBodyStyle): ResolvedBodyStyle {
    if (style.label !== null || style.draw !== null) return style;
    const key = `${style.fill}|${style.stroke}|${style.opacity}|${style.lineWidth}|${style.zIndex}|${style.visible}`;
    const existing = this.interned.get(key);
    if (existing !== undefined) return existing;
    if (this.interned.size < 1024) this.interned.set(key, style);
    return style;
  }
}
