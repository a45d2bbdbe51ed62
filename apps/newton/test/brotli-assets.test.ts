import { brotliDecompressSync, gzipSync } from 'node:zlib';
import { mkdirSync, mkdtempSync, readFileSync, rmSync, writeFileSync, existsSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { afterEach, beforeEach, describe, expect, it } from 'vitest';
import { brotliFileFor, writeBrotliFiles } from '../scripts/brotli-assets.ts';

describe('the built app in Brotli (npm start)', () => {
  let root = '';
  const script = 'export const text = "Newton";\n'.repeat(200);
  beforeEach(() => {
    root = mkdtempSync(join(tmpdir(), 'newton-br-'));
    mkdirSync(join(root, 'assets'));
    writeFileSync(join(root, 'index.html'), `<!doctype html>${'<p>x</p>'.repeat(300)}`);
    writeFileSync(join(root, 'assets', 'entry.js'), script);
    writeFileSync(join(root, 'assets', 'tiny.js'), 'export {};\n');
    writeFileSync(join(root, 'assets', 'icon.png'), Buffer.alloc(4096, 7));
  });
  afterEach(() => rmSync(root, { recursive: true, force: true }));

  it('writes a .br beside each text file of at least 1 KB, decoding to the same bytes', () => {
    expect(writeBrotliFiles(root)).toBe(2);
    const decoded = brotliDecompressSync(readFileSync(join(root, 'assets', 'entry.js.br')));
    expect(decoded.toString()).toBe(script);
    expect(existsSync(join(root, 'assets', 'tiny.js.br'))).toBe(false);
    expect(existsSync(join(root, 'assets', 'icon.png.br'))).toBe(false);
    // Smaller than what vite preview sends otherwise (gzip at its default level).
    const br = readFileSync(join(root, 'assets', 'entry.js.br')).byteLength;
    expect(br).toBeLessThan(gzipSync(script).byteLength);
  });

  it('answers only a browser that accepts Brotli, for a file inside the app that has a .br', () => {
    writeBrotliFiles(root);
    const accept = 'gzip, deflate, br';
    expect(brotliFileFor(root, '/assets/entry.js', accept)).toBe(
      join(root, 'assets', 'entry.js.br'),
    );
    expect(brotliFileFor(root, '/', accept)).toBe(join(root, 'index.html.br'));
    expect(brotliFileFor(root, '/index.html?x=1', accept)).toBe(join(root, 'index.html.br'));
    expect(brotliFileFor(root, '/assets/entry.js', 'gzip, deflate')).toBeNull();
    expect(brotliFileFor(root, '/assets/tiny.js', accept)).toBeNull();
    expect(brotliFileFor(root, '/assets/icon.png', accept)).toBeNull();
    expect(brotliFileFor(root, '/../etc/passwd', accept)).toBeNull();
    // Dot segments resolve as a browser resolves them: never above the app's folder.
    expect(brotliFileFor(root, '/%2e%2e/%2e%2e/index.html', accept)).toBe(
      join(root, 'index.html.br'),
    );
    expect(brotliFileFor(root, '/%E0%A4%A', accept)).toBeNull();
  });
});
