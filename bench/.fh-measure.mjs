import { build } from 'esbuild';
import { gzipSync } from 'node:zlib';
const root = process.cwd();
const alias = {
  '@physical/engine': root + '/packages/engine/src/index.ts',
  '@physical/canvas': root + '/packages/canvas/src/index.ts',
  '@physical/canvas/define': root + '/packages/canvas/src/define.ts',
  '@physical/worker': root + '/packages/worker/src/index.ts',
};
async function size(name, contents) {
  const r = await build({ stdin: { contents, resolveDir: root, loader: 'ts' }, bundle: true, minify: true, format: 'esm', platform: 'neutral', target: 'es2022', write: false, alias, metafile: true, logLevel: 'error' });
  const code = r.outputFiles[0].contents;
  console.log(name, (gzipSync(code, { level: 9 }).byteLength / 1024).toFixed(1), 'KB gz');
  if (process.argv[2] === name) {
    const ins = Object.entries(Object.values(r.metafile.outputs)[0].inputs).sort((a, b) => b[1].bytesInOutput - a[1].bytesInOutput);
    for (const [f, i] of ins.slice(0, 60)) console.log('  ', i.bytesInOutput, f.replace(root, ''));
  }
}
await size('engine', `import { World, box } from '@physical/engine'; const w = new World(); w.add(box({width:1,height:1})); w.step(); console.log(w);`);
await size('engine+canvas', `import { World, box } from '@physical/engine'; import '@physical/canvas/define'; const w = new World(); w.add(box({width:1,height:1})); document.querySelector('physical-canvas').world = w;`);
await size('worker-page', `import { WorkerWorld } from '@physical/worker'; import '@physical/canvas/define'; const w = new WorkerWorld(new Worker('x')); w.add({kind:'box', width:1,height:1}); document.querySelector('physical-canvas').world = w;`);
