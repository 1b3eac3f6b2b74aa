// The benchmark runner (built and started by bench/run.mjs): Node CPU figures on headless-gl, then
// whole-frame and fill-floor times in Chromium, each for the working tree's renderer ("new") and the
// baseline built from a git ref ("old", bench/build.mjs) in the same run; prints a table with a
// new ÷ old row per scene (and for each normal-mapped scene a row comparing it with the same scene
// without normals, timed in turns with it) and writes bench/results/latest.json. Normal-mapped
// scenes run in Chromium only (headless-gl cannot draw into several attachments).
import { library as baselineLibrary, baseline } from 'virtual:penumbra-baseline';
import { mkdirSync, writeFileSync } from 'node:fs';
import { cpus } from 'node:os';
import { resolve } from 'node:path';
import { launchChromium } from '../test/browser/chromium';
import { serveDirectory } from '../test/browser/staticServer';
import { runCpu, type CpuResult } from './cpu';
import { EXTRA_STATS, extraStatCells, type ExtraStats } from './extraStats';
import { CURRENT } from './library';
import { runsOn, runsOnHeadlessGl, SCENES } from './scenes';
import { summarize, type Summary } from './stats';
import { printTable, ratioCell } from './table';
import type { BenchPage } from './page/main';
import { fitMicro, MICRO_CONFIGURATIONS, type MicroResult, type MicroRow } from './page/micro';

/** One frame of S3 or S4 with the exact core takes minutes on SwiftShader: an hour before a page call gives up. */
const PAGE_CALL_TIMEOUT_MS = 60 * 60 * 1000;

/** One renderer's Chromium figures for a scene. */
interface BrowserSide {
  frame: Summary;
  /** Median frame ÷ median floor. */
  ratio: number;
}

interface BrowserResult {
  floor: Summary;
  /** In a normal-mapped scene: the working tree renderer's frames on the same scene without normals, timed in turns with its own. */
  withoutNormals?: Summary;
  /** Median over the frames of frame ÷ the frame without normals timed in the same turn (robust to the load drifting between turns). */
  normalsRatio?: number;
  current: BrowserSide;
  baseline?: BrowserSide;
  /** With --bounds: median frames with trivial shadow shading (null: no such stages) and with no hulls, ÷ median floor (see bench/page/bounds.ts). */
  bounds?: { trivialShading: number | null; noHulls: number };
  /** The working tree renderer's optional figures after the last frame (bench/extraStats.ts). */
  extra: ExtraStats;
}

