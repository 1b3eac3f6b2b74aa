// The test suite's own tooling, run as a contributor or CI runs it: npm test's layers, vitest with
// this repository's config writing to a pipe (no terminal), and the set-up check of
// scripts/with-display.mjs on a machine without Xvfb or Chromium.
import { spawn, spawnSync } from 'node:child_process';
import { mkdirSync, mkdtempSync, readdirSync, readFileSync, rmSync, symlinkSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join, resolve } from 'node:path';
import { describe, expect, it } from 'vitest';

const REPO = resolve(import.meta.dirname, '../..');

/** The environment of a child vitest: without the variables that mark it as running inside vitest. */
function plainEnvironment(): NodeJS.ProcessEnv {
  return Object.fromEntries(Object.entries(process.env).filter(([key]) => !key.startsWith('VITEST') && key !== 'NODE_ENV' && key !== 'TEST'));
}

describe('npm test', () => {
  it('runs every test file: each lies in a folder that one of the layer scripts it runs gives vitest', () => {
    const scripts = (JSON.parse(readFileSync(join(REPO, 'package.json'), 'utf8')) as { scripts: Record<string, string> }).scripts;
    const layers = [...scripts.test.matchAll(/npm run (test:[\w-]+)/g)].map(([, name]) => name);
    const folders = layers.flatMap((name) => scripts[name].match(/vitest run ([^&]*)/)?.[1].split(' ').filter((arg) => arg.startsWith('test/')) ?? []);
    expect(layers).toEqual(['test:unit', 'test:accuracy', 'test:gl', 'test:browser', 'test:package']);
    const files = (readdirSync(join(REPO, 'test'), { recursive: true }) as string[])
      .map((file) => `test/${file.split('\\').join('/')}`)
      .filter((file) => file.endsWith('.test.ts'));
    expect(files.filter((file) => !folders.some((folder) => file.startsWith(`${folder.replace(/\/$/, '')}/`)))).toEqual([]);
    // Every layer holds tests.
    for (const folder of folders) expect(files.some((file) => file.startsWith(`${folder}/`)), folder).toBe(true);
  });
});

describe('vitest without a terminal', () => {
  it('prints each file as it starts and as it ends, numbered, while the run goes on', async () => {
    const root = mkdtempSync(join(tmpdir(), 'penumbra-progress-'));
    try {
      symlinkSync(join(REPO, 'node_modules'), join(root, 'node_modules'), 'dir');
      mkdirSync(join(root, 'test'));
      for (const name of ['first', 'second']) {
        writeFileSync(join(root, 'test', `${name}.test.ts`), `import { expect, it } from 'vitest';
it('${name} waits', async () => {
  await new Promise((done) => setTimeout(done, 1500));
  expect(1).toBe(1);
});
`);
      }
      const lines: { text: string; at: number }[] = [];
      const exitedAt = await new Promise<number>((done, fail) => {
        const child = spawn(process.execPath, [join(REPO, 'node_modules/vitest/vitest.mjs'), 'run', '--config', join(REPO, 'vitest.config.ts'), '--root', root], {
          cwd: root, env: { ...plainEnvironment(), NO_COLOR: '1', FORCE_COLOR: '0' }, stdio: ['ignore', 'pipe', 'pipe'],
        });
        let pending = '';
        child.stdout.on('data', (chunk: Buffer) => {
          const parts = (pending + chunk.toString('utf8')).split('\n');
          pending = parts.pop()!;
          for (const text of parts) lines.push({ text, at: Date.now() });
        });
        child.on('error', fail);
        child.on('close', () => done(Date.now()));
      });
      const texts = lines.map((line) => line.text);
      const starts = texts.filter((text) => /^▶ \[\d\/2\] test\/(first|second)\.test\.ts started$/.test(text));
      const ends = lines.filter((line) => /^✓ \[\d\/2\] test\/(first|second)\.test\.ts: 1 passed, 0 failed, 0 skipped in \d+\.\d s$/.test(line.text));
      expect(starts, texts.join('\n')).toHaveLength(2);
      expect(ends, texts.join('\n')).toHaveLength(2);
      expect(texts.filter((text) => /✓ test\/(first|second)\.test\.ts > (first|second) waits/.test(text)), 'verbose: each test on its line').toHaveLength(2);
      // The first file's line arrives while the second file still runs (1.5 s), not with the summary.
      expect(exitedAt - ends[0].at).toBeGreaterThan(700);
    } finally {
      rmSync(root, { recursive: true, force: true });
    }
  }, 120_000);
});

describe('scripts/with-display.mjs on a machine without Xvfb or Chromium', () => {
  /** A PATH with node and sh only (no xvfb-run, no xauth), no DISPLAY, and Chromium looked for where it is not. */
  function bareMachine(): NodeJS.ProcessEnv {
    const bin = mkdtempSync(join(tmpdir(), 'penumbra-bare-bin-'));
    symlinkSync(process.execPath, join(bin, 'node'));
    symlinkSync('/bin/sh', join(bin, 'sh'));
    const env: NodeJS.ProcessEnv = { ...plainEnvironment(), PATH: bin, PUPPETEER_EXECUTABLE_PATH: join(bin, 'no-chromium') };
    delete env.DISPLAY;
    return env;
  }

  it('--check stops at once with the apt-get command that installs Xvfb and Chromium', () => {
    const result = spawnSync(process.execPath, [join(REPO, 'scripts/with-display.mjs'), '--check'], { cwd: REPO, env: bareMachine(), encoding: 'utf8', timeout: 30_000 });
    expect(result.status).toBe(1);
    expect(result.stderr).toContain('Xvfb (xvfb-run and xauth)');
    expect(result.stderr).toContain('Chromium at ');
    expect(result.stderr).toContain('apt-get update && apt-get install -y xvfb xauth chromium');
  });

  it('a browser test is refused before vitest starts; test/unit and test/gl need no Chromium', () => {
    const env = { ...bareMachine(), DISPLAY: ':99' };
    const browser = spawnSync(process.execPath, [join(REPO, 'scripts/with-display.mjs'), 'vitest', 'run', 'test/browser/pixi.test.ts'], { cwd: REPO, env, encoding: 'utf8', timeout: 30_000 });
    expect(browser.status).toBe(1);
    expect(browser.stderr).toContain('apt-get update && apt-get install -y chromium');
    expect(browser.stdout).toBe('');
    const unit = spawnSync(process.execPath, [join(REPO, 'scripts/with-display.mjs'), '--check', 'vitest', 'run', 'test/unit', 'test/gl/'], { cwd: REPO, env, encoding: 'utf8', timeout: 30_000 });
    expect(unit.stderr).toBe('');
    expect(unit.status).toBe(0);
  });
});
