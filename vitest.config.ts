import { resolve } from 'node:path';
import { defineConfig } from 'vitest/config';

export default defineConfig({
  test: {
    include: ['test/**/*.test.ts'],
    environment: 'node',
    testTimeout: 120_000,
    hookTimeout: 120_000,
    // headless-gl contexts and Chromium are heavy: one test file at a time keeps memory and timings
    // sane. The layers without GL (npm run test:unit, test:accuracy) run files in parallel instead,
    // one worker a core, and without isolation: a worker loads the sources once for all its files,
    // so a test there must not rely on module state (a cache, a counter) that another file left.
    fileParallelism: false,
    // In a terminal, vitest's live summary; in a log (CI, a pipe), each test as it ends and each file
    // as it starts and ends, so a long run is never silent.
    reporters: process.stdout.isTTY ? ['default'] : ['verbose', resolve(import.meta.dirname, 'test/progressReporter.ts')],
  },
});
