import { existsSync, readdirSync, readFileSync, statSync } from 'node:fs';
import { join, resolve } from 'node:path';
import { describe, expect, it } from 'vitest';

/**
 * The maintainers' guides name code: every name in backticks must exist, so that a rename that
 * forgets a guide fails here. A span is checked by its shape: `npm run x` (a script of package.json),
 * a path (a file or folder of the repository; `*` matches within a name; a build output listed in
 * .gitignore counts, since a fresh clone has not built it), or an identifier, possibly
 * dotted or called (`HostFrame.enter`, `draw()`: each part must occur as a word in the sources).
 * Other spans (expressions, values, options) are not names and are left alone, as are fenced blocks.
 */
const ROOT = resolve(import.meta.dirname, '../..');
const GUIDES = ['docs/architecture.md', 'DEVELOPING.md'];
const SOURCE_FOLDERS = ['src', 'shaders', 'test', 'bench', 'scripts', 'demo', '.ci'];
const SKIPPED = new Set(['node_modules', '.build', 'results', 'dist']);

function files(dir: string): string[] {
  if (!existsSync(dir)) return [];
  return readdirSync(dir).flatMap((name) => {
    const path = join(dir, name);
    if (statSync(path).isDirectory()) return SKIPPED.has(name) ? [] : files(path);
    return /\.(ts|mjs|js|glsl|sh|json|html)$/.test(name) || name === 'run' ? [path] : [];
  });
}

const sources = SOURCE_FOLDERS.flatMap((folder) => files(join(ROOT, folder)))
  .filter((path) => path !== import.meta.filename).map((path) => readFileSync(path, 'utf8')).join('\n')
  + readFileSync(join(ROOT, 'package.json'), 'utf8');
const scripts = (JSON.parse(readFileSync(join(ROOT, 'package.json'), 'utf8')) as { scripts: Record<string, string> }).scripts;

/** The spans in backticks of `text`, fenced blocks left out. */
function codeSpans(text: string): string[] {
  return [...text.replace(/```[\s\S]*?```/g, '').matchAll(/`([^`\n]+)`/g)].map((match) => match[1].trim());
}

/** Every file and folder of the repository, relative to its root, outside the skipped folders. */
function entries(dir: string, prefix = ''): string[] {
  return readdirSync(dir).flatMap((name) => {
    if (SKIPPED.has(name) || name === '.git') return [];
    const path = join(dir, name), relativePath = prefix + name;
    return statSync(path).isDirectory() ? [relativePath, ...entries(path, `${relativePath}/`)] : [relativePath];
  });
}
const repository = entries(ROOT);
const buildOutputs = readFileSync(join(ROOT, '.gitignore'), 'utf8').split('\n').map((line) => line.trim())
  .filter((line) => line.endsWith('/')).map((line) => line.replace(/\/$/, ''));

/** Whether `path` is a file or folder of the repository, given from its root or by its last parts (`passes/LightPass.ts`). */
function pathExists(path: string): boolean {
  const trimmed = path.replace(/\/$/, '');
  if (existsSync(join(ROOT, trimmed)) || buildOutputs.includes(trimmed)) return true;
  const pattern = new RegExp(`(^|/)${trimmed.replace(/[.]/g, '\\.').replace(/\*/g, '[^/]*')}$`);
  return repository.some((entry) => pattern.test(entry));
}

/** Why `span` names nothing that exists, or null when it does or is not a name. */
function missingName(span: string): string | null {
  const script = /^npm run ([\w:-]+)/.exec(span);
  if (script) return scripts[script[1]] === undefined ? `no script "${script[1]}" in package.json` : null;
  if (/^\.?[\w.-]+(\/[\w.*-]+)+\/?$/.test(span) || /^[\w-]+\.(md|ts|glsl|json|mjs|js)$/.test(span)) {
    return pathExists(span) ? null : `no file or folder ${span}`;
  }
  const identifier = /^([A-Za-z_]\w*(\.[A-Za-z_]\w*)*)(\(\))?$/.exec(span);
  if (!identifier) return null;
  const missing = identifier[1].split('.').filter((part) => !new RegExp(`\\b${part}\\b`).test(sources));
  return missing.length > 0 ? `${missing.join(', ')} not found in the sources` : null;
}

describe('maintainer guides', () => {
  for (const guide of GUIDES) {
    it(`${guide} names only what exists`, () => {
      const spans = codeSpans(readFileSync(join(ROOT, guide), 'utf8'));
      expect(spans.length).toBeGreaterThan(10);
      const wrong = spans.flatMap((span) => {
        const why = missingName(span);
        return why ? [`\`${span}\`: ${why}`] : [];
      });
      expect(wrong).toEqual([]);
    });
  }

  it('catches a renamed identifier, a missing file and a missing script', () => {
    expect(missingName('ShadowCache.build')).toBeNull();
    expect(missingName('FramePlanThatWasRenamed.build')).toMatch(/not found/);
    expect(missingName('src/frame/FramePipeline.ts')).toBeNull();
    expect(missingName('src/frame/Gone.ts')).toMatch(/no file/);
    expect(missingName('shaders/light-*.frag.glsl')).toBeNull();
    expect(missingName('npm run test:unit')).toBeNull();
    expect(missingName('npm run test:nothing')).toMatch(/no script/);
    expect(missingName('layers | 0')).toBeNull();
  });
});
