#!/usr/bin/env node
// `npm run bench`: bundles the runner (for Node) and the benchmark page (for Chromium) with Vite,
// then runs the runner with an X display (headless-gl needs one), exposed GC and a young
// generation large enough to measure per-frame allocation. Arguments are passed on:
// --scenes=S1,S2  --frames=100  --browser-frames=10  --lightmap-scale=0.5  --bounds  --no-node  --no-browser
import { spawnSync } from 'node:child_process';
import { resolve } from 'node:path';
import { build } from 'vite';

const root = resolve(import.meta.dirname, '..');
const out = resolve(root, 'bench/.build');
const quiet = { configFile: false, logLevel: 'warn' };

await build({
  ...quiet,
  root: resolve(root, 'bench/page'),
  base: './',
  build: { outDir: resolve(out, 'page'), emptyOutDir: true },
});
await build({
  ...quiet,
  root,
  ssr: { noExternal: true, external: ['gl', 'puppeteer'] },
  build: {
    ssr: resolve(root, 'bench/main.ts'),
    outDir: out,
    emptyOutDir: false,
    target: 'node20',
    rollupOptions: { output: { entryFileNames: 'main.mjs' } },
  },
});
const result = spawnSync('node', [
  resolve(root, 'scripts/with-display.mjs'),
  'node', '--expose-gc', '--max-semi-space-size=128', resolve(out, 'main.mjs'), ...process.argv.slice(2),
], { stdio: 'inherit', cwd: root });
process.exit(result.status ?? 1);
