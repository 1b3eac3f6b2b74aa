#!/usr/bin/env node
// `npm run bench:hulls`: what building large hulls costs on the CPU (validation, triangulation),
// from the built package (dist/). Each outline is timed twice: the first hull in a fresh Node
// process (the code still cold: V8 interprets it, as for the first level a game loads), median of
// several processes; and warm, median of later hulls in one process. A scene file's load (parse,
// check, build) is timed the same way.
//   npm run bench:hulls -- --runs=5
import { fileURLToPath } from 'node:url';
import { benchArgs, median, runChild } from './coldWarm.mjs';

const OUTLINES = {
  /** 10,000 spikes: half its points reflex, the sweep line crossing thousands of edges. */
  'star, 20,000 points': (n) => ring(n, (i) => (i % 2 ? 50 : 100)),
  /** A traced outline: a wobbly circle, like marching squares around a round sprite. */
  'traced blob, 20,000 points': (n) => ring(n, (i) => 100 + 3 * Math.sin((i * 2 * Math.PI * 40) / n)),
  /** Teeth: a sweep line crosses every tooth, the worst case for a grid of points. */
  'comb, 19,998 points': comb,
};
const POINTS = 20_000;

function ring(n, radius) {
  return Array.from({ length: n }, (_, i) => {
    const angle = (2 * Math.PI * i) / n;
    return [radius(i) * Math.cos(angle), radius(i) * Math.sin(angle)];
  });
}

function comb(n) {
  const teeth = Math.floor((n - 2) / 4), points = [];
  for (let t = 0; t < teeth; t++) points.push([4 * t, 0], [4 * t, 100], [4 * t + 2, 100], [4 * t + 2, 0]);
  points.push([4 * teeth, -10], [0, -10]);
  return points;
}

const args = benchArgs();
const runs = Number(args.get('runs') ?? 5);

if (args.has('child')) {
  // One measurement in this process: `--child=<outline>|scene --repeat=<k>` prints k times in ms.
  const { Hull, readScene, createSceneObjects, SCENE_FORMAT, SCENE_FORMAT_VERSION } = await import('../dist/index.js');
  const name = args.get('child'), repeat = Number(args.get('repeat') ?? 1);
  const points = OUTLINES[name.replace(/^scene: /, '')](POINTS);
  const file = name.startsWith('scene: ') ? JSON.stringify({ format: SCENE_FORMAT, version: SCENE_FORMAT_VERSION, hulls: [{ points }], lights: [] }) : null;
  const times = [];
  for (let k = 0; k < repeat; k++) {
    const start = performance.now();
    const hulls = file ? createSceneObjects(readScene(file), () => null).hulls : [new Hull(points)];
    if (!hulls[0].valid) throw new Error(`${name}: the hull came out invalid`);
    times.push(performance.now() - start);
  }
  console.log(JSON.stringify(times));
} else {
  const script = fileURLToPath(import.meta.url);
  const child = (name, repeat) => runChild(script, name, repeat);
  console.log(`| outline | first in a process, ms (median of ${runs}) | warm, ms (median of 10) |`);
  console.log('|---|---|---|');
  for (const outline of Object.keys(OUTLINES)) {
    for (const name of [outline, `scene: ${outline}`]) {
      const first = median(Array.from({ length: runs }, () => child(name, 1)[0]));
      const warm = median(child(name, 15).slice(5));
      console.log(`| ${name} | ${first.toFixed(0)} | ${warm.toFixed(0)} |`);
    }
  }
}
