import { CURRENT, type BenchHull, type BenchLight } from '../library';
import { WORLD_HEIGHT, WORLD_WIDTH } from '../scenes';
import { measureShadowStatistics } from './statistics';

/** One configuration of the micro-benchmark: its frame time and what its shadow loop did. */
export interface MicroRow {
  name: string;
  /** Median of the timed frames, ms. */
  frame: number;
  pixels: number;
  visits: number;
  decidedWithoutLoop: number;
}

/** The rows, and the costs fitted to them. */
export interface MicroResult {
  rows: MicroRow[];
  /** Extra cost of a light pixel whose loop makes no trip (bin and first entry fetched), ns. */
  zeroTripPixel: number;
  /** Cost per record visited (least squares over the ring configurations), ns. */
  perVisit: number;
}

const CENTRE: readonly [number, number] = [WORLD_WIDTH / 2, WORLD_HEIGHT / 2];
/** Covers the whole world: every pixel is a light pixel. */
const RANGE = 800;
const RADIUS = 4;
/** Ring hulls: 1-unit squares this far from the light, too small to make any pixel dark (the loop never stops early). */
const RING_DISTANCE = 40;
const RING_SIZES = [16, 32, 64, 128];

/**
 * The inner loop's cost, for the estimates the shadow core rests on: one light over the whole
 * world (1280 × 720 light pixels), drawn with
 * - no hull (the light pass without the shadow chunk);
 * - one hull far off screen: the shadowed program, every pixel's bin holds nothing nearer than itself
 *   (0 trips: the bin, and for some the first entry, fetched);
 * - rings of N tiny hulls around the light: pixels beyond the ring visit the records in their bin
 *   (counted by the statistics build), each hiding a sliver of the disk, never all of it.
 * The frame times are renderLightmap + a 1-pixel read, median of `frames`. One configuration per
 * call, so that no call outlasts the DevTools protocol's timeout.
 */
export const MICRO_CONFIGURATIONS: readonly { name: string; hulls: () => BenchHull[] }[] = [
  { name: 'no hull', hulls: () => [] },
  { name: '0 trips (one hull off screen)', hulls: () => [square(CENTRE[0] + RANGE - 10, CENTRE[1], 2)] },
  ...RING_SIZES.map((count) => ({ name: `ring of ${count} tiny hulls`, hulls: () => ring(count) })),
];

/** Measures configuration `index` of {@link MICRO_CONFIGURATIONS}. */
export function measureMicroRow(gl: WebGL2RenderingContext, index: number, frames: number): MicroRow {
  const { name, hulls } = MICRO_CONFIGURATIONS[index];
  return measure(gl, name, hulls(), frames);
}

/** Fits the costs to rows measured in the order of {@link MICRO_CONFIGURATIONS}. */
export function fitMicro(rows: MicroRow[]): MicroResult {
  const noHull = rows[0], zeroTrip = rows[1], rings = rows.slice(2);
  const zeroTripPixel = ((zeroTrip.frame - noHull.frame) / zeroTrip.pixels) * 1e6;
  // frame = zeroTrip.frame + perVisit × visits: least squares through that point.
  let numerator = 0, denominator = 0;
  for (const row of rings) {
    numerator += (row.frame - zeroTrip.frame) * row.visits;
    denominator += row.visits * row.visits;
  }
  return { rows, zeroTripPixel, perVisit: (numerator / denominator) * 1e6 };
}

function measure(gl: WebGL2RenderingContext, name: string, hulls: BenchHull[], frames: number): MicroRow {
  const light = (): BenchLight => new CURRENT.PointLight({ position: CENTRE, range: RANGE, radius: RADIUS });
  const renderer = new CURRENT.PenumbraRenderer(gl, { ambientColor: [0, 0, 0] });
  renderer.addLight(light());
  for (const hull of hulls) renderer.addHull(hull);
  const pixel = new Float32Array(4);
  const times: number[] = [];
  const framebuffer = gl.createFramebuffer();
  try {
    for (let frame = 0; frame < frames + 1; frame++) {
      const start = performance.now();
      renderer.renderLightmap();
      gl.bindFramebuffer(gl.FRAMEBUFFER, framebuffer);
      gl.framebufferTexture2D(gl.FRAMEBUFFER, gl.COLOR_ATTACHMENT0, gl.TEXTURE_2D, (renderer as unknown as { lightmapTexture: WebGLTexture }).lightmapTexture, 0);
      gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.FLOAT, pixel);
      gl.bindFramebuffer(gl.FRAMEBUFFER, null);
      if (frame > 0) times.push(performance.now() - start);
    }
  } finally {
    gl.deleteFramebuffer(framebuffer);
    renderer.dispose();
  }
  times.sort((a, b) => a - b);
  const statistics = measureShadowStatistics(gl, {}, [light()], hulls);
  return { name, frame: times[times.length >> 1], ...statistics };
}

function square(x: number, y: number, size: number): BenchHull {
  return new CURRENT.Hull([[0, 0], [size, 0], [size, size], [0, size]], { position: [x - size / 2, y - size / 2] });
}

function ring(count: number): BenchHull[] {
  return Array.from({ length: count }, (_, i) => {
    const angle = (2 * Math.PI * i) / count;
    return square(CENTRE[0] + RING_DISTANCE * Math.cos(angle), CENTRE[1] + RING_DISTANCE * Math.sin(angle), 1);
  });
}
