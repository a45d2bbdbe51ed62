// Rewrites packages/scenes/baselines.json from the current engine and prints which samples changed.
// Usage: npm run baselines:update
import { existsSync, readFileSync, writeFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { type Baseline, measureBaselines } from '../src/baselines.ts';

const file = fileURLToPath(new URL('../baselines.json', import.meta.url));
const old: Record<string, Baseline> = existsSync(file)
  ? (JSON.parse(readFileSync(file, 'utf8')) as Record<string, Baseline>)
  : {};
const next = measureBaselines();
const lines: string[] = [];
for (const [id, baseline] of Object.entries(next)) {
  const before = old[id];
  if (before === undefined) lines.push(`  new      ${id}: ${baseline.hash}`);
  else if (before.hash !== baseline.hash || before.steps !== baseline.steps) {
    lines.push(`  changed  ${id}: ${before.hash} -> ${baseline.hash}`);
  }
}
for (const id of Object.keys(old)) if (!(id in next)) lines.push(`  removed  ${id}`);
writeFileSync(file, `${JSON.stringify(next, null, 2)}\n`);
process.stdout.write(
  lines.length === 0
    ? `baselines: no sample changed (${Object.keys(next).length} samples)\n`
    : `baselines: ${lines.length} change(s) written to packages/scenes/baselines.json\n${lines.join('\n')}\n`,
);
