import { readdirSync, readFileSync, statSync } from 'node:fs';
import { join, relative } from 'node:path';
import { describe, expect, it } from 'vitest';

/**
 * What ANGLE's Metal backend (Safari on macOS, iPadOS and iOS) handles badly, kept out of every
 * program: `flat` varyings, whose provoking-vertex rule it emulates by rewriting the index buffer
 * with a GPU→CPU sync on every draw (maplibre-gl-js removed theirs after it hung iPadOS 16 Safari's
 * GPU process, and keeps a test like this one), and triangle fans, which it converts on the CPU.
 * Read from the sources: the shader files and the GLSL and draw calls inside TypeScript.
 */
const root = join(import.meta.dirname, '..', '..');

function filesUnder(folder: string, extensions: readonly string[]): string[] {
  const found: string[] = [];
  for (const name of readdirSync(folder)) {
    const path = join(folder, name);
    if (statSync(path).isDirectory()) found.push(...filesUnder(path, extensions));
    else if (extensions.some((extension) => name.endsWith(extension))) found.push(path);
  }
  return found;
}

/** Lines of `files` matching `pattern`, as `path:line: text`, comments left out. */
function offendingLines(files: readonly string[], pattern: RegExp): string[] {
  const lines: string[] = [];
  for (const file of files) {
    readFileSync(file, 'utf8').split('\n').forEach((line, i) => {
      const code = line.replace(/\/\/.*$/, '').replace(/^\s*\*.*$/, '');
      if (pattern.test(code)) lines.push(`${relative(root, file)}:${i + 1}: ${line.trim()}`);
    });
  }
  return lines;
}

const sources = [...filesUnder(join(root, 'shaders'), ['.glsl']), ...filesUnder(join(root, 'src'), ['.ts'])];

describe('shader portability', () => {
  it('has no flat varyings in any program', () => {
    expect(sources.length).toBeGreaterThan(20);
    expect(offendingLines(sources, /\bflat\s+(in|out|highp|mediump|lowp|smooth)?\s*\w+\s+\w+\s*;/)).toEqual([]);
  });

  it('draws no triangle fans', () => {
    expect(offendingLines(sources, /TRIANGLE_FAN/)).toEqual([]);
  });
});
