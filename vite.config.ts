import { resolve } from 'node:path';
import { defineConfig } from 'vite';
import { stripGlslComments } from './scripts/glsl-comments.mjs';

// Library build: the core and one entry per engine integration, as ES modules (.js) and CommonJS
// (.cjs, for require() and Jest), shaders inlined through `?raw` imports (without their comments),
// gl-matrix left to the user's bundler. Source maps embed their sources (sourcesContent), so they need nothing outside dist/.
// The declarations come from `tsc -p tsconfig.build.json` and scripts/fix-declarations.mjs.
// Minified with function and class names kept (`Function.prototype.name`), so stack traces and
// devtools name PenumbraRenderer, Hull, … rather than the mangler's one-letter names.
const KEEP_NAMES = { function: true, class: true };

export default defineConfig({
  plugins: [stripGlslComments()],
  build: {
    outDir: 'dist',
    emptyOutDir: true,
    sourcemap: true,
    lib: {
      entry: {
        index: resolve(import.meta.dirname, 'src/index.ts'),
        pixi: resolve(import.meta.dirname, 'src/integrations/pixi/index.ts'),
        phaser: resolve(import.meta.dirname, 'src/integrations/phaser/index.ts'),
      },
      formats: ['es', 'cjs'],
      fileName: (format, entryName) => `${entryName}.${format === 'es' ? 'js' : 'cjs'}`,
    },
    rolldownOptions: {
      // The engines are peer dependencies: the integrations import them, the bundle never holds them.
      external: [/^gl-matrix/, /^pixi\.js/, /^phaser$/],
      output: { minify: { compress: { keepNames: KEEP_NAMES }, mangle: { keepNames: KEEP_NAMES } } },
    },
  },
});
