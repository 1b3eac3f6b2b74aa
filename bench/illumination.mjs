#!/usr/bin/env node
// What `renderer.illuminationAt(x, y)` and `isLit(x, y)` cost on the CPU: 300 random points a
// frame in the benchmark's animated scenes (bench/scenes.ts: lights of range 150–350 and radius
// 5–25, small hulls; every light and one hull in ten move each frame), from the sources through
// Vite's module runner (bench/illumination.ts). Per case: the median over frames 21–80 in one
// process (V8 optimizes the code in the first frames; every case runs 20 frames before the table),
// in ms per frame and µs per query.
// "sum only" is `{ perLight: false }` with the result reused; "per light" lists the lights too;
// "scene still" leaves the scene as it is between frames (the hull grid is never rebuilt).
//   node bench/illumination.mjs [--frames=80]
import { resolve } from 'node:path';
import { runnerImport } from 'vite';
import { benchArgs, median } from './coldWarm.mjs';

const args = benchArgs();
const frames = Number(args.get('frames') ?? 80);
const { module } = await runnerImport(resolve(import.meta.dirname, 'illumination.ts'));
const perFrame = module.POINTS_PER_FRAME;

// A round of every case first, so that the first case in the table is not the one V8 learns on.
for (const name of Object.keys(module.CASES)) {
  const bench = module.CASES[name]();
  for (let i = 0; i < 20; i++) bench.frame();
}
console.log(`| case | scene | ms per frame (${perFrame} queries, median of frames 21–${frames}) | µs per query | points lit (isLit: above 0.1) |`);
console.log('|---|---|---|---|---|');
for (const name of Object.keys(module.CASES)) {
  const bench = module.CASES[name]();
  const times = Array.from({ length: frames }, () => bench.frame());
  const ms = median(times.slice(20));
  console.log(`| ${name} | ${bench.describe()} | ${ms.toFixed(3)} | ${((1000 * ms) / perFrame).toFixed(2)} | ${Math.round(100 * bench.reached())}% |`);
}
