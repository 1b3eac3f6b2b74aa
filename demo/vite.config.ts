import { existsSync } from 'node:fs';
import { resolve } from 'node:path';
import { defineConfig } from 'vite';

const root = import.meta.dirname;
const src = resolve(root, '../src');

// Every page under demo/ with an index.html: the playground at the root, engine examples in folders.
const pages = ['index.html', 'pixi/index.html', 'phaser/index.html']
  .map((page) => resolve(root, page))
  .filter((page) => existsSync(page));

export default defineConfig({
  root,
  base: './',
  resolve: {
    // The demos use the package the way users import it, served from source.
    alias: [
      { find: /^penumbra-gl\/pixi$/, replacement: resolve(src, 'integrations/pixi/index.ts') },
      { find: /^penumbra-gl\/phaser$/, replacement: resolve(src, 'integrations/phaser/index.ts') },
      { find: /^penumbra-gl$/, replacement: resolve(src, 'index.ts') },
    ],
  },
  build: {
    outDir: resolve(root, '../demo-dist'),
    emptyOutDir: true,
    rolldownOptions: { input: pages },
  },
});
