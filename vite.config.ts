import { resolve } from 'node:path';
import { defineConfig } from 'vite';

// Library build: ESM only, the core and one entry per engine integration, shaders inlined through `?raw` imports, gl-matrix left to the user's bundler.
export default defineConfig({
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
      formats: ['es'],
    },
    // The engines are peer dependencies: the integrations import them, the bundle never holds them.
    rollupOptions: { external: [/^gl-matrix/, /^pixi\.js/, /^phaser$/] },
  },
});
