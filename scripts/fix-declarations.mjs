#!/usr/bin/env node
// Makes tsc's declarations in dist/ resolve under every moduleResolution (bundler, node16, nodenext):
// - each relative specifier gets the extension Node needs (`./scene/Hull` → `./scene/Hull.js`, a folder
//   → `./folder/index.js`); without one, node16/nodenext resolve nothing and every type becomes `any`;
// - each `X.d.ts` gets a `X.d.cts` twin whose specifiers end in `.cjs`, the types of the CommonJS build
//   (a `.d.ts` in this `"type": "module"` package describes ES modules only).
// Run after `tsc -p tsconfig.build.json` (npm run build). Fails on a specifier it cannot resolve.
import { existsSync, readFileSync, readdirSync, writeFileSync } from 'node:fs';
import { dirname, join, relative, resolve } from 'node:path';

const root = resolve(import.meta.dirname, '..', 'dist');
// `from '…'`, `import '…'`, `import('…')`: every place a declaration names another module.
const SPECIFIER = /(\bfrom\s*|\bimport\s*\(\s*|\bimport\s+)(['"])(\.\.?\/[^'"]*|\.\.?)\2/g;

function declarationFiles(folder) {
  return readdirSync(folder, { withFileTypes: true }).flatMap((entry) => {
    const path = join(folder, entry.name);
    if (entry.isDirectory()) return declarationFiles(path);
    return entry.name.endsWith('.d.ts') ? [path] : [];
  });
}

/** `specifier` (relative to `file`) without extension, as `base` + `.js` or `base/index` + `.js`. */
function withoutExtension(file, specifier) {
  const bare = specifier.replace(/\.(js|cjs|mjs|ts)$/, '');
  const target = resolve(dirname(file), bare);
  if (existsSync(`${target}.d.ts`)) return bare;
  if (existsSync(join(target, 'index.d.ts'))) return `${bare.replace(/\/$/, '')}/index`;
  throw new Error(`${relative(root, file)}: cannot resolve '${specifier}' to a declaration file`);
}

const files = declarationFiles(root);
let rewritten = 0;
for (const file of files) {
  const source = readFileSync(file, 'utf8');
  const rewrite = (extension) => source.replace(SPECIFIER, (_, lead, quote, specifier) => {
    rewritten++;
    return `${lead}${quote}${withoutExtension(file, specifier)}${extension}${quote}`;
  });
  writeFileSync(file, rewrite('.js'));
  writeFileSync(file.replace(/\.d\.ts$/, '.d.cts'), rewrite('.cjs'));
}
console.log(`fix-declarations: ${files.length} declaration files, ${rewritten / 2} relative specifiers given extensions; .d.cts twins written`);
