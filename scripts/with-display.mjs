#!/usr/bin/env node
// Runs a command with an X display, which headless-gl's WebGL2 context needs: directly when
// DISPLAY is set, otherwise under xvfb-run. Fails with the install hint when Xvfb is missing.
import { spawnSync } from 'node:child_process';

const command = process.argv.slice(2);
if (command.length === 0) {
  console.error('usage: with-display.mjs <command> [args…]');
  process.exit(2);
}
const hasXvfb = spawnSync('sh', ['-c', 'command -v xvfb-run'], { stdio: 'ignore' }).status === 0;
if (!process.env.DISPLAY && !hasXvfb) {
  console.error('headless-gl needs an X display: install Xvfb (as root: apt-get install -y xvfb) or set DISPLAY.');
  process.exit(1);
}
const [program, args] = process.env.DISPLAY
  ? ['npx', command]
  : ['xvfb-run', ['-a', '-s', '-screen 0 1280x1024x24', 'npx', ...command]];
const result = spawnSync(program, args, { stdio: 'inherit' });
process.exit(result.status ?? 1);
