#!/usr/bin/env node
// What hullsFromAlpha costs (bench/alpha.ts: a 256 × 256 soft-edged blob with a hole, a thin
// handle and islands; a grass strip, a comb and a fence whose outlines zigzag), from the sources
// through Vite's module runner. Timed twice: the first call in a fresh Node process (cold: V8
// still interpreting), median of several processes; and warm, the median of later calls in one
// process (V8 takes some 20 calls to optimize it on the small sprite, a few on the large ones).
// "outlines" is the splitting, tracing and simplification alone (src/geometry/alphaOutlines.ts);
// the other cases add building the Hull objects (validation, triangulation).
// Targets: ≤ 10 ms for the 256 × 256 sprite, ≤ 200 ms warm for the comb-like sprites.
//   node bench/alpha.mjs --runs=5 [--case=comb]
import { resolve } from 'node:path';
import { fileURLToPath } from 'node:url';
import { runnerImport } from 'vite';
import { benchArgs, median, runChild } from './coldWarm.mjs';

const args = benchArgs();

if (args.has('child')) {
  await runnerImport(resolve(import.meta.dirname, 'alpha.ts'));
} else {
  const runs = Number(args.get('runs') ?? 5);
  const { module } = await runnerImport(resolve(import.meta.dirname, 'alpha.ts'));
  const script = fileURLToPath(import.meta.url);
  const child = (what, repeat) => runChild(script, what, repeat);
  // Warm: calls 31–60 of the small sprite; calls 6–15 of the large ones (each takes far longer).
  const warmCalls = (name) => (name === 'outlines' || name === 'hullsFromAlpha' ? [60, 30] : [15, 5]);
  const names = args.has('case') ? [args.get('case')] : Object.keys(module.CASES);
  console.log(`| case | hulls | points | first in a process, ms (median of ${runs}) | warm, ms (median of later calls) |`);
  console.log('|---|---|---|---|---|');
  for (const name of names) {
    const firsts = Array.from({ length: runs }, () => child(name, 1).times[0]);
    const [calls, skipped] = warmCalls(name);
    const warm = child(name, calls);
    console.log(`| ${module.CASES[name].describe} | ${warm.hulls} | ${warm.points} | ${median(firsts).toFixed(2)} | ${median(warm.times.slice(skipped)).toFixed(2)} |`);
  }
}
