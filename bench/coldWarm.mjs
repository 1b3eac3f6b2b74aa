// The harness the CPU benchmarks of hull building share (bench/hulls.mjs, tiles.mjs, alpha.mjs):
// each times a case cold, as the first call in a fresh Node process, and warm, as later calls in
// one process. A script runs itself again as the child: `--child=<case> --repeat=<k>` makes it
// measure in that process and print its result as JSON on its last line.
import { spawnSync } from 'node:child_process';

/** The `--key=value` (or bare `--key`) arguments as a map; a lone `--` (from `npm run x --`) is dropped. */
export function benchArgs() {
  return new Map(process.argv.slice(2).filter((arg) => arg !== '--').map((arg) => arg.replace(/^--/, '').split('=')));
}

/** The median of `values` (the upper one of an even count). */
export function median(values) {
  return [...values].sort((a, b) => a - b)[values.length >> 1];
}

/** Runs `script` as a child measuring case `name` `repeat` times; returns the JSON it printed last. */
export function runChild(script, name, repeat) {
  const run = spawnSync(process.execPath, [script, `--child=${name}`, `--repeat=${repeat}`], { encoding: 'utf8' });
  if (run.status !== 0) throw new Error(run.stderr);
  return JSON.parse(run.stdout.trim().split('\n').pop());
}
