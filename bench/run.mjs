#!/usr/bin/env node
// `npm run bench`: builds the baseline renderer from a git ref and the bench bundles with Vite
// (bench/build.mjs), then runs the bench, which measures the working tree's renderer ("new") and
// the baseline ("old") side by side in the same run, with a new ÷ old row.
//
// bench/main.ts: Node CPU figures on headless-gl (JS ms with GL stubbed, time in GL, GL calls, heap
// per frame), then whole frames and the fill floor in Chromium on SwiftShader. headless-gl runs
// under an X display (scripts/with-display.mjs: Xvfb when DISPLAY is unset), with exposed GC and a
// young generation large enough to measure per-frame allocation.
//   npm run bench -- --scenes=S1,S2 --frames=100 --browser-frames=10 --lightmap-scale=0.5 --bounds --no-node --no-browser
//
// --baseline=<ref> (default 8d3feef, the last commit before the shadow-core v2 rewrite) or --no-baseline.
import { spawnSync } from 'node:child_process';
import { resolve } from 'node:path';
import { baselineRefFromArgs, buildBaseline, buildBench } from './build.mjs';

const root = resolve(import.meta.dirname, '..');
const args = process.argv.slice(2);
// Arguments for bench/main.ts: the build's own are consumed here.
const passed = args.filter((arg) => arg !== '--no-baseline' && !arg.startsWith('--baseline='));

const ref = baselineRefFromArgs(args);
const baseline = ref ? await buildBaseline(root, ref) : null;
if (baseline) process.stderr.write(`baseline: ${baseline.ref} = ${baseline.commit}\n`);
const out = await buildBench(root, { baseline, targets: ['page', 'node'] });

const result = spawnSync('node', [
  resolve(root, 'scripts/with-display.mjs'),
  'node', '--expose-gc', '--max-semi-space-size=128', resolve(out, 'main.mjs'), ...passed,
], { stdio: 'inherit', cwd: root });
process.exit(result.status ?? 1);
