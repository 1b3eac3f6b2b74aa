#!/usr/bin/env node
// Writes docs/playground.png (the editor on the Dungeon preset) and docs/showcase.png (the showcase
// level as a game shows it, the README's picture), and prints the showcase's and the stress
// preset's overlay figures, from the built playground (npm run build:demo) in Chromium. Runs the
// TypeScript capture through Vite's module runner, so it shares the test suite's Chromium launcher
// and static server. Options: --showcase (only docs/showcase.png), --daylight=0..1 (its time of
// day, default night), --out=path (where it goes).
import { resolve } from 'node:path';
import { runnerImport } from 'vite';

await runnerImport(resolve(import.meta.dirname, 'capturePlayground.ts'));