interface SceneResult {
  scene: string;
  lights: number;
  hulls: number;
  node?: { current: CpuResult; baseline?: CpuResult };
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
const oldName = baseline ? `old ${baseline.ref}` : 'old';
/** What a normal-mapped scene may cost against the same scene without normals (issue 17). */
const NORMALS_TARGET = 1.3;

const results: SceneResult[] = scenes.map((spec) => ({ scene: spec.name, lights: spec.lights, hulls: spec.hulls + spec.farHulls }));
if (!args.has('no-node')) {
  for (const [i, spec] of scenes.entries()) {
    if (!runsOnHeadlessGl(spec)) {
      process.stderr.write(`node ${spec.name}: skipped (normals need several colour attachments, which headless-gl cannot draw into)\n`);
      continue;
    }
    const contenders = [['new', CURRENT], ...(baselineLibrary && runsOn(spec, baselineLibrary) ? [[oldName, baselineLibrary] as const] : [])] as const;
    process.stderr.write(`node ${spec.name}: ${contenders.map(([name]) => name).join(', ')}, frames in turns…\n`);
    // Few real warm-up frames: the stubbed ones that follow warm the JIT up cheaply (see runCpu).
    const measured = runCpu(spec, contenders.map(([, library]) => library), { warmup: 5, frames: cpuFrames });
    measured.forEach((node, k) => {
      process.stderr.write(`  ${contenders[k][0]}: JS ${node.js.median.toFixed(2)} ms, ${node.glCalls} GL calls, heap ${node.heapBytesPerFrame} B/frame\n`);
    });
    results[i].node = { current: measured[0], baseline: measured[1] };
  }
}
if (!args.has('no-browser')) {
  const server = await serveDirectory(resolve(root, 'bench/.build/page'));
  const browser = await launchChromium(PAGE_CALL_TIMEOUT_MS);
  type Window = { penumbraBench: BenchPage };
  try {
    for (const [i, spec] of scenes.entries()) {
      process.stderr.write(`chromium ${spec.name}…\n`);
      const page = await browser.newPage();
      await page.goto(server.url, { waitUntil: 'load' });
      await page.waitForFunction('window.penumbraBench');
      // Evaluated in the page: each function must name the page's API itself.
      await page.evaluate((name, scale, bounds) => (window as unknown as Window).penumbraBench.setup(name, scale, bounds), spec.name, lightmapScale, withBounds);
      const normalsRatios: number[] = [];
      const times = { frame: [] as number[], baseline: [] as number[], withoutNormals: [] as number[], floor: [] as number[], trivialShading: [] as number[], noHulls: [] as number[] };
      for (let frame = 0; frame < BROWSER_WARMUP + browserFrames; frame++) {
        const measured = await page.evaluate(() => (window as unknown as Window).penumbraBench.frame());
        if (frame < BROWSER_WARMUP) continue;
        times.frame.push(measured.frame);
        times.floor.push(measured.floor);
        if (measured.baseline !== undefined) times.baseline.push(measured.baseline);
        if (measured.withoutNormals !== undefined) {
          times.withoutNormals.push(measured.withoutNormals);
          normalsRatios.push(measured.frame / measured.withoutNormals);
        }
        if (measured.trivialShading !== undefined) times.trivialShading.push(measured.trivialShading);
        if (measured.noHulls !== undefined) times.noHulls.push(measured.noHulls);
      }
      const extra = await page.evaluate(() => (window as unknown as Window).penumbraBench.extraStats());
      await page.evaluate(() => (window as unknown as Window).penumbraBench.teardown());
      await page.close();
      const floor = summarize(times.floor);
      const side = (samples: number[]): BrowserSide => {
        const frame = summarize(samples);
        return { frame, ratio: frame.median / floor.median };
      };
      const result: BrowserResult = { floor, current: side(times.frame), extra };
      if (times.baseline.length > 0) result.baseline = side(times.baseline);
      if (times.withoutNormals.length > 0) {
        result.withoutNormals = summarize(times.withoutNormals);
        result.normalsRatio = summarize(normalsRatios).median;
      }
      if (withBounds) {
        const ofFloor = (samples: number[]) => summarize(samples).median / floor.median;
        result.bounds = { trivialShading: times.trivialShading.length > 0 ? ofFloor(times.trivialShading) : null, noHulls: ofFloor(times.noHulls) };
      }
      results[i].browser = result;
      const oldFrame = (result.baseline ? `, ${oldName} ${result.baseline.frame.median.toFixed(1)} ms` : '')
        + (result.withoutNormals ? `, without normals ${result.withoutNormals.median.toFixed(1)} ms` : '');
      process.stderr.write(`  frame ${result.current.frame.median.toFixed(1)} ms${oldFrame}, floor ${floor.median.toFixed(1)} ms\n`);
    }
  } finally {
    await browser.close();
    await server.close();
  }
}

if (args.has('micro')) {
  const server = await serveDirectory(resolve(root, 'bench/.build/page'));
  const browser = await launchChromium(PAGE_CALL_TIMEOUT_MS);
  try {
    process.stderr.write('chromium micro-benchmark…\n');
    const page = await browser.newPage();
    await page.goto(server.url, { waitUntil: 'load' });
    await page.waitForFunction('window.penumbraBench');
    const rows: MicroRow[] = [];
    for (let index = 0; index < MICRO_CONFIGURATIONS.length; index++) {
      rows.push(await page.evaluate((i, frames) => (window as unknown as { penumbraBench: BenchPage }).penumbraBench.micro(i, frames), index, browserFrames));
      process.stderr.write(`  ${rows[index].name}: ${rows[index].frame.toFixed(1)} ms\n`);
    }
    await page.close();
    printMicro(fitMicro(rows));
  } finally {
    await browser.close();
    await server.close();
  }
}

const machine = `${cpus()[0]?.model ?? 'unknown CPU'} × ${cpus().length}, Node ${process.version}, no GPU (headless-gl on Mesa, Chromium on SwiftShader)`;
report(results, machine);
mkdirSync(resolve(root, 'bench/results'), { recursive: true });
const file = resolve(root, 'bench/results/latest.json');
writeFileSync(file, JSON.stringify({ date: new Date().toISOString(), machine, baseline, cpuFrames, browserFrames, lightmapScale, results }, null, 2));
console.log(`\nwritten ${file}`);

function report(rows: SceneResult[], machine: string): void {
  const ms = (value: number) => value.toFixed(2);
  const pair = (summary: Summary | undefined) => (summary ? `${ms(summary.median)} / ${ms(summary.p95)}` : '–');
  const table: string[][] = [[
    'scene', 'renderer', 'lights', 'hulls', 'drawn', 'edges', 'node JS ms (med / p95)', 'in GL ms (med)', 'GL calls', 'heap B/frame',
    'chromium frame ms (med / p95)', 'floor ms (med / p95)', 'frame ÷ floor',
    ...(withBounds ? ['trivial shading ÷ floor', 'no hulls ÷ floor'] : []),
    ...EXTRA_STATS.map(({ label }) => label),
  ]];
  const bounds = (row: SceneResult) => (withBounds ? [row.browser?.bounds?.trivialShading?.toFixed(2) ?? '–', row.browser?.bounds?.noHulls.toFixed(2) ?? '–'] : []);
  const blankBounds = withBounds ? ['', ''] : [];
  const verdicts: string[] = [];
  const normalsVerdicts: string[] = [];
  for (const row of rows) {
    const node = row.node?.current, oldNode = row.node?.baseline;
    const browser = row.browser?.current, oldBrowser = row.browser?.baseline;
    const nodeCells = (result: CpuResult | undefined) => [
      String(result?.lightsDrawn ?? '–'), String(result?.edges ?? '–'),
      pair(result?.js), result ? ms(result.gl.median) : '–', result ? result.glCalls.toFixed(0) : '–',
      result?.heapBytesPerFrame == null ? '–' : result.heapBytesPerFrame.toFixed(0),
    ];
    // Chromium's figures (full resolution) over Node's (an eighth of it) where both have them.
    const extra: ExtraStats = { ...row.node?.current.extra, ...row.browser?.extra };
    table.push([
      row.scene, 'new', String(row.lights), String(row.hulls), ...nodeCells(node),
      pair(browser?.frame), pair(row.browser?.floor), browser ? browser.ratio.toFixed(2) : '–', ...bounds(row),
      ...extraStatCells(extra),
    ]);
    const plain = row.browser?.withoutNormals;
    if (plain && browser) {
      // The same scene without normals, timed in turns with this one: what lighting through normals costs on top.
      const plainName = SCENES.find((spec) => spec.name === row.scene)?.normalsOf ?? '';
      table.push([row.scene, `${plainName} (no normals)`, String(row.lights), String(row.hulls), '–', '–', '–', '–', '–', '–',
        pair(plain), pair(row.browser?.floor), ratioCell(plain.median, row.browser?.floor.median), ...blankBounds, ...EXTRA_STATS.map(() => '')]);
      table.push([
        row.scene, `normals ÷ none`, '', '', '', '', '', '', '', '',
        ratioCell(browser.frame.median, plain.median), '', '', ...blankBounds,
        ...EXTRA_STATS.map(() => ''),
      ]);
      normalsVerdicts.push(`${row.scene} ${row.browser?.normalsRatio?.toFixed(2)} (ratio of medians ${ratioCell(browser.frame.median, plain.median)})`);
    }
    if (!baselineLibrary) continue;
    table.push([
      row.scene, oldName, String(row.lights), String(row.hulls), ...nodeCells(oldNode),
      pair(oldBrowser?.frame), pair(row.browser?.floor), oldBrowser ? oldBrowser.ratio.toFixed(2) : '–', ...blankBounds,
      ...EXTRA_STATS.map(() => ''),
    ]);
    table.push([
      row.scene, 'new ÷ old', '', '', ratioCell(node?.lightsDrawn, oldNode?.lightsDrawn), ratioCell(node?.edges, oldNode?.edges),
      ratioCell(node?.js.median, oldNode?.js.median), ratioCell(node?.gl.median, oldNode?.gl.median),
      ratioCell(node?.glCalls, oldNode?.glCalls), ratioCell(node?.heapBytesPerFrame, oldNode?.heapBytesPerFrame),
      ratioCell(browser?.frame.median, oldBrowser?.frame.median), '', ratioCell(browser?.ratio, oldBrowser?.ratio), ...blankBounds,
      ...EXTRA_STATS.map(() => ''),
    ]);
    if (browser && oldBrowser) verdicts.push(`${row.scene} ${(browser.frame.median / oldBrowser.frame.median).toFixed(2)}`);
  }
  printTable(`penumbra-gl benchmark — ${machine}${baseline ? `; old = ${baseline.ref} (${baseline.commit.slice(0, 12)})` : ''}`, table);
  if (verdicts.length > 0) {
    const slower = rows.filter((row) => row.browser?.baseline && row.browser.current.frame.median > row.browser.baseline.frame.median).map((row) => row.scene);
    console.log(`\nchromium frame new ÷ old (median): ${verdicts.join(', ')}; ${slower.length === 0 ? 'no scene slower' : `slower: ${slower.join(', ')}`}`);
  }
  if (normalsVerdicts.length > 0) {
    console.log(`\nchromium frame with normals ÷ without, each frame against the one timed in its turn (median, target ≤ ${NORMALS_TARGET}): ${normalsVerdicts.join(', ')}`);
  }
}

/** The micro-benchmark's rows and fitted costs (see bench/page/micro.ts). */
function printMicro(micro: MicroResult): void {
  const table = [['configuration', 'frame ms', 'light px', 'records visited', 'visits / px', 'px decided w/o loop']];
  for (const row of micro.rows) {
    table.push([row.name, row.frame.toFixed(1), row.pixels.toFixed(0), row.visits.toFixed(0),
      (row.visits / row.pixels).toFixed(2), `${((row.decidedWithoutLoop / row.pixels) * 100).toFixed(1)}%`]);
  }
  printTable('shadow loop micro-benchmark (Chromium, one light over the whole world)', table);
  console.log(`\na light pixel whose loop makes no trip: +${micro.zeroTripPixel.toFixed(1)} ns; each record visited: ${micro.perVisit.toFixed(1)} ns`);
}
