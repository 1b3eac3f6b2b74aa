// The GPU mode of the bench (`npm run bench -- --gpu`, or the packed bench of
// scripts/pack-gpu-bench.sh): the Node rendering path on headless-gl, whose bundled ANGLE renders on
// Vulkan (ANGLE_DEFAULT_PLATFORM=vulkan; libvulkan.so.1 beside node_modules/gl/build/Release/libGLESv2.so;
// the driver from VK_ICD_FILENAMES or the loader's search), with real GL calls and no X display.
// Per scene, the working tree's renderer ("new") and the baseline ("old", bench/build.mjs) draw
// whole frames (scene cleared white, lightmap, composite into the 1280×720 drawing buffer) in
// turns, each timed to its gl.finish(); the median of --frames after --warmup, with the fill floor
// (bench/floor.ts) timed alike. Prints a table and writes JSON (--out, default
// bench/results/gpu-latest.json). Frame times include headless-gl's JavaScript validation layer,
// which a browser's native WebGL does not have: 'submit ms' is the part until draw() returned.
// Options: --scenes=S1,S3 --frames=20 --warmup=5 --lightmap-scale=1 --out=<file> --any-backend (run even if not on Vulkan).
import { library as baselineLibrary, baseline } from 'virtual:penumbra-baseline';
import { mkdirSync, writeFileSync } from 'node:fs';
import { cpus } from 'node:os';
import { dirname, resolve } from 'node:path';
import { createContext, destroyContext } from '../test/gl/context';
import { EXTRA_STATS, extraStatCells, readExtraStats, type ExtraStats } from './extraStats';
import { FillFloor } from './floor';
import { answerVertexArrayLikeBrowsers } from './glProbe';
import { CURRENT, type BenchRenderer, type RendererLibrary } from './library';
import { createScene, runsOn, runsOnHeadlessGl, SCENES, WORLD_HEIGHT, WORLD_WIDTH, type BenchScene, type SceneSpec } from './scenes';
import { summarize, type Summary } from './stats';
import { printTable, ratioCell } from './table';

interface Side {
  /** Whole frame to gl.finish(), ms. */
  frame: Summary;
  /** Until draw() returned (JavaScript, headless-gl's layer and command submission), ms. */
  submit: Summary;
  /** Median frame ÷ median floor. */
  ratio: number;
  /** Mean of the R, G and B bytes of a frame read back after the measured ones: 0 or 255 means nothing was lit. */
  meanPixel: number;
  /** Share of pixels differing from the other renderer's frame by more than 8/255 in a channel (new only). */
  differentPixels?: number;
  /** The first gl.getError() after one of its frames, with the frame's number; null: none. */
  glError: { code: number; frame: number } | null;
  extra: ExtraStats;
}

interface GpuSceneResult {
  scene: string;
  lights: number;
  hulls: number;
  floor: Summary;
  current: Side;
  baseline?: Side;
  /** gl.getError() after the floor's frames and the read-backs (0: none). */
  glError: number;
}

const args = new Map(process.argv.slice(2).map((arg) => arg.replace(/^--/, '').split('=') as [string, string]));
const only = args.get('scenes')?.split(',');
const scenes = SCENES.filter((scene) => !only || only.includes(scene.name));
const frames = Number(args.get('frames') ?? 20);
const warmup = Number(args.get('warmup') ?? 5);
const lightmapScale = Number(args.get('lightmap-scale') ?? 1);
const out = resolve(args.get('out') ?? 'bench/results/gpu-latest.json');
const oldName = baseline ? `old ${baseline.ref}` : 'old';

let gl: WebGL2RenderingContext;
try {
  gl = createContext(WORLD_WIDTH, WORLD_HEIGHT);
  answerVertexArrayLikeBrowsers(gl);
} catch (error) {
  console.error(`${String(error)}\nOn Vulkan: set ANGLE_DEFAULT_PLATFORM=vulkan, put libvulkan.so.1 beside node_modules/gl/build/Release/libGLESv2.so, and make a Vulkan driver visible (VK_ICD_FILENAMES=/usr/share/vulkan/icd.d/lvp_icd.x86_64.json for Mesa's lavapipe).`);
  process.exit(1);
}
const device = describeDevice(gl);
if (!/vulkan/i.test(device.renderer) && !args.has('any-backend')) {
  console.error(`not on Vulkan: the context's renderer is "${device.renderer}". Set ANGLE_DEFAULT_PLATFORM=vulkan (or pass --any-backend).`);
  process.exit(1);
}
process.stderr.write(`renderer: ${device.renderer}\n`);

