/**
 * What `hullsFromAlpha` costs on a 256 × 256 sprite: a blob with soft (antialiased) edges, a hole,
 * a thin handle and a few islands. Run by `bench/alpha.mjs` through Vite's module runner, from the
 * sources. `--child --repeat=k` times k calls in this process and prints them (ms) as JSON:
 * the first is cold (the code not yet optimized, as for the first sprite a game loads).
 */
import { alphaOutlines } from '../src/geometry/alphaOutlines';
import { hullsFromAlpha, type AlphaImage } from '../src/scene/hullsFromAlpha';

/** The benchmark sprite, `size` × `size` pixels, RGBA. */
export function benchSprite(size = 256): AlphaImage {
  const data = new Uint8ClampedArray(size * size * 4);
  const s = size / 100;
  for (let py = 0; py < size; py++) {
    for (let px = 0; px < size; px++) {
      const x = (px + 0.5) / s, y = (py + 0.5) / s;
      const angle = Math.atan2(y - 52, x - 45);
      const rim = 32 + 3 * Math.sin(5 * angle) + 1.5 * Math.sin(13 * angle) - Math.hypot(x - 45, y - 52);
      let alpha = 128 + 60 * s * rim;
      if (Math.hypot(x - 38, y - 45) < 7) alpha = 0;
      if (x > 74 && x < 94 && Math.abs(y - 52) < 1) alpha = 255;
      if (Math.hypot(x - 86, y - 14) < 7 || Math.hypot(x - 10, y - 90) < 4 || Math.hypot(x - 90, y - 90) < 2) alpha = 255;
      const i = 4 * (py * size + px);
      data[i] = 200;
      data[i + 1] = 120;
      data[i + 2] = 40;
      data[i + 3] = Math.max(0, Math.min(255, alpha));
    }
  }
  return { data, width: size, height: size };
}

const args = new Map(process.argv.slice(2).map((arg) => arg.replace(/^--/, '').split('=') as [string, string]));
if (args.has('child')) {
  const repeat = Number(args.get('repeat') ?? 1), what = args.get('child');
  const sprite = benchSprite();
  const times: number[] = [];
  let hulls = 0, points = 0;
  for (let k = 0; k < repeat; k++) {
    const start = performance.now();
    if (what === 'outlines') {
      const outlines = alphaOutlines(sprite.data, sprite.width, sprite.height, 128, { tolerance: 1, maxPoints: 64, minArea: 0 });
      times.push(performance.now() - start);
      hulls = outlines.length;
      points = outlines.reduce((sum, coords) => sum + coords.length / 2, 0);
    } else {
      const made = hullsFromAlpha(sprite, { scale: 0.5, position: [100, 100] });
      times.push(performance.now() - start);
      if (!made.every((hull) => hull.valid)) throw new Error('a hull came out invalid');
      hulls = made.length;
      points = made.reduce((sum, hull) => sum + hull.points.length, 0);
    }
  }
  console.log(JSON.stringify({ times, hulls, points }));
}
