#!/usr/bin/env node
// What hullsFromAlpha costs on a 256 × 256 sprite (bench/alpha.ts: a soft-edged blob with a hole,
// a thin handle and islands), from the sources through Vite's module runner. Timed twice: the
// first call in a fresh Node process (cold: V8 still interpreting), median of several processes;
// and warm, median of calls 31–60 in one process (V8 takes some 20 calls to optimize it).
// "outlines" is the splitting, tracing and simplification alone (src/geometry/alphaOutlines.ts);
// "hullsFromAlpha" adds building the Hull objects (validation, triangulation). Target: ≤ 10 ms.
//   node bench/alpha.mjs --runs=5
import { resolve } from 'node:path';
import { fileURLToPath } from 'node:url';
import { runnerImport } from 'vite';
import { benchArgs, median, runChild } from './coldWarm.mjs';

const args = benchArgs();

if (args.has('child')) {
  await runnerImport(resolve(import.meta.dirname, 'alpha.ts'));
} else {
  const runs = Number(args.get('runs') ?? 5);
  const script = fileURLToPath(import.meta.url);
  const child = (what, repeat) => runChild(script, what, repeat);
  console.log(`| 256 × 256 sprite | hulls | points | first in a process, ms (median of ${runs}) | warm, ms (median of calls 31–60) |`);
  console.log('|---|---|---|---|---|');
  for (const what of ['outlines', 'hullsFromAlpha']) {
    const firsts = Array.from({ length: runs }, () => child(what, 1).times[0]);
    const warm = child(what, 60);
    console.log(`| ${what} | ${warm.hulls} | ${warm.points} | ${median(firsts).toFixed(2)} | ${median(warm.times.slice(30)).toFixed(2)} |`);
  }
}
