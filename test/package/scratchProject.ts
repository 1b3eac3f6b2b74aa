// A new user's project, made in a scratch directory: the packed tarball installed with npm, the
// README's snippets written as they are, the engines and tools the snippets need linked from this
// repository's node_modules (installed by `npm ci`, so nothing is fetched here).
import { execFile, execFileSync, spawnSync } from 'node:child_process';
import { mkdirSync, mkdtempSync, readFileSync, readdirSync, symlinkSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join, resolve } from 'node:path';

export const REPO = resolve(import.meta.dirname, '../..');

/** Runs a command; returns its exit status and output together (stdout then stderr). */
export function run(command: string, args: string[], cwd: string, timeout = 120_000): { status: number; output: string } {
  const result = spawnSync(command, args, { cwd, encoding: 'utf8', timeout, env: { ...process.env, NO_COLOR: '1', FORCE_COLOR: '0' } });
  if (result.error) return { status: 1, output: String(result.error) };
  return { status: result.status ?? 1, output: `${result.stdout}${result.stderr}` };
}

/** {@link run}, without blocking: for commands that may run side by side. */
export function runAsync(command: string, args: string[], cwd: string, timeout = 120_000): Promise<{ status: number; output: string }> {
  return new Promise((done) => {
    execFile(command, args, { cwd, encoding: 'utf8', timeout, maxBuffer: 64 << 20, env: { ...process.env, NO_COLOR: '1', FORCE_COLOR: '0' } }, (error, stdout, stderr) => {
      const status = error ? (typeof error.code === 'number' ? error.code : 1) : 0;
      done({ status, output: `${stdout}${stderr}${error && typeof error.code !== 'number' ? String(error) : ''}` });
    });
  });
}

/** The README's code blocks tagged ```ts snippet=NAME, by name, as written. */
export function readmeSnippets(): Map<string, string> {
  const readme = readFileSync(join(REPO, 'README.md'), 'utf8');
  const snippets = new Map<string, string>();
  for (const match of readme.matchAll(/^```(?:ts|js|typescript|javascript) snippet=([\w-]+)[^\n]*\n([\s\S]*?)^```/gm)) {
    snippets.set(match[1], match[2]);
  }
  return snippets;
}

export interface Packed {
  /** The scratch directory (deleted by the caller). */
  root: string;
  tarball: string;
  /** The files in the tarball, without the leading `package/`. */
  files: string[];
  /** `npm pack`'s own report (prepack's build, the file list, the sizes). */
  packOutput: string;
}

/** `npm pack` of the working tree (its prepack builds dist/) into a new scratch directory. */
export function pack(): Packed {
  const root = mkdtempSync(join(tmpdir(), 'penumbra-package-'));
  const packDir = join(root, 'pack');
  mkdirSync(packDir);
  const packed = run('npm', ['pack', '--pack-destination', packDir, '--foreground-scripts'], REPO, 300_000);
  if (packed.status !== 0) throw new Error(`npm pack failed:\n${packed.output}`);
  const name = readdirSync(packDir).find((file) => file.endsWith('.tgz'));
  if (!name) throw new Error(`npm pack wrote no tarball:\n${packed.output}`);
  const tarball = join(packDir, name);
  const files = execFileSync('tar', ['-tzf', tarball], { encoding: 'utf8' }).split('\n').filter(Boolean).map((file) => file.replace(/^package\//, ''));
  return { root, tarball, files, packOutput: packed.output };
}

/** Packages the snippets need besides penumbra-gl, linked from this repository (peer dependencies and tools). */
const LINKED = ['pixi.js', 'phaser', 'vite', 'typescript', 'gl', '@types/node'];

/**
 * A Vite vanilla-ts project (the template's package.json, tsconfig and index.html, one page per
 * snippet) in `root/app`, with the tarball installed by npm (its dependency gl-matrix from npm's
 * cache when it holds it) and the packages above linked.
 */
export function createApp(root: string, tarball: string): { app: string; installOutput: string } {
  const app = join(root, 'app');
  mkdirSync(app);
  writeFileSync(join(app, 'package.json'), `${JSON.stringify({ name: 'lit-app', private: true, version: '0.0.0', type: 'module' }, null, 2)}\n`);
  const install = run('npm', ['install', tarball, '--prefer-offline', '--no-audit', '--no-fund', '--no-package-lock'], app, 300_000);
  if (install.status !== 0) throw new Error(`npm install of the tarball failed:\n${install.output}`);
  mkdirSync(join(app, 'node_modules', '@types'), { recursive: true });
  for (const name of LINKED) {
    symlinkSync(join(REPO, 'node_modules', name), join(app, 'node_modules', name), 'dir');
  }
  return { app, installOutput: install.output };
}

/** create-vite's vanilla-ts tsconfig (strict, noUnusedLocals/Parameters), with `moduleResolution` as asked. */
export function viteTsconfig(resolution: 'bundler' | 'node16' | 'nodenext', include: string[]): string {
  const bundler = resolution === 'bundler';
  return `${JSON.stringify({
    compilerOptions: {
      target: 'ES2022',
      useDefineForClassFields: true,
      module: bundler ? 'ESNext' : resolution === 'node16' ? 'Node16' : 'NodeNext',
      lib: ['ES2022', 'DOM', 'DOM.Iterable'],
      types: ['vite/client'],
      skipLibCheck: true,
      moduleResolution: bundler ? 'bundler' : resolution === 'node16' ? 'Node16' : 'NodeNext',
      ...(bundler ? { allowImportingTsExtensions: true } : {}),
      verbatimModuleSyntax: true,
      moduleDetection: 'force',
      noEmit: true,
      strict: true,
      noUnusedLocals: true,
      noUnusedParameters: true,
      erasableSyntaxOnly: true,
      noFallthroughCasesInSwitch: true,
      noUncheckedSideEffectImports: true,
    },
    include,
  }, null, 2)}\n`;
}

/** The template's index.html for a page whose module is `./main.ts`. */
export function indexHtml(title: string): string {
  return `<!doctype html>
<html lang="en">
  <head>
    <meta charset="UTF-8" />
    <link rel="icon" href="data:," />
    <meta name="viewport" content="width=device-width, initial-scale=1.0" />
    <title>${title}</title>
    <style>html, body { margin: 0; background: #000; }</style>
  </head>
  <body>
    <div id="app"></div>
    <script type="module" src="./main.ts"></script>
  </body>
</html>
`;
}
