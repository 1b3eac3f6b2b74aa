// Builds the bench's bundles with Vite (used by bench/run.mjs and scripts/pack-gpu-bench.sh):
// - the baseline renderer: src/ and shaders/ of a git ref (default BASELINE_REF), extracted with
//   `git archive` into bench/.build/baseline/<commit>-v<n>/ and built there as one ES module
//   (penumbra.mjs, gl-matrix left external), cached by commit;
// - the bench bundles, which import it as 'virtual:penumbra-baseline' (typed in bench/baseline.d.ts;
//   `library` is null with --no-baseline): the Chromium page (bench/.build/page/), the Node runner
//   (bench/.build/main.mjs) and the Vulkan GPU mode (bench/.build/gpu.mjs).
// Needs the ref's history in the clone (CI: fetch-depth 0); `npm test` never builds any of this.
import { execFileSync } from 'node:child_process';
import { existsSync, mkdirSync, rmSync, writeFileSync } from 'node:fs';
import { resolve } from 'node:path';
import { build } from 'vite';

/** The last commit before the shadow-core v2 rewrite: the renderer the new core must not be slower than. */
export const BASELINE_REF = '8d3feef';

const VIRTUAL_ID = 'virtual:penumbra-baseline';
/** Part of the baseline's cache folder: raise it when the baseline's build options change. */
const BASELINE_BUILD = 'v1';
const quiet = { configFile: false, logLevel: 'warn' };

/**
 * The baseline asked for by the command line: `--baseline=<ref>` (default BASELINE_REF), or null
 * with `--no-baseline`.
 */
export function baselineRefFromArgs(args) {
  if (args.includes('--no-baseline')) return null;
  const given = args.find((arg) => arg.startsWith('--baseline='));
  return given ? given.slice('--baseline='.length) : BASELINE_REF;
}

/**
 * Extracts `ref`'s src/ and shaders/ and builds them into one ES module; returns
 * `{ ref, commit, file }`. Rebuilt only when the commit's module is missing.
 */
export async function buildBaseline(root, ref) {
  let commit;
  try {
    commit = git(root, ['rev-parse', '--verify', '--quiet', `${ref}^{commit}`]).trim();
  } catch {
    throw new Error(`bench baseline: git cannot find the commit '${ref}' in ${root}. In a shallow clone fetch the history (git fetch --unshallow, or actions/checkout with fetch-depth: 0), name another ref with --baseline=<ref>, or run without it: --no-baseline.`);
  }
  const dir = resolve(root, 'bench/.build/baseline', `${commit}-${BASELINE_BUILD}`);
  const file = resolve(dir, 'dist/penumbra.mjs');
  if (existsSync(file)) return { ref, commit, file };
  rmSync(dir, { recursive: true, force: true });
  mkdirSync(dir, { recursive: true });
  const present = new Set(git(root, ['ls-tree', '--name-only', commit]).split('\n'));
  if (!present.has('src')) throw new Error(`bench baseline: ${ref} (${commit}) has no src/`);
  const paths = ['src', 'shaders', 'tsconfig.json'].filter((path) => present.has(path));
  const archive = execFileSync('git', ['archive', '--format=tar', commit, ...paths], { cwd: root, maxBuffer: 1 << 30 });
  execFileSync('tar', ['-x', '-C', dir], { input: archive });
  await build({
    ...quiet,
    root: dir,
    build: {
      outDir: resolve(dir, 'dist'),
      emptyOutDir: true,
      // The bench bundles minify (or not) both renderers alike; this build only compiles TypeScript and inlines the shaders.
      minify: false,
      target: 'es2022',
      lib: { entry: resolve(dir, 'src/index.ts'), formats: ['es'], fileName: () => 'penumbra.mjs' },
      // Resolved by the bench bundles from the repository's node_modules: one gl-matrix for both renderers.
      rollupOptions: { external: [/^gl-matrix/] },
    },
  });
  writeFileSync(resolve(dir, 'REF'), `${ref} ${commit}\n`);
  return { ref, commit, file };
}

/** Serves 'virtual:penumbra-baseline' from the baseline module, or as `library = null`. */
function baselinePlugin(baseline) {
  const resolved = `\0${VIRTUAL_ID}`;
  return {
    name: 'penumbra-baseline',
    resolveId: (id) => (id === VIRTUAL_ID ? resolved : null),
    load(id) {
      if (id !== resolved) return null;
      if (!baseline) return 'export const library = null;\nexport const baseline = null;\n';
      const info = JSON.stringify({ ref: baseline.ref, commit: baseline.commit });
      return `export * as library from ${JSON.stringify(baseline.file)};\nexport const baseline = ${info};\n`;
    },
  };
}

/**
 * Builds the bench bundles into bench/.build: `targets` among 'page', 'node', 'gpu'. `baseline` is
 * buildBaseline's answer or null.
 */
export async function buildBench(root, { baseline, targets }) {
  const out = resolve(root, 'bench/.build');
  const plugins = [baselinePlugin(baseline)];
  if (targets.includes('page')) {
    await build({
      ...quiet,
      plugins,
      root: resolve(root, 'bench/page'),
      base: './',
      build: { outDir: resolve(out, 'page'), emptyOutDir: true },
    });
  }
  for (const [target, entry, name] of [['node', 'bench/main.ts', 'main.mjs'], ['gpu', 'bench/gpu.ts', 'gpu.mjs']]) {
    if (!targets.includes(target)) continue;
    await build({
      ...quiet,
      plugins,
      root,
      // Everything bundled but headless-gl (native) and puppeteer: gpu.mjs runs with only node_modules/gl beside it.
      ssr: { noExternal: true, external: ['gl', 'puppeteer'] },
      build: {
        ssr: resolve(root, entry),
        outDir: out,
        emptyOutDir: false,
        target: 'node20',
        rollupOptions: { output: { entryFileNames: name } },
      },
    });
  }
  const info = { date: new Date().toISOString(), targets, baseline: baseline && { ref: baseline.ref, commit: baseline.commit } };
  writeFileSync(resolve(out, 'build-info.json'), `${JSON.stringify(info, null, 2)}\n`);
  return out;
}

function git(root, args) {
  return execFileSync('git', args, { cwd: root, encoding: 'utf8', stdio: ['ignore', 'pipe', 'pipe'] });
}
