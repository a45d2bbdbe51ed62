import { build } from 'esbuild';
import { gzipSync } from 'node:zlib';
const root = process.cwd();
const alias = { '@physical/engine': root + '/packages/engine/src/index.ts', '@physical/canvas': root + '/packages/canvas/src/index.ts', '@physical/canvas/define': root + '/packages/canvas/src/define.ts', '@physical/worker': root + '/packages/worker/src/index.ts' };
async function b(contents) {
  const r = await build({ stdin: { contents, resolveDir: root, loader: 'ts' }, bundle: true, minify: true, format: 'esm', platform: 'neutral', target: 'es2022', write: false, alias, metafile: true, logLevel: 'error' });
  return { gz: gzipSync(r.outputFiles[0].contents, { level: 9 }).byteLength, inputs: Object.values(r.metafile.outputs)[0].inputs };
}
const e = await b(`import { World, box } from '@physical/engine'; const w = new World(); w.add(box({width:1,height:1})); w.step(); console.log(w);`);
const c = await b(`import { World, box } from '@physical/engine'; import '@physical/canvas/define'; const w = new World(); w.add(box({width:1,height:1})); document.querySelector('physical-canvas').world = w;`);
console.log('engine', e.gz, 'canvas', c.gz, 'diff', c.gz - e.gz);
const rows = Object.entries(c.inputs).map(([f, i]) => [f.replace(root, ''), i.bytesInOutput - (e.inputs[f]?.bytesInOutput ?? 0)]).filter(([, d]) => d !== 0).sort((a, b) => b[1] - a[1]);
let tot = 0; for (const [f, d] of rows) { tot += d; console.log(String(d).padStart(7), f); }
console.log('total raw added', tot);
