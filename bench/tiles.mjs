#!/usr/bin/env node
// What turning tile grids into hulls costs on the CPU: hullsFromTiles on a few maps, and one
// TileHulls.setTile. Runs bench/tiles.ts from source through Vite's module runner. Each case is
// timed twice: the first call in a fresh Node process (the code still cold, as for the first level
// a game loads), median of several processes; and warm, median of later calls in one process.
//   node bench/tiles.mjs -- --runs=5
import { fileURLToPath } from 'node:url';
import { resolve } from 'node:path';
import { runnerImport } from 'vite';
import { benchArgs, median, runChild } from './coldWarm.mjs';

const args = benchArgs();
const runs = Number(args.get('runs') ?? 5);
const { module } = await runnerImport(resolve(import.meta.dirname, 'tiles.ts'));

if (args.has('child')) {
  // One measurement in this process: `--child=<case> --repeat=<k>` prints k times in ms.
  const bench = module.CASES[args.get('child')]();
  const repeat = Number(args.get('repeat') ?? 1);
  console.log(JSON.stringify(Array.from({ length: repeat }, () => bench.run())));
} else {
  const script = fileURLToPath(import.meta.url);
  const child = (name, repeat) => runChild(script, name, repeat);
  console.log(`| case | grid | first in a process, ms (median of ${runs}) | warm, ms (median) |`);
  console.log('|---|---|---|---|');
  for (const name of Object.keys(module.CASES)) {
    const first = median(Array.from({ length: runs }, () => child(name, 1)[0]));
    const warm = median(child(name, name.startsWith('setTile') ? 205 : 25).slice(5));
    const digits = warm < 1 ? 3 : 1;
    console.log(`| ${name} | ${module.CASES[name]().describe()} | ${first.toFixed(digits)} | ${warm.toFixed(digits)} |`);
  }
}
