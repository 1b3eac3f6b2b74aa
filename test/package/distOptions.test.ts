import { existsSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { testLibrary, type Library } from '../unit/optionMessages';

/**
 * The built bundle, minified as it ships: its messages must name the public classes too, as the
 * sources' do (test/unit/options.test.ts). `npm run test:package` builds it first; run
 * `npm run build` before running this file alone.
 */
const DIST_ENTRY = new URL('../../dist/index.js', import.meta.url);

const distLibrary = existsSync(DIST_ENTRY) ? ((await import(/* @vite-ignore */ DIST_ENTRY.href)) as Library) : undefined;

testLibrary('dist', () => {
  if (!distLibrary) throw new Error(`${fileURLToPath(DIST_ENTRY)} is missing: run npm run build first`);
  return distLibrary;
});
