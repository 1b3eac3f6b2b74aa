import { resolve } from 'node:path';
import { defineConfig } from 'vite';

// Library build: ESM only, shaders inlined through `?raw` imports, gl-matrix left to the user's bundler.
export default defineConfig({
  build: {
    outDir: 'dist',
    emptyOutDir: true,
    sourcemap: true,
    lib: {
      entry: { index: resolve(import.meta.dirname, 'src/index.ts') },
      formats: ['es'],
    },
    rollupOptions: { external: [/^gl-matrix/] },
  },
});
