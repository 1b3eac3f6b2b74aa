// The benchmark runner (built and started by bench/run.mjs): Node CPU figures on headless-gl, then
// whole-frame and fill-floor times in Chromium; prints a table and writes bench/results/latest.json.
import { mkdirSync, writeFileSync } from 'node:fs';
import { cpus } from 'node:os';
import { resolve } from 'node:path';
import { launchChromium } from '../test/browser/chromium';
import { serveDirectory } from '../test/browser/staticServer';
import { runCpu, type CpuResult } from './cpu';
import { SCENES } from './scenes';
import { summarize, type Summary } from './stats';
import type { BenchPage } from './page/main';

interface BrowserResult {
  frame: Summary;
  floor: Summary;
  /** Median frame ÷ median floor. */
  ratio: number;
  /** With --bounds: median frames with trivial shadow shading and with no hulls, ÷ median floor (see bench/page/bounds.ts). */
  bounds?: { trivialShading: number; noHulls: number };
}

interface SceneResult {
  scene: string;
  lights: number;
  hulls: number;
  node?: CpuResult;
  browser?: BrowserResult;
}

const args = new Map(process.argv.slice(2).map((arg) => arg.replace(/^--/, '').split('=') as [string, string]));
const only = args.get('scenes')?.split(',');
const scenes = SCENES.filter((scene) => !only || only.includes(scene.name));
const cpuFrames = Number(args.get('frames') ?? 100);
const browserFrames = Number(args.get('browser-frames') ?? 10);
// The browser frames' lightmap resolution scale (the renderer's `lightmapScale`), for fill-bound comparisons.
const lightmapScale = Number(args.get('lightmap-scale') ?? 1);
// Also time the frame with trivial shadow shading and with no hulls: what faster shading could win.
const withBounds = args.has('bounds');
// run.mjs starts the bundle from the repository root.
const root = process.cwd();
/** Frames run in Chromium before the measured ones. */
const BROWSER_WARMUP = 2;

const results: SceneResult[] = scenes.map((spec) => ({ scene: spec.name, lights: spec.lights, hulls: spec.hulls + spec.farHulls }));
if (!args.has('no-node')) {
  for (const [i, spec] of scenes.entries()) {
    process.stderr.write(`node ${spec.name}…\n`);
    // Few real warm-up frames: the stubbed ones that follow warm the JIT up cheaply (see runCpu).
    const node = runCpu(spec, { warmup: 5, frames: cpuFrames });
    results[i].node = node;
    process.stderr.write(`  JS ${node.js.median.toFixed(2)} ms, ${node.glCalls} GL calls, heap ${node.heapBytesPerFrame} B/frame\n`);
  }
}
if (!args.has('no-browser')) {
  const server = await serveDirectory(resolve(root, 'bench/.build/page'));
  const browser = await launchChromium();
  try {
    for (const [i, spec] of scenes.entries()) {
      process.stderr.write(`chromium ${spec.name}…\n`);
      const page = await browser.newPage();
      await page.goto(server.url, { waitUntil: 'load' });
      await page.waitForFunction('window.penumbraBench');
      // Evaluated in the page: each function must name the page's API itself.
      await page.evaluate((name, scale, bounds) => (window as unknown as { penumbraBench: BenchPage }).penumbraBench.setup(name, scale, bounds), spec.name, lightmapScale, withBounds);
      const times: { frame: number[]; floor: number[]; trivialShading: number[]; noHulls: number[] } = { frame: [], floor: [], trivialShading: [], noHulls: [] };
      for (let frame = 0; frame < BROWSER_WARMUP + browserFrames; frame++) {
        const measured = await page.evaluate(() => (window as unknown as { penumbraBench: BenchPage }).penumbraBench.frame());
        if (frame < BROWSER_WARMUP) continue;
        times.frame.push(measured.frame);
        times.floor.push(measured.floor);
        if (measured.trivialShading !== undefined) times.trivialShading.push(measured.trivialShading);
        if (measured.noHulls !== undefined) times.noHulls.push(measured.noHulls);
      }
      await page.evaluate(() => (window as unknown as { penumbraBench: BenchPage }).penumbraBench.teardown());
      await page.close();
      const frame = summarize(times.frame), floor = summarize(times.floor);
      results[i].browser = { frame, floor, ratio: frame.median / floor.median };
      if (withBounds) {
        const ofFloor = (samples: number[]) => summarize(samples).median / floor.median;
        results[i].browser.bounds = { trivialShading: ofFloor(times.trivialShading), noHulls: ofFloor(times.noHulls) };
      }
      process.stderr.write(`  frame ${frame.median.toFixed(1)} ms, floor ${floor.median.toFixed(1)} ms\n`);
    }
  } finally {
    await browser.close();
    await server.close();
  }
}

const machine = `${cpus()[0]?.model ?? 'unknown CPU'} × ${cpus().length}, Node ${process.version}, no GPU (headless-gl on Mesa, Chromium on SwiftShader)`;
printTable(results, machine);
mkdirSync(resolve(root, 'bench/results'), { recursive: true });
const file = resolve(root, 'bench/results/latest.json');
writeFileSync(file, JSON.stringify({ date: new Date().toISOString(), machine, cpuFrames, browserFrames, results }, null, 2));
console.log(`\nwritten ${file}`);

function printTable(rows: SceneResult[], machine: string): void {
  const ms = (value: number) => value.toFixed(2);
  const pair = (summary: Summary | undefined) => (summary ? `${ms(summary.median)} / ${ms(summary.p95)}` : '–');
  const table = [[
    'scene', 'lights', 'hulls', 'drawn', 'edges', 'node JS ms (med / p95)', 'in GL ms (med)', 'GL calls', 'heap B/frame',
    'chromium frame ms (med / p95)', 'floor ms (med / p95)', 'frame ÷ floor',
    ...(withBounds ? ['trivial shading ÷ floor', 'no hulls ÷ floor'] : []),
  ]];
  for (const row of rows) {
    table.push([
      row.scene, String(row.lights), String(row.hulls), String(row.node?.lightsDrawn ?? '–'), String(row.node?.edges ?? '–'),
      pair(row.node?.js), row.node ? ms(row.node.gl.median) : '–', row.node ? row.node.glCalls.toFixed(0) : '–',
      row.node?.heapBytesPerFrame == null ? '–' : row.node.heapBytesPerFrame.toFixed(0),
      pair(row.browser?.frame), pair(row.browser?.floor), row.browser ? row.browser.ratio.toFixed(2) : '–',
      ...(withBounds ? [row.browser?.bounds?.trivialShading.toFixed(2) ?? '–', row.browser?.bounds?.noHulls.toFixed(2) ?? '–'] : []),
    ]);
  }
  const widths = table[0].map((_, column) => Math.max(...table.map((line) => line[column].length)));
  console.log(`penumbra-gl benchmark — ${machine}`);
  for (const [n, line] of table.entries()) {
    console.log(line.map((cell, column) => cell.padEnd(widths[column])).join(' | '));
    if (n === 0) console.log(widths.map((width) => '-'.repeat(width)).join('-|-'));
  }
}
