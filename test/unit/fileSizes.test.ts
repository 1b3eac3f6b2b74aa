import { readdirSync, readFileSync, statSync } from 'node:fs';
import { join, relative, resolve } from 'node:path';
import { describe, expect, it } from 'vitest';

/**
 * Files a maintainer can read whole (DEVELOPING.md, "The layer rule"): the public renderer at most 450 lines (its API:
 * each call a check and a delegation), every other source file at most 600. A file that grows past
 * its bound is split along a seam of its own.
 */
const SRC = resolve(import.meta.dirname, '../../src');
const RENDERER = 'PenumbraRenderer.ts';
const RENDERER_LINES = 450;
const FILE_LINES = 600;

function sources(dir: string): string[] {
  return readdirSync(dir).flatMap((name) => {
    const path = join(dir, name);
    return statSync(path).isDirectory() ? sources(path) : name.endsWith('.ts') ? [path] : [];
  });
}

/** The files of `files` longer than their bound, as "path: lines > bound". */
function oversized(files: readonly { path: string; lines: number }[]): string[] {
  return files.flatMap(({ path, lines }) => {
    const bound = path === RENDERER ? RENDERER_LINES : FILE_LINES;
    return lines > bound ? [`${path}: ${lines} > ${bound}`] : [];
  });
}

describe('source file sizes', () => {
  it(`keeps ${RENDERER} within ${RENDERER_LINES} lines and every other file in src/ within ${FILE_LINES}`, () => {
    const files = sources(SRC).map((path) => ({ path: relative(SRC, path), lines: readFileSync(path, 'utf8').split('\n').length - 1 }));
    expect(files.length).toBeGreaterThan(50);
    expect(oversized(files)).toEqual([]);
  });

  it('catches a file one line over its bound', () => {
    expect(oversized([{ path: RENDERER, lines: RENDERER_LINES + 1 }, { path: 'shadow/RecordMarks.ts', lines: FILE_LINES + 1 }, { path: 'a.ts', lines: FILE_LINES }]))
      .toEqual([`${RENDERER}: ${RENDERER_LINES + 1} > ${RENDERER_LINES}`, `shadow/RecordMarks.ts: ${FILE_LINES + 1} > ${FILE_LINES}`]);
  });
});
