import { measureFrontEnd } from '/work/wt/first-hour/bench/src/size.ts';
const s = await measureFrontEnd();
const base = new Map(s.engine.costs.map((c) => [c.path, c.bytes]));
console.log('CANVAS ADDS', s.engineWithCanvas.gzippedBytes - s.engine.gzippedBytes, 'lazy', s.engineWithCanvas.lazyGzippedBytes);
for (const c of s.engineWithCanvas.costs) { const d = c.bytes - (base.get(c.path) ?? 0); if (d !== 0) console.log(String(d).padStart(7), c.path); }
console.log('WORKER PAGE', s.workerPage.gzippedBytes, 'min', s.workerPage.minifiedBytes);
for (const c of s.workerPage.costs) console.log(String(c.bytes).padStart(7), c.path);
