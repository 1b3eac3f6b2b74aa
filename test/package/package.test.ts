// The package as a user gets it: `npm pack` of the working tree (prepack builds), checked with publint
// and @arethetypeswrong/cli, installed into a new Vite vanilla-ts project where the README's snippets
// are type-checked, built and rendered in Chromium, bundled import by import to measure
// tree-shaking, and used from Node with plain headless-gl (ESM and CommonJS). One pack and one
// install serve every check.
import { existsSync, mkdirSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { join, posix } from 'node:path';
import { gzipSync } from 'node:zlib';
import { PNG } from 'pngjs';
import type { Browser } from 'puppeteer';
import { build } from 'vite';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { collectPageErrors, launchChromium } from '../browser/chromium';
import { serveDirectory, type StaticServer } from '../browser/staticServer';
import { REPO, createApp, indexHtml, pack, readmeSnippets, run, runAsync, viteTsconfig, type Packed } from './scratchProject';

/** The README's snippets that run in a browser, each built as its own page. */
const PAGES = ['plain', 'occluders', 'normals', 'pixi', 'phaser'] as const;

/**
 * Imports bundled on their own, with the most each may weigh (minified, gl-matrix included where
 * used). The engine entries' budgets rose from 170 KB to 180 KB with the normals' surface pass and
 * the edge-aware upsampling (pixi 169 KB, phaser 172 KB with the shaders' indentation stripped).
 * They rose by 6 KB with the union's sweep past four middle intervals (173.1, 197.0 and 200.2 KB),
 * by 5 KB with the lean and held programs and the tile rectangles (178.6, 202.5, 205.7 KB), and by
 * 17–23 KB with the input checks, exact predicates, colour and point forms, followers and the scene
 * format's app data (195.3, 222.8, 228.1 KB; the scene format alone 12.1 KB, the model 24.7 KB).
 * The scene format alone read 12.6 KB at 2c6119c (bound 12.5 → 13 KB). The engine entries rose by
 * 2 KB with the rule for a disk wholly inside one record (198.4 and 231.2 KB at 5a92b74), and by
 * 6 KB with the listed tiles' records and program (205.7, 233.2, 238.5 KB at 5c8811e), and by
 * 1.5 KB with programs compiled per kind of light and unclassified lights drawn lean (207.3,
 * 234.8, 240.1 KB at bf48d13; bounds 209, 237, 242 KB).
 * The names dist/ keeps (vite.config.ts) cost nothing here: a minifying bundler renames again; in
 * dist/ itself they add about 10 KB to the core chunk (238 → 248 KB as ES).
 */
const IMPORTS = [
  { name: "'penumbra-gl' (everything)", code: "import * as all from 'penumbra-gl';\nconsole.log(all);", maxBytes: 209_000, glsl: true },
  { name: "'penumbra-gl/pixi' (everything)", code: "import * as all from 'penumbra-gl/pixi';\nconsole.log(all);", maxBytes: 237_000, glsl: true },
  { name: "'penumbra-gl/phaser' (everything)", code: "import * as all from 'penumbra-gl/phaser';\nconsole.log(all);", maxBytes: 242_000, glsl: true },
  { name: '{ readScene, writeScene }', code: "import { readScene, writeScene } from 'penumbra-gl';\nconsole.log(writeScene(readScene('{}')));", maxBytes: 13_000, glsl: false },
  { name: '{ Hull, PointLight }', code: "import { Hull, PointLight } from 'penumbra-gl';\nconsole.log(new Hull([[0, 0], [1, 0], [0, 1]]), new PointLight({ position: [1, 2], range: 3 }));", maxBytes: 30_000, glsl: false },
] as const;

/** Text that only shader sources or GL calls produce: none of it may reach a bundle without the renderer. */
const GL_MARKERS = ['#version 300 es', 'getParameter(', 'createShader(', 'bindVertexArray('];

let packed: Packed;
let app: string;

beforeAll(() => {
  packed = pack();
  console.log(packed.packOutput.split('\n').filter((line) => line.startsWith('npm notice')).join('\n'));
  app = createApp(packed.root, packed.tarball).app;
  writePages(); // once: the README read at the start of the run
}, 400_000);

afterAll(() => {
  if (packed && !process.env.KEEP_SCRATCH) rmSync(packed.root, { recursive: true, force: true });
  else if (packed) console.log(`scratch project kept at ${packed.root}`);
});

describe('the packed tarball', () => {
  it('holds dist/, the scene schema, the docs pages, README.md, CHANGELOG.md, LICENSE and package.json only, and every file the exports map names', () => {
    const outside = packed.files.filter((file) => !file.startsWith('dist/') && !/^docs\/[\w-]+\.md$/.test(file) && !['schema/scene.schema.json', 'README.md', 'CHANGELOG.md', 'LICENSE', 'package.json'].includes(file));
    expect(outside).toEqual([]);
    expect(packed.files).toContain('LICENSE');
    expect(packed.files).toContain('README.md');
    const manifest = JSON.parse(readFileSync(join(REPO, 'package.json'), 'utf8')) as { exports: Record<string, unknown> };
    const targets = JSON.stringify(manifest.exports).match(/\.\/dist\/[^"]+/g) ?? [];
    expect(targets.length).toBeGreaterThanOrEqual(12);
    expect(targets.filter((target) => !packed.files.includes(target.slice(2)))).toEqual([]);
    expect((manifest.exports as Record<string, string>)['./scene.schema.json']).toBe('./schema/scene.schema.json');
    expect(packed.files).toContain('schema/scene.schema.json');
  });

  it('holds the target of every relative link and image in README.md and the docs pages (they work in node_modules)', () => {
    const pages = packed.files.filter((file) => file === 'README.md' || file === 'CHANGELOG.md' || file.startsWith('docs/'));
    expect(pages).toContain('docs/reference.md');
    const broken: string[] = [];
    for (const page of pages) {
      const text = readFileSync(join(REPO, page), 'utf8').replace(/^```[\s\S]*?^```/gm, '');
      for (const [, target] of text.matchAll(/\]\(([^)\s]+)\)/g)) {
        if (/^[a-z]+:|^#/.test(target)) continue;
        const file = posix.normalize(posix.join(posix.dirname(page), target.split('#')[0]));
        if (!packed.files.includes(file)) broken.push(`${page}: ${target}`);
      }
    }
    expect(broken).toEqual([]);
  });

  it('has source maps that embed every source (nothing they name lies outside the tarball)', () => {
    const installed = join(app, 'node_modules', 'penumbra-gl');
    const maps = packed.files.filter((file) => file.endsWith('.map'));
    expect(maps.length).toBeGreaterThan(0);
    const missing: string[] = [];
    for (const file of maps) {
      const map = JSON.parse(readFileSync(join(installed, file), 'utf8')) as { sources: string[]; sourcesContent?: (string | null)[] };
      map.sources.forEach((source, i) => {
        if (typeof map.sourcesContent?.[i] !== 'string') missing.push(`${file}: ${source}`);
      });
    }
    expect(missing).toEqual([]);
  });

  it('passes publint (any error or warning fails)', () => {
    const result = run(join(REPO, 'node_modules/.bin/publint'), ['--strict', packed.tarball], REPO);
    console.log(`publint:\n${result.output}`);
    expect(result.status, result.output).toBe(0);
  });

  it('passes @arethetypeswrong/cli: types for import and require under node16 and bundler', () => {
    // The node16 profile: node10 resolution (TypeScript's deprecated "node") cannot see subpath exports.
    const result = run(join(REPO, 'node_modules/.bin/attw'), [packed.tarball, '--profile', 'node16', '--format', 'table-flipped'], REPO);
    console.log(`attw:\n${result.output}`);
    expect(result.status, result.output).toBe(0);
  });
});

describe('types in a Vite vanilla-ts project (strict, noUnusedLocals/Parameters)', () => {
  const results = new Map<string, { status: number; output: string }>();

  // One tsc run per moduleResolution over the probes and every snippet page, side by side.
  beforeAll(async () => {
    await Promise.all((['bundler', 'node16', 'nodenext'] as const).map(async (resolution) => {
      const include = ['probe/esm.ts', ...PAGES.filter((page) => existsSync(join(app, page, 'main.ts'))).map((page) => `${page}/main.ts`)];
      if (resolution !== 'bundler') include.push('probe/cjs.cts');
      writeFileSync(join(app, `tsconfig.${resolution}.json`), viteTsconfig(resolution, include));
      results.set(resolution, await runAsync(process.execPath, [join(app, 'node_modules/typescript/bin/tsc'), '-p', `tsconfig.${resolution}.json`, '--pretty', 'false'], app));
    }));
  }, 300_000);

  const typecheck = (resolution: string) => results.get(resolution)!;

  for (const resolution of ['bundler', 'node16', 'nodenext'] as const) {
    it(`resolve under moduleResolution ${resolution}: misuse is an error, not any (import${resolution === 'bundler' ? '' : ' and require'})`, () => {
      const { output } = typecheck(resolution);
      const probeErrors = output.split('\n').filter((line) => line.startsWith('probe/'));
      if (probeErrors.length > 0) console.log(`tsc (${resolution}):\n${probeErrors.join('\n')}`);
      expect(probeErrors).toEqual([]);
    });
  }

  for (const page of PAGES) {
    for (const resolution of ['bundler', 'node16'] as const) {
      it(`README snippet=${page}, as written, type-checks under ${resolution}`, () => {
        expect(readmeSnippets().has(page), `README.md has no \`\`\`ts snippet=${page} block`).toBe(true);
        const { output } = typecheck(resolution);
        const errors = output.split('\n').filter((line) => line.startsWith(`${page}/`));
        if (errors.length > 0) console.log(`tsc (${resolution}) on README snippet=${page}:\n${errors.join('\n')}`);
        expect(errors).toEqual([]);
      });
    }
  }
});

describe('tree-shaking: each import bundled on its own with Vite from the installed package', () => {
  it('keeps shaders and GL code out of bundles that only use the scene format or the model classes', async () => {
    const rows: string[] = [];
    const failures: string[] = [];
    for (const [i, entry] of IMPORTS.entries()) {
      const dir = join(app, 'shake', String(i));
      mkdirSync(dir, { recursive: true });
      writeFileSync(join(dir, 'entry.js'), `${entry.code}\n`);
      await build({
        root: dir, configFile: false, logLevel: 'silent',
        build: {
          outDir: join(dir, 'out'), minify: true, write: true,
          rolldownOptions: { input: join(dir, 'entry.js'), external: [/^pixi\.js/, /^phaser$/], output: { entryFileNames: 'entry.js' } },
        },
      });
      const code = readFileSync(join(dir, 'out', 'entry.js'));
      const text = code.toString('utf8');
      const markers = GL_MARKERS.filter((marker) => text.includes(marker));
      rows.push(`${entry.name.padEnd(36)} ${String(code.length).padStart(8)} B  gzip ${String(gzipSync(code).length).padStart(7)} B  bound ${entry.maxBytes} B  ${markers.length ? 'has shaders/GL' : 'no shaders, no GL'}`);
      if (code.length > entry.maxBytes) failures.push(`${entry.name}: ${code.length} B over the bound of ${entry.maxBytes} B`);
      if (!entry.glsl && markers.length > 0) failures.push(`${entry.name}: holds ${markers.join(', ')}`);
      if (entry.glsl && !text.includes('#version 300 es')) failures.push(`${entry.name}: no shader in the full entry (measuring the wrong thing?)`);
    }
    console.log(`bundle sizes (Vite, minified; pixi.js and phaser external, gl-matrix bundled):\n${rows.join('\n')}`);
    expect(failures).toEqual([]);
  });
});

describe('Node with plain headless-gl (gl@9.0.0-rc.10, no patch) and the installed package', () => {
  /** A 64×48 frame: a light on the left, a hull in the middle; prints the brightness in front of and behind the hull. */
  const program = (load: string) => `${load}
const W = 64, H = 48;
const gl = createGL(W, H, { createWebGL2Context: true });
if (!gl) throw new Error('no WebGL2 context (is an X display running?)');
const renderer = new PenumbraRenderer(gl, { ambientColor: [0.05, 0.05, 0.05] });
renderer.addLight(new PointLight({ position: [12, 24], range: 70, radius: 2 }));
renderer.addHull(new Hull([[30, 14], [36, 14], [36, 34], [30, 34]]));
renderer.beginDraw();
gl.clearColor(1, 1, 1, 1);
gl.clear(gl.COLOR_BUFFER_BIT);
renderer.draw();
const pixels = new Uint8Array(W * H * 4);
gl.readPixels(0, 0, W, H, gl.RGBA, gl.UNSIGNED_BYTE, pixels);
const at = (x, y) => pixels[((H - 1 - y) * W + x) * 4];
console.log(JSON.stringify({ lit: at(18, 24), shadowed: at(50, 24), error: gl.getError() }));
renderer.dispose();
gl.getExtension('STACKGL_destroy_context').destroy();
`;
  const cases = {
    'ESM (import)': ['node-esm.mjs', "import createGL from 'gl';\nimport { Hull, PenumbraRenderer, PointLight } from 'penumbra-gl';"],
    'CommonJS (require)': ['node-cjs.cjs', "const createGL = require('gl');\nconst { Hull, PenumbraRenderer, PointLight } = require('penumbra-gl');"],
  } as const;

  for (const [name, [file, load]] of Object.entries(cases)) {
    it(`${name}: renders light in front of the hull and shadow behind it`, () => {
      writeFileSync(join(app, file), program(load));
      const result = run(process.execPath, [file], app);
      console.log(`node ${file}: ${result.output.trim()}`);
      expect(result.status, result.output).toBe(0);
      const frame = JSON.parse(result.output.trim().split('\n').pop()!) as { lit: number; shadowed: number; error: number };
      expect(frame.error).toBe(0);
      expect(frame.lit).toBeGreaterThan(150);
      expect(frame.shadowed).toBeLessThan(40);
    });
  }

  it('the README\'s Node snippet (```ts snippet=node) runs as written', () => {
    const snippet = readmeSnippets().get('node');
    if (!snippet) throw new Error('README.md has no ```ts snippet=node block');
    writeFileSync(join(app, 'readme-node.mts'), snippet);
    // Type-checked as Node code, then run through Node's own type stripping where it has it, else compiled.
    writeFileSync(join(app, 'tsconfig.node-snippet.json'), `${JSON.stringify({ compilerOptions: { target: 'ES2022', module: 'NodeNext', moduleResolution: 'NodeNext', strict: true, noUnusedLocals: true, noUnusedParameters: true, skipLibCheck: true, outDir: 'node-snippet', types: ['node'] }, include: ['readme-node.mts'] }, null, 2)}\n`);
    const compiled = run(process.execPath, [join(app, 'node_modules/typescript/bin/tsc'), '-p', 'tsconfig.node-snippet.json', '--pretty', 'false'], app);
    expect(compiled.status, compiled.output).toBe(0);
    const result = run(process.execPath, [join('node-snippet', 'readme-node.mjs')], app);
    console.log(`README snippet=node: ${result.output.trim()}`);
    expect(result.status, result.output).toBe(0);
  });
});

describe('readable dist/: the installed files keep their function and class names', () => {
  it('in Node (ESM and CommonJS) every function and class penumbra-gl exports is named as exported, and a stack trace names the class', () => {
    const check = `const wrong = Object.entries(api).filter(([key, value]) => typeof value === 'function' && value.name !== key).map(([key, value]) => key + ' is named ' + JSON.stringify(value.name));
let stack = '';
try { new api.Hull('not points'); } catch (error) { stack = String(error.stack); }
console.log(JSON.stringify({ wrong, renderer: api.PenumbraRenderer.name, hull: api.Hull.name, stackNamesHull: stack.includes('at new Hull ') }));
`;
    const programs = { 'names-esm.mjs': `import * as api from 'penumbra-gl';\n${check}`, 'names-cjs.cjs': `const api = require('penumbra-gl');\n${check}` };
    for (const [file, program] of Object.entries(programs)) {
      writeFileSync(join(app, file), program);
      const result = run(process.execPath, [file], app);
      console.log(`node ${file}: ${result.output.trim()}`);
      expect(result.status, result.output).toBe(0);
      expect(JSON.parse(result.output.trim().split('\n').pop()!)).toEqual({ wrong: [], renderer: 'PenumbraRenderer', hull: 'Hull', stackNamesHull: true });
    }
  });

  it('in Chromium, loaded unbundled through an import map, every function and class of penumbra-gl, /pixi and /phaser is named as exported', async () => {
    writeFileSync(join(app, 'names.html'), NAMES_PAGE);
    const server = await serveDirectory(app);
    const browser = await launchChromium();
    try {
      const tab = await browser.newPage();
      const errors = collectPageErrors(tab);
      await tab.goto(`${server.url}names.html`);
      await tab.waitForFunction('window.exportNames || window.loadError', { timeout: 60_000 });
      const { exportNames, loadError } = await tab.evaluate('({ exportNames: window.exportNames, loadError: window.loadError })') as { exportNames?: Record<string, Record<string, string>>; loadError?: string };
      expect(loadError, loadError).toBeUndefined();
      expect(errors).toEqual([]);
      const wrong = Object.entries(exportNames!).flatMap(([entry, names]) => Object.entries(names).filter(([key, name]) => key !== name).map(([key, name]) => `${entry}: ${key} is named ${JSON.stringify(name)}`));
      console.log(`function and class exports: ${Object.entries(exportNames!).map(([entry, names]) => `${entry} ${Object.keys(names).length}`).join(', ')}; misnamed: ${wrong.length}`);
      expect(wrong).toEqual([]);
      expect(exportNames!.index.PenumbraRenderer).toBe('PenumbraRenderer');
      expect(exportNames!.pixi.PenumbraLayer).toBe('PenumbraLayer');
      expect(exportNames!.phaser.PenumbraPlugin).toBe('PenumbraPlugin');
    } finally {
      await browser.close();
      await server.close();
    }
  }, 120_000);
});

/** A page that imports the installed dist/ files of the three entries as they are, the engines and gl-matrix mapped to their own ES builds. */
const NAMES_PAGE = `<!doctype html>
<html>
  <head>
    <link rel="icon" href="data:," />
    <script type="importmap">
      { "imports": { "gl-matrix": "/node_modules/gl-matrix/esm/index.js", "pixi.js": "/node_modules/pixi.js/dist/pixi.min.mjs", "phaser": "/node_modules/phaser/dist/phaser.esm.min.js" } }
    </script>
    <script type="module">
      try {
        const names = {};
        for (const entry of ['index', 'pixi', 'phaser']) {
          const exports = await import('/node_modules/penumbra-gl/dist/' + entry + '.js');
          names[entry] = Object.fromEntries(Object.entries(exports).filter(([, value]) => typeof value === 'function').map(([key, value]) => [key, value.name]));
        }
        window.exportNames = names;
      } catch (error) {
        window.loadError = String(error);
      }
    </script>
  </head>
  <body></body>
</html>
`;

describe('the README\'s browser snippets, built with Vite and rendered in Chromium', () => {
  let browser: Browser;
  let server: StaticServer;
  let built = false;

  beforeAll(async () => {
    const input = Object.fromEntries(PAGES.filter((page) => existsSync(join(app, page, 'main.ts'))).map((page) => [page, join(app, page, 'index.html')]));
    try {
      await build({ root: app, configFile: false, logLevel: 'warn', build: { outDir: join(app, 'dist'), rolldownOptions: { input } } });
      built = true;
    } catch (error) {
      console.log(`vite build of the snippet pages failed: ${String(error)}`);
    }
    server = await serveDirectory(join(app, built ? 'dist' : '.'));
    browser = await launchChromium();
  }, 300_000);

  afterAll(async () => {
    await browser?.close();
    await server?.close();
  });

  for (const page of PAGES) {
    it(`snippet=${page}: builds, runs without console errors, and shows light and shadow`, async () => {
      expect(readmeSnippets().has(page), `README.md has no \`\`\`ts snippet=${page} block`).toBe(true);
      expect(built, 'vite build of the snippet pages failed (see the log)').toBe(true);
      const tab = await browser.newPage();
      const errors = collectPageErrors(tab);
      await tab.setViewport({ width: 1024, height: 768 });
      await tab.goto(`${server.url}${page}/index.html`);
      // Long: under load the page's main thread can be busy for tens of seconds compiling shaders.
      const canvas = await tab.waitForSelector('canvas', { timeout: 90_000 });
      // Frames until the criteria hold or 90 s pass (SwiftShader takes seconds a frame; engines boot on their own clock).
      let stats!: ReturnType<typeof luminanceStats>;
      let size: string;
      const start = Date.now();
      for (const deadline = start + 90_000; ;) {
        await tab.evaluate(() => new Promise<void>((done) => requestAnimationFrame(() => requestAnimationFrame(() => done()))));
        const png = PNG.sync.read(Buffer.from(await canvas!.screenshot({ type: 'png' })));
        stats = luminanceStats(png);
        size = `${png.width}×${png.height}`;
        if (showsLight(stats) || Date.now() > deadline) break;
      }
      await tab.close();
      console.log(`snippet=${page}: ${size} canvas, luminance max ${stats.max.toFixed(0)}, 90th percentile ${stats.p90.toFixed(0)}, 10th percentile ${stats.p10.toFixed(0)}, lit (> 100) ${(stats.litFraction * 100).toFixed(1)}%, dark (< 40) ${(stats.darkFraction * 100).toFixed(1)}%, after ${((Date.now() - start) / 1000).toFixed(1)} s of frames; console errors: ${errors.length}`);
      expect(errors).toEqual([]);
      // Light: a region clearly lit. Shadow or ambient: a region clearly darker.
      expect(stats.max, 'no bright pixel: nothing lit').toBeGreaterThan(150);
      expect(stats.litFraction, 'under 2% of the canvas lit (luminance > 100)').toBeGreaterThan(0.02);
      expect(stats.darkFraction, 'under 5% of the canvas in shadow or ambient (luminance < 40)').toBeGreaterThan(0.05);
    }, 180_000);
  }
});

/** Writes each README snippet as its page's main.ts (as written), and the type probes. */
function writePages(): void {
  const snippets = readmeSnippets();
  for (const page of PAGES) {
    const snippet = snippets.get(page);
    if (!snippet) continue;
    mkdirSync(join(app, page), { recursive: true });
    writeFileSync(join(app, page, 'index.html'), indexHtml(`penumbra-gl: README snippet=${page}`));
    writeFileSync(join(app, page, 'main.ts'), snippet);
  }
  mkdirSync(join(app, 'probe'), { recursive: true });
  // Each @ts-expect-error fails tsc if the line type-checks, i.e. if the types resolved to `any`.
  writeFileSync(join(app, 'probe', 'esm.ts'), `import { PointLight, readScene, type SceneDocument } from 'penumbra-gl';
import { PenumbraLayer } from 'penumbra-gl/pixi';
import { PenumbraPlugin } from 'penumbra-gl/phaser';

// @ts-expect-error position is a vector, range a number
export const wrong = new PointLight({ position: 'x', range: 'far' });
export const right: PointLight = new PointLight({ position: [1, 2], range: 3 });
export const scene: SceneDocument = readScene('{}');
// @ts-expect-error the layer needs a renderer
export const layer = new PenumbraLayer();
export type Plugin = PenumbraPlugin;
`);
  // A CommonJS file: its imports resolve through the \`require\` condition (the .d.cts types).
  writeFileSync(join(app, 'probe', 'cjs.cts'), `import type { PointLight, LightOptions } from 'penumbra-gl';
import type { PenumbraLayer } from 'penumbra-gl/pixi';
import type { PenumbraPlugin } from 'penumbra-gl/phaser';

// @ts-expect-error position is a vector, range a number
const wrong: LightOptions = { position: 'x', range: 'far' };
// @ts-expect-error a string is no light
const light: PointLight = 'light';
// @ts-expect-error a number is no layer
const layer: PenumbraLayer = 1;
// @ts-expect-error a number is no plugin
const plugin: PenumbraPlugin = 1;
console.log(wrong, light, layer, plugin);
`);
}

/** The criteria the snippet pages are held to (asserted one by one in the test). */
function showsLight(stats: ReturnType<typeof luminanceStats>): boolean {
  return stats.max > 150 && stats.litFraction > 0.02 && stats.darkFraction > 0.05;
}

/** Luminance (0–255) statistics over every pixel of a screenshot. */
function luminanceStats(png: PNG): { max: number; p10: number; p90: number; litFraction: number; darkFraction: number } {
  const values = new Float32Array(png.width * png.height);
  for (let i = 0; i < values.length; i++) {
    values[i] = 0.2126 * png.data[i * 4] + 0.7152 * png.data[i * 4 + 1] + 0.0722 * png.data[i * 4 + 2];
  }
  const sorted = values.slice().sort();
  const quantile = (q: number) => sorted[Math.min(sorted.length - 1, Math.floor(q * sorted.length))];
  let lit = 0, dark = 0;
  for (const value of values) {
    if (value > 100) lit++;
    if (value < 40) dark++;
  }
  return { max: sorted[sorted.length - 1], p10: quantile(0.1), p90: quantile(0.9), litFraction: lit / values.length, darkFraction: dark / values.length };
}
