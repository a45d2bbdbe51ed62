// Draws the app icons (PNG, no dependencies): a light-blue body pushed by an orange force arrow
// on Material's dark surface. Run with `npm run icons -w @physical/newton`; output in public/icons.
import { writeFileSync } from 'node:fs';
import { deflateSync } from 'node:zlib';

type Rgb = readonly [number, number, number];

const BACKGROUND: Rgb = [0x12, 0x12, 0x12];
const SURFACE: Rgb = [0x1e, 0x2a, 0x33];
const BODY: Rgb = [0x4f, 0xc3, 0xf7];
const ARROW: Rgb = [0xff, 0x8a, 0x65];

const crcTable = Array.from({ length: 256 }, (_, n) => {
  let c = n;
  for (let k = 0; k < 8; k++) c = c & 1 ? 0xedb88320 ^ (c >>> 1) : c >>> 1;
  return c >>> 0;
});

function crc32(bytes: Uint8Array): number {
  let c = 0xffffffff;
  for (const byte of bytes) c = crcTable[(c ^ byte) & 0xff]! ^ (c >>> 8);
  return (c ^ 0xffffffff) >>> 0;
}

function chunk(type: string, data: Uint8Array): Buffer {
  const head = Buffer.alloc(8);
  head.writeUInt32BE(data.length, 0);
  head.write(type, 4, 'ascii');
  const crc = Buffer.alloc(4);
  crc.writeUInt32BE(crc32(Buffer.concat([head.subarray(4), data])));
  return Buffer.concat([head, data, crc]);
}

function png(size: number, pixel: (x: number, y: number) => Rgb): Buffer {
  const raw = Buffer.alloc(size * (size * 3 + 1));
  for (let y = 0; y < size; y++) {
    raw[y * (size * 3 + 1)] = 0;
    for (let x = 0; x < size; x++) {
      const [r, g, b] = pixel(x, y);
      const at = y * (size * 3 + 1) + 1 + x * 3;
      raw[at] = r;
      raw[at + 1] = g;
      raw[at + 2] = b;
    }
  }
  const header = Buffer.alloc(13);
  header.writeUInt32BE(size, 0);
  header.writeUInt32BE(size, 4);
  header[8] = 8; // bit depth
  header[9] = 2; // RGB
  return Buffer.concat([
    Buffer.from([0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a]),
    chunk('IHDR', header),
    chunk('IDAT', deflateSync(raw, { level: 9 })),
    chunk('IEND', new Uint8Array(0)),
  ]);
}

/** The colour at a point of the unit square (0..1), `inset` shrinking the drawing (maskable). */
function shade(u: number, v: number, inset: number, rounded: boolean): Rgb {
  const s = (value: number): number => (value - inset) / (1 - 2 * inset);
  const x = s(u);
  const y = s(v);
  if (rounded) {
    const r = 0.22;
    const cx = Math.min(Math.max(u, r), 1 - r);
    const cy = Math.min(Math.max(v, r), 1 - r);
    if (Math.hypot(u - cx, v - cy) > r) return BACKGROUND;
  }
  // Arrow: shaft from x 0.12 to 0.5 at y 0.5, head to 0.66.
  const inShaft = x >= 0.1 && x <= 0.48 && Math.abs(y - 0.5) <= 0.05;
  const inHead = x >= 0.44 && x <= 0.64 && Math.abs(y - 0.5) <= (0.64 - x) * 0.75;
  if (Math.hypot(x - 0.73, y - 0.5) <= 0.17) return BODY;
  if (inShaft || inHead) return ARROW;
  return rounded ? SURFACE : BACKGROUND;
}

function icon(size: number, inset: number, rounded: boolean): Buffer {
  const samples = 4;
  return png(size, (px, py) => {
    const sum = [0, 0, 0];
    for (let i = 0; i < samples; i++) {
      for (let j = 0; j < samples; j++) {
        const c = shade(
          (px + (i + 0.5) / samples) / size,
          (py + (j + 0.5) / samples) / size,
          inset,
          rounded,
        );
        sum[0]! += c[0];
        sum[1]! += c[1];
        sum[2]! += c[2];
      }
    }
    const n = samples * samples;
    return [Math.round(sum[0]! / n), Math.round(sum[1]! / n), Math.round(sum[2]! / n)];
  });
}

const out = new URL('../public/icons/', import.meta.url);
writeFileSync(new URL('icon-192.png', out), icon(192, 0, true));
writeFileSync(new URL('icon-512.png', out), icon(512, 0, true));
writeFileSync(new URL('maskable-512.png', out), icon(512, 0.1, false));
writeFileSync(new URL('apple-touch-icon.png', out), icon(180, 0, false));
