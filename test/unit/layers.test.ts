import { readdirSync, readFileSync, statSync } from 'node:fs';
import { dirname, join, relative, resolve } from 'node:path';
import { describe, expect, it } from 'vitest';

/**
 * The folders of src/ are layers: each may import only the layers below it (docs/architecture.md).
 * The renderer (the files at the top of src/ and src/frame/) may import any layer; integrations reach
 * the model only through the public API (src/index.ts), beside the GL helpers and passes an engine's
 * own drawing needs, and shared utilities.
 */
const ALLOWED: Readonly<Record<string, readonly string[]>> = {
  util: [],
  geometry: ['util'],
  scene: ['geometry', 'util'],
  format: ['scene', 'geometry', 'util'],
  gl: ['util'],
  shadow: ['scene', 'geometry', 'gl', 'util'],
  passes: ['shadow', 'scene', 'geometry', 'gl', 'util'],
  renderer: ['passes', 'shadow', 'scene', 'format', 'geometry', 'gl', 'util'],
  integrations: ['api', 'passes', 'gl', 'util'],
  api: ['renderer', 'passes', 'shadow', 'scene', 'format', 'geometry', 'gl', 'util'],
};

const SRC = resolve(import.meta.dirname, '../../src');

/** The layer of a file under src/: its top folder, `api` for the barrel, `renderer` for the rest of the top. */
function layerOf(file: string): string {
  const path = relative(SRC, file).split(/[\\/]/);
  if (path.length === 1) return path[0] === 'index.ts' ? 'api' : 'renderer';
  return path[0] === 'frame' ? 'renderer' : path[0];
}

function sourceFiles(dir: string): string[] {
  return readdirSync(dir).flatMap((name) => {
    const path = join(dir, name);
    if (statSync(path).isDirectory()) return sourceFiles(path);
    return path.endsWith('.ts') ? [path] : [];
  });
}

/** Relative imports in a source file's text that resolve inside src/, as absolute paths with `.ts`. */
function importsIn(file: string, text: string): string[] {
  const found: string[] = [];
  for (const match of text.matchAll(/(?:^|\n)\s*(?:import|export)\b[^'"]*?from\s+['"](\.[^'"]+)['"]/g)) {
    const target = resolve(dirname(file), match[1]);
    if (target.startsWith(SRC)) found.push(target.endsWith('.ts') ? target : `${target}.ts`);
  }
  return found;
}

/** Every import that goes against the layers, as `file → target (from layer → to layer)`. */
function backwardImports(file: string, text: string): string[] {
  const from = layerOf(file);
  return importsIn(file, text)
    .filter((target) => layerOf(target) !== from && !(ALLOWED[from] ?? []).includes(layerOf(target)))
    .map((target) => `${relative(SRC, file)} → ${relative(SRC, target)} (${from} → ${layerOf(target)})`);
}

describe('source layers', () => {
  const files = sourceFiles(SRC);

  it('every folder of src/ is a known layer', () => {
    for (const file of files) expect(Object.keys(ALLOWED)).toContain(layerOf(file));
  });

  it('no file imports a layer above its own', () => {
    expect(files.flatMap((file) => backwardImports(file, readFileSync(file, 'utf8')))).toEqual([]);
  });

  it('catches a backward import, and allows the same import downward', () => {
    const geometryFile = join(SRC, 'geometry', 'polygon.ts');
    const sceneFile = join(SRC, 'scene', 'Hull.ts');
    expect(backwardImports(geometryFile, "import { Hull } from '../scene/Hull';")).toEqual([
      'geometry/polygon.ts → scene/Hull.ts (geometry → scene)',
    ]);
    expect(backwardImports(sceneFile, "export { isSimplePolygon } from '../geometry/polygon';")).toEqual([]);
    expect(backwardImports(join(SRC, 'integrations', 'pixi', 'Occluder.ts'), "import type { Hull } from '../../scene/Hull';")).toHaveLength(1);
    expect(backwardImports(geometryFile, 'import type { Hull } from "../scene/Hull";')).toHaveLength(1);
  });
});
