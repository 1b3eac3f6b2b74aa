#!/usr/bin/env node
// What hullsFromAlpha costs on a 256 × 256 sprite (bench/alpha.ts: a soft-edged blob with a hole,
// a thin handle and islands), from the sources through Vite's module runner. Timed twice: the
// first call in a fresh Node process (cold: V8 still interpreting), median of several processes;
// and warm, median of calls 31–60 in one process (V8 takes some 20 calls to optimize it).
// "outlines" is the splitting, tracing and simplification alone (src/geometry/alphaOutlines.ts);
// "hullsFromAlpha" adds building the Hull objects (validation, triangulation). Target: ≤ 10 ms.
//   node bench/alpha.mjs --runs=5
import { spawnSync } from 'node:child_process';
import { resolve } from 'node:path';
import { fileURLToPath } from 'node:url';
import { runnerImport } from 'vite';

const args = new Map(process.argv.slice(2).map((arg) => arg.replace(/^--/, '').split('=')));
const median = (values) => values.sort((a, b) => a - b)[values.length >> 1];

if (args.has('child')) {
  await runnerImport(resolve(import.meta.dirname, 'alpha.ts'));
} else {
  const runs = Number(args.get('runs') ?? 5);
  const script = fileURLToPath(import.meta.url);
  const child = (what, repeat) => {
    const run = spawnSync(process.execPath, [script, `--child=${what}`, `--repeat=${repeat}`], { encoding: 'utf8' });
    if (run.status !== 0) throw new Error(run.stderr);
    return JSON.parse(run.stdout.trim().split('\n').pop());
  };
  console.log(`| 256 × 256 sprite | hulls | points | first in a process, ms (median of ${runs}) | warm, ms (median of calls 31–60) |`);
  console.log('|---|---|---|---|---|');
  for (const what of ['outlines', 'hullsFromAlpha']) {
    const firsts = Array.from({ length: runs }, () => child(what, 1).times[0]);
    const warm = child(what, 60);
    console.log(`| ${what} | ${warm.hulls} | ${warm.points} | ${median(firsts).toFixed(2)} | ${median(warm.times.slice(30)).toFixed(2)} |`);
  }
}
