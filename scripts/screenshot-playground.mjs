#!/usr/bin/env node
// Writes docs/playground.png and prints the stress preset's overlay figures, from the built
// playground (npm run build:demo) in Chromium. Runs the TypeScript capture through Vite's module
// runner, so it shares the test suite's Chromium launcher and static server.
import { resolve } from 'node:path';
import { runnerImport } from 'vite';

await runnerImport(resolve(import.meta.dirname, 'capturePlayground.ts'));