const machine = `${cpus()[0]?.model ?? 'unknown CPU'} × ${cpus().length}, Node ${process.version}, headless-gl on ANGLE/Vulkan`;
const results: GpuSceneResult[] = [];
for (const spec of scenes) {
  if (!runsOnHeadlessGl(spec)) {
    process.stderr.write(`gpu ${spec.name}: skipped (normals need several colour attachments, which headless-gl cannot draw into; run it in Chromium: npm run bench)\n`);
    continue;
  }
  process.stderr.write(`gpu ${spec.name}…\n`);
  results.push(runScene(spec));
  const last = results[results.length - 1];
  const old = last.baseline ? `, ${oldName} ${last.baseline.frame.median.toFixed(2)} ms` : '';
  process.stderr.write(`  frame ${last.current.frame.median.toFixed(2)} ms${old}, floor ${last.floor.median.toFixed(2)} ms\n`);
  // Written after every scene: a run stopped in a slow scene keeps the ones before.
  writeResults();
}
destroyContext(gl);
report(results);
console.log(`\nwritten ${out}`);

function writeResults(): void {
  mkdirSync(dirname(out), { recursive: true });
  writeFileSync(out, JSON.stringify({
    date: new Date().toISOString(), machine, device, vkIcdFilenames: process.env.VK_ICD_FILENAMES ?? process.env.VK_DRIVER_FILES ?? null,
    baseline, frames, warmup, lightmapScale, results,
  }, null, 2));
}

/** The context's renderer, version and vendor as the driver states them (headless-gl's own getParameter answers 'ANGLE'). */
function describeDevice(context: WebGL2RenderingContext): { renderer: string; version: string; vendor: string } {
  const info = context.getExtension('WEBGL_debug_renderer_info');
  // headless-gl lacks WEBGL_debug_renderer_info; its native getParameter (the deepest on the prototype chain) reads glGetString.
  let native: ((pname: number) => unknown) | undefined;
  for (let proto: object | null = Object.getPrototypeOf(context); proto && proto !== Object.prototype; proto = Object.getPrototypeOf(proto)) {
    const own = Object.getOwnPropertyDescriptor(proto, 'getParameter')?.value as ((pname: number) => unknown) | undefined;
    if (typeof own === 'function') native = own;
  }
  const read = (pname: number) => String((native ?? context.getParameter).call(context, pname));
  return {
    renderer: info ? String(context.getParameter(info.UNMASKED_RENDERER_WEBGL)) : read(context.RENDERER),
    version: read(context.VERSION),
    vendor: info ? String(context.getParameter(info.UNMASKED_VENDOR_WEBGL)) : read(context.VENDOR),
  };
}

interface Contender {
  scene: BenchScene;
  renderer: BenchRenderer;
  frame: number[];
  submit: number[];
  glError: { code: number; frame: number } | null;
}

function contender(spec: SceneSpec, library: RendererLibrary): Contender {
  const scene = createScene(spec, library);
  const renderer = new library.PenumbraRenderer(gl, { ambientColor: [0.05, 0.05, 0.05], lightmapScale });
  for (const light of scene.lights) renderer.addLight(light);
  for (const hull of scene.hulls) renderer.addHull(hull);
  return { scene, renderer, frame: [], submit: [], glError: null };
}

/** One whole frame of `renderer`, timed to its gl.finish(); the queue is drained before it starts. */
function timeFrame(renderer: BenchRenderer): { frame: number; submit: number } {
  gl.finish();
  const start = performance.now();
  renderer.beginDraw();
  gl.clearColor(1, 1, 1, 1);
  gl.clear(gl.COLOR_BUFFER_BIT);
  renderer.draw();
  const submitted = performance.now();
  gl.finish();
  const end = performance.now();
  return { frame: end - start, submit: submitted - start };
}

