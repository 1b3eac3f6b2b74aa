#!/usr/bin/env node
// Runs a command with an X display, which headless-gl's WebGL2 context needs: directly when
// DISPLAY is set, otherwise under xvfb-run. Before anything runs it checks what the tests need and
// stops at once, naming what is missing and the command that installs it:
//   with-display.mjs vitest run …     Xvfb (or DISPLAY) and headless-gl's addon; Chromium too,
//                                     unless every file filter lies in test/unit or test/gl
//   with-display.mjs --check [cmd …]  the same checks for that command (without one: for the
//                                     whole suite), then exits without running anything
import { spawnSync } from 'node:child_process';
import { existsSync } from 'node:fs';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';

const ROOT = join(dirname(fileURLToPath(import.meta.url)), '..');
/** Where test/browser/chromium.ts looks for Chromium. */
const CHROMIUM_PATH = process.env.PUPPETEER_EXECUTABLE_PATH ?? '/usr/bin/chromium';

const args = process.argv.slice(2);
const checkOnly = args[0] === '--check';
const command = checkOnly ? args.slice(1) : args;
if (!checkOnly && command.length === 0) {
  console.error('usage: with-display.mjs [--check] <command> [args…]');
  process.exit(2);
}

const missing = missingRequirements(command.length === 0 || needsChromium(command));
if (missing.length > 0) {
  console.error(setupMessage(missing));
  process.exit(1);
}
if (checkOnly) process.exit(0);

const [program, programArgs] = process.env.DISPLAY
  ? ['npx', command]
  : ['xvfb-run', ['-a', '-s', '-screen 0 1280x1024x24', 'npx', ...command]];
const result = spawnSync(program, programArgs, { stdio: 'inherit' });
process.exit(result.status ?? 1);

/** Whether the command may run test/browser or test/package files, which drive Chromium. */
function needsChromium(commandLine) {
  if (commandLine[0] !== 'vitest') return false;
  const filters = commandLine.slice(1).filter((arg) => !arg.startsWith('-') && arg !== 'run');
  return !(filters.length > 0 && filters.every((filter) => /^(\.\/)?test\/(unit|gl)(\/|$)/.test(filter)));
}

/** What is missing, each with the Debian packages that provide it and another way to satisfy it. */
function missingRequirements(chromium) {
  const missing = [];
  const hasXvfb = spawnSync('sh', ['-c', 'command -v xvfb-run && command -v xauth'], { stdio: 'ignore' }).status === 0;
  if (!process.env.DISPLAY && !hasXvfb) {
    missing.push({ what: 'Xvfb (xvfb-run and xauth), for the X display headless-gl renders with', packages: ['xvfb', 'xauth'], or: 'set DISPLAY to a running X server' });
  }
  if (chromium && !existsSync(CHROMIUM_PATH)) {
    missing.push({ what: `Chromium at ${CHROMIUM_PATH}, for the browser and package tests`, packages: ['chromium'], or: 'set PUPPETEER_EXECUTABLE_PATH to a Chromium or Chrome binary' });
  }
  if (!existsSync(join(ROOT, 'node_modules/gl/build/Release/webgl.node'))) {
    missing.push({
      what: "headless-gl's native addon (node_modules/gl/build/Release/webgl.node), built when npm installs gl",
      packages: ['build-essential', 'python3', 'pkg-config', 'libx11-dev', 'libxi-dev', 'libxext-dev', 'libglu1-mesa-dev', 'libglew-dev'],
      then: '(cd node_modules/gl && npx node-gyp rebuild)',
    });
  }
  return missing;
}

function setupMessage(missing) {
  const packages = [...new Set(missing.flatMap((item) => item.packages))];
  const lines = ['The tests cannot run on this machine yet. Missing:'];
  for (const item of missing) lines.push(`  - ${item.what}${item.or ? ` (or ${item.or})` : ''}`);
  lines.push('', 'On Debian, as root:', `  apt-get update && apt-get install -y ${packages.join(' ')}`);
  for (const item of missing) if (item.then) lines.push(`then, in this repository: ${item.then}`);
  lines.push('(.ci/run does all of this on a fresh Debian machine.)');
  return lines.join('\n');
}
