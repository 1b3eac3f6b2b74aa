/**
 * What `hullsFromAlpha` costs: on a 256 × 256 sprite (a blob with soft, antialiased edges, a hole,
 * a thin handle and a few islands), and on comb-like sprites whose outlines are long and zigzag
 * (a grass strip, a comb, a fence). Run by `bench/alpha.mjs` through Vite's module runner, from
 * the sources. `--child=<case> --repeat=k` times k calls in this process and prints them (ms) as
 * JSON: the first is cold (the code not yet optimized, as for the first sprite a game loads).
 */
import { alphaOutlines } from '../src/geometry/alphaOutlines';
import { hullsFromAlpha, type AlphaImage } from '../src/scene/hullsFromAlpha';

/** The benchmark sprite, `size` × `size` pixels, RGBA. */
function benchSprite(size = 256): AlphaImage {
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

/** An opaque-or-clear RGBA image, `solid(x, y)` deciding each pixel. */
function maskImage(width: number, height: number, solid: (x: number, y: number) => boolean): AlphaImage {
  const data = new Uint8ClampedArray(width * height * 4);
  for (let y = 0; y < height; y++) for (let x = 0; x < width; x++) data[4 * (y * width + x) + 3] = solid(x, y) ? 255 : 0;
  return { data, width, height };
}

/** A 2,048 × 64 grass strip: 1-pixel blades 1 pixel apart, 16 to 62 pixels tall, on a 2-pixel base. */
function grassSprite(): AlphaImage {
  const height = 64;
  return maskImage(2048, height, (x, y) => y >= height - 2 || (x % 2 === 0 && y >= 1 + ((x * 7919) % 47)));
}

/** A 2,048 × 512 comb: 1-pixel teeth 1 pixel apart, 504 pixels long, hanging from an 8-pixel spine. */
function combSprite(): AlphaImage {
  return maskImage(2048, 512, (x, y) => y < 8 || x % 2 === 0);
}

/** A 2,048 × 512 fence: 4-pixel bars 4 pixels apart, joined by two 8-pixel rails (so with holes). */
function fenceSprite(): AlphaImage {
  return maskImage(2048, 512, (x, y) => x % 8 < 4 || (y >= 96 && y < 104) || (y >= 400 && y < 408));
}

/** The cases: the sprite's outlines alone (splitting, tracing, simplifying), then whole hulls (validation, triangulation too). */
export const CASES: Record<string, { sprite: () => AlphaImage; outlinesOnly?: boolean; describe: string }> = {
  outlines: { sprite: benchSprite, outlinesOnly: true, describe: '256 × 256 sprite, outlines' },
  hullsFromAlpha: { sprite: benchSprite, describe: '256 × 256 sprite' },
  grass: { sprite: grassSprite, describe: '2,048 × 64 grass, 1-px blades' },
  comb: { sprite: combSprite, describe: '2,048 × 512 comb, 1-px teeth' },
  fence: { sprite: fenceSprite, describe: '2,048 × 512 fence, 4-px bars, 2 rails' },
};

const args = new Map(process.argv.slice(2).map((arg) => arg.replace(/^--/, '').split('=') as [string, string]));
if (args.has('child')) {
  const repeat = Number(args.get('repeat') ?? 1), bench = CASES[args.get('child')!];
  const sprite = bench.sprite();
  const times: number[] = [];
  let hulls = 0, points = 0;
  for (let k = 0; k < repeat; k++) {
    const start = performance.now();
    if (bench.outlinesOnly) {
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
