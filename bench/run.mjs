#!/usr/bin/env node
// `npm run bench`: builds the baseline renderer from a git ref and the bench bundles with Vite
// (bench/build.mjs), then runs one of the bench's modes. Every mode measures the working tree's
// renderer ("new") and the baseline ("old") side by side in the same run, with a new ÷ old row.
//
// Default mode (bench/main.ts): Node CPU figures on headless-gl (JS ms with GL stubbed, time in GL,
// GL calls, heap per frame), then whole frames and the fill floor in Chromium on SwiftShader.
// headless-gl runs under an X display (scripts/with-display.mjs: Xvfb when DISPLAY is unset), with
// exposed GC and a young generation large enough to measure per-frame allocation.
//   npm run bench -- --scenes=S1,S2 --frames=100 --browser-frames=10 --lightmap-scale=0.5 --bounds --no-node --no-browser
//
// GPU mode (--gpu, bench/gpu.ts): the Node rendering path on Vulkan through headless-gl's ANGLE,
// real GL calls, frames timed to gl.finish(); no X display. Needs libvulkan.so.1 beside
// node_modules/gl/build/Release/libGLESv2.so (copied there from the system when missing) and a
// Vulkan driver (the loader's own search, or VK_ICD_FILENAMES; here Mesa's lavapipe:
// VK_ICD_FILENAMES=/usr/share/vulkan/icd.d/lvp_icd.x86_64.json). For a machine with a GPU and no
// repository, scripts/pack-gpu-bench.sh packs this mode with Node into one tarball.
//   npm run bench -- --gpu --scenes=S1,S3 --frames=20 --warmup=5 --lightmap-scale=1 --out=bench/results/gpu-latest.json
//
// Both: --baseline=<ref> (default 8d3feef, the last commit before the shadow-core v2 rewrite) or
// --no-baseline; --build-only builds the mode's bundles into bench/.build and runs nothing.
import { spawnSync } from 'node:child_process';
import { copyFileSync, existsSync } from 'node:fs';
import { resolve } from 'node:path';
import { baselineRefFromArgs, buildBaseline, buildBench } from './build.mjs';

const root = resolve(import.meta.dirname, '..');
const args = process.argv.slice(2);
const gpu = args.includes('--gpu');
// Arguments for bench/main.ts or bench/gpu.ts: the build's own are consumed here.
const passed = args.filter((arg) => !['--gpu', '--no-baseline', '--build-only'].includes(arg) && !arg.startsWith('--baseline='));

const ref = baselineRefFromArgs(args);
let baseline = null;
try {
  baseline = ref ? await buildBaseline(root, ref) : null;
} catch (error) {
  console.error(error instanceof Error ? error.message : error);
  process.exit(1);
}
if (baseline) process.stderr.write(`baseline: ${baseline.ref} = ${baseline.commit}\n`);
const out = await buildBench(root, { baseline, targets: gpu ? ['gpu'] : ['page', 'node'] });
if (args.includes('--build-only')) process.exit(0);

let result;
if (gpu) {
  ensureVulkanLoader();
  const env = { ...process.env, ANGLE_DEFAULT_PLATFORM: 'vulkan' };
  // The Vulkan path needs no X display: make sure none is used.
  delete env.DISPLAY;
  result = spawnSync('node', [resolve(out, 'gpu.mjs'), ...passed], { stdio: 'inherit', cwd: root, env });
} else {
  result = spawnSync('node', [
    resolve(root, 'scripts/with-display.mjs'),
    'node', '--expose-gc', '--max-semi-space-size=128', resolve(out, 'main.mjs'), ...passed,
  ], { stdio: 'inherit', cwd: root });
}
process.exit(result.status ?? 1);

/** ANGLE loads the Vulkan loader from its own folder only ("Internal Vulkan error (-3)" without it). */
function ensureVulkanLoader() {
  const release = resolve(root, 'node_modules/gl/build/Release');
  const target = resolve(release, 'libvulkan.so.1');
  if (existsSync(target)) return;
  const candidates = ['/usr/lib/x86_64-linux-gnu/libvulkan.so.1', '/usr/lib64/libvulkan.so.1', '/usr/lib/libvulkan.so.1', '/lib/x86_64-linux-gnu/libvulkan.so.1'];
  const found = candidates.find((path) => existsSync(path));
  if (!found) {
    console.error('bench --gpu: no libvulkan.so.1 found. Install the Vulkan loader and a driver (Debian, as root: apt-get install -y libvulkan1 mesa-vulkan-drivers).');
    process.exit(1);
  }
  copyFileSync(found, target);
  process.stderr.write(`copied ${found} to ${target} (ANGLE loads the Vulkan loader from its own folder)\n`);
}
