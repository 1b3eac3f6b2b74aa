import { defineConfig } from 'vitest/config';

export default defineConfig({
  test: {
    include: ['test/**/*.test.ts'],
    environment: 'node',
    testTimeout: 120_000,
    hookTimeout: 120_000,
    // headless-gl contexts and Chromium are heavy: one test file at a time keeps memory and timings sane.
    fileParallelism: false,
  },
});