function runScene(spec: SceneSpec): GpuSceneResult {
  const contenders = [contender(spec, CURRENT), ...(baselineLibrary && runsOn(spec, baselineLibrary) ? [contender(spec, baselineLibrary)] : [])];
  const floor = new FillFloor(gl, WORLD_WIDTH, WORLD_HEIGHT);
  const floorTimes: number[] = [];
  let reported = performance.now();
  for (let frame = 0; frame < warmup + frames; frame++) {
    for (const { scene } of contenders) scene.step(frame);
    // Which renderer goes first alternates from frame to frame.
    const order = frame % 2 === 1 ? [...contenders].reverse() : contenders;
    for (const entry of order) {
      const time = timeFrame(entry.renderer);
      // Read outside the timed part: each renderer's errors are its own.
      const error = gl.getError();
      if (error !== 0 && !entry.glError) entry.glError = { code: error, frame };
      if (frame < warmup) continue;
      entry.frame.push(time.frame);
      entry.submit.push(time.submit);
    }
    gl.finish();
    gl.getError();
    const start = performance.now();
    floor.render(contenders[0].scene.lights);
    gl.finish();
    if (frame >= warmup) floorTimes.push(performance.now() - start);
    gl.bindFramebuffer(gl.FRAMEBUFFER, null);
    // Slow scenes (S4 on a CPU rasterizer takes minutes a frame) say where they are.
    if (performance.now() - reported > 10_000) {
      reported = performance.now();
      const last = (entry: Contender) => (entry.frame.length > 0 ? `${entry.frame[entry.frame.length - 1].toFixed(0)} ms` : 'warm-up');
      process.stderr.write(`  frame ${frame + 1} of ${warmup + frames}: ${contenders.map((entry, i) => `${i === 0 ? 'new' : oldName} ${last(entry)}`).join(', ')}\n`);
    }
  }
  const floorSummary = summarize(floorTimes);
  // Read each renderer's frame of one more (same) scene state back, to see that it drew.
  const images = contenders.map(({ renderer }) => {
    timeFrame(renderer);
    const pixels = new Uint8Array(WORLD_WIDTH * WORLD_HEIGHT * 4);
    gl.readPixels(0, 0, WORLD_WIDTH, WORLD_HEIGHT, gl.RGBA, gl.UNSIGNED_BYTE, pixels);
    return pixels;
  });
  const sides = contenders.map((entry, i): Side => {
    const frame = summarize(entry.frame);
    return {
      frame, submit: summarize(entry.submit), ratio: frame.median / floorSummary.median,
      meanPixel: meanPixel(images[i]), glError: entry.glError, extra: readExtraStats(entry.renderer.stats),
    };
  });
  if (images.length === 2) sides[0].differentPixels = differentShare(images[0], images[1]);
  const glError = gl.getError();
  if (glError !== 0) process.stderr.write(`  gl.getError() = 0x${glError.toString(16)} after ${spec.name}'s fill floor or read-backs\n`);
  for (const [i, side] of sides.entries()) {
    if (side.glError) process.stderr.write(`  gl.getError() = 0x${side.glError.code.toString(16)} after ${i === 0 ? 'new' : oldName}'s frame ${side.glError.frame} of ${spec.name}\n`);
  }
  for (const { renderer } of contenders) renderer.dispose();
  floor.dispose();
  return { scene: spec.name, lights: spec.lights, hulls: spec.hulls + spec.farHulls, floor: floorSummary, current: sides[0], baseline: sides[1], glError };
}

function meanPixel(pixels: Uint8Array): number {
  let sum = 0;
  for (let i = 0; i < pixels.length; i += 4) sum += pixels[i] + pixels[i + 1] + pixels[i + 2];
  return sum / (pixels.length / 4 * 3);
}

function differentShare(a: Uint8Array, b: Uint8Array): number {
  let different = 0;
  for (let i = 0; i < a.length; i += 4) {
    if (Math.max(Math.abs(a[i] - b[i]), Math.abs(a[i + 1] - b[i + 1]), Math.abs(a[i + 2] - b[i + 2])) > 8) different++;
  }
  return different / (a.length / 4);
}

function report(rows: GpuSceneResult[]): void {
  const ms = (value: number) => value.toFixed(2);
  const pair = (summary: Summary) => `${ms(summary.median)} / ${ms(summary.p95)}`;
  const table: string[][] = [[
    'scene', 'renderer', 'lights', 'hulls', 'frame ms (med / p95)', 'submit ms (med)', 'floor ms (med)', 'frame ÷ floor',
    'mean px', 'px ≠ old', 'GL error', ...EXTRA_STATS.map(({ label }) => label),
  ]];
  for (const row of rows) {
    const side = (name: string, s: Side, extra: string[]) => [
      row.scene, name, String(row.lights), String(row.hulls), pair(s.frame), ms(s.submit.median), ms(row.floor.median), s.ratio.toFixed(2),
      s.meanPixel.toFixed(1), s.differentPixels === undefined ? '–' : `${(s.differentPixels * 100).toFixed(2)}%`,
      s.glError ? `0x${s.glError.code.toString(16)} (frame ${s.glError.frame})` : 'none', ...extra,
    ];
    table.push(side('new', row.current, extraStatCells(row.current.extra)));
    if (!row.baseline) continue;
    table.push(side(oldName, row.baseline, EXTRA_STATS.map(() => '')));
    table.push([
      row.scene, 'new ÷ old', '', '', ratioCell(row.current.frame.median, row.baseline.frame.median),
      ratioCell(row.current.submit.median, row.baseline.submit.median), '', ratioCell(row.current.ratio, row.baseline.ratio),
      '', '', '', ...EXTRA_STATS.map(() => ''),
    ]);
  }
  printTable([
    `penumbra-gl GPU benchmark (Vulkan) — ${machine}`,
    `GL renderer: ${device.renderer}; ${device.version}`,
    `frames: ${frames} after ${warmup} warm-up, 1280×720, lightmap scale ${lightmapScale}${baseline ? `; old = ${baseline.ref} (${baseline.commit.slice(0, 12)})` : '; no baseline'}`,
  ].join('\n'), table);
  const compared = rows.filter((row) => row.baseline);
  if (compared.length > 0) {
    const slower = compared.filter((row) => row.current.frame.median > row.baseline!.frame.median).map((row) => row.scene);
    console.log(`\nframe new ÷ old (median): ${compared.map((row) => `${row.scene} ${ratioCell(row.current.frame.median, row.baseline!.frame.median)}`).join(', ')}; ${slower.length === 0 ? 'no scene slower' : `slower: ${slower.join(', ')}`}`);
  }
}
