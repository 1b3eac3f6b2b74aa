import { SceneGeometry } from './sceneGeometry';
import { box, type Point, type ReferenceLight, type ReferenceScene } from './scenes';

/** mulberry32: a small, fast, seeded PRNG (uniform in [0, 1)); the same seed gives the same sequence everywhere. */
export function createRandom(seed: number): () => number {
  let state = seed >>> 0;
  return () => {
    state = (state + 0x6d2b79f5) >>> 0;
    let t = state;
    t = Math.imul(t ^ (t >>> 15), t | 1);
    t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
}

/**
 * Coordinates are multiples of 1/64: exact in float32 (the renderer keeps hull points as float32)
 * and short in JSON.
 */
const snap = (value: number) => Math.round(value * 64) / 64;

/**
 * A random scene of `width × height` from `seed`: 1–5 features, each a convex polygon, a rotated
 * box, a concave star or U, a row of 3–8 touching square tiles (one hull each, on whole pixels
 * like a tile map), or an open polyline of 2–6 points (a fence, free to cross itself); hulls and
 * polylines may overlap one another and reach past the image. Then 1–3 lights,
 * anywhere within 8 pixels of the image, centre outside every hull (at least half a pixel from any
 * outline) with a disk free to overlap hulls: radius 0 one time in five, else 1–30; range 20–100;
 * white or coloured, intensity 0.5–1.5. One scene in four adds a row of 5–8 thin posts before the
 * first light, whose disk becomes wider than their gaps.
 */
export function randomScene(seed: number, width: number, height: number): ReferenceScene {
  const random = createRandom(seed);
  const between = (low: number, high: number) => low + (high - low) * random();
  const integer = (low: number, high: number) => Math.floor(between(low, high + 1));
  const hulls: Point[][] = [];
  const polylines: Point[][] = [];
  const featureCount = integer(1, 5);
  for (let f = 0; f < featureCount; f++) {
    const cx = between(0, width), cy = between(0, height);
    const rotation = between(0, 2 * Math.PI);
    const kind = integer(0, 5);
    if (kind === 0) {
      // Convex: 3–8 points on a circle at jittered angles, stretched into an ellipse and turned.
      const count = integer(3, 8), radius = between(1.5, 14), stretch = between(0.4, 1);
      const onCircle = polygon(count, (i) => [radius, (2 * Math.PI * (i + between(-0.3, 0.3))) / count], 0, 0);
      hulls.push(transform(onCircle.map(([x, y]) => [x, y * stretch]), cx, cy, rotation, 1));
    } else if (kind === 1) {
      // A rotated box, from a thin post to a slab.
      const w = between(2, 24), h = between(2, 12);
      hulls.push(transform([[-w / 2, -h / 2], [w / 2, -h / 2], [w / 2, h / 2], [-w / 2, h / 2]], cx, cy, rotation, 1));
    } else if (kind === 2) {
      // Concave: a star of 5–10 points at alternating radii.
      const count = integer(5, 10), outer = between(4, 16), inner = outer * between(0.3, 0.7);
      hulls.push(polygon(count, (i) => [i % 2 === 0 ? outer : inner * between(0.8, 1.2), rotation + (2 * Math.PI * i) / count], cx, cy));
    } else if (kind === 3) {
      // Concave: a U (notch of random depth), rotated and scaled.
      const depth = between(0.3, 0.8);
      const u: Point[] = [[-1, -1], [-0.4, -1], [-0.4, 1 - 2 * depth], [0.4, 1 - 2 * depth], [0.4, -1], [1, -1], [1, 1], [-1, 1]];
      hulls.push(transform(u, cx, cy, rotation, between(5, 15)));
    } else if (kind === 4) {
      // A row or column of touching square tiles on whole pixels.
      const size = random() < 0.5 ? 4 : 8, count = integer(3, 8), horizontal = random() < 0.5;
      const x0 = Math.round(cx - size), y0 = Math.round(cy - size);
      for (let i = 0; i < count; i++) hulls.push(horizontal ? box(x0 + i * size, y0, size, size) : box(x0, y0 + i * size, size, size));
    } else {
      // An open polyline: a walk of 1–5 steps of 4–20 pixels, turning up to 150° at each point.
      const points: Point[] = [[snap(cx), snap(cy)]];
      let heading = rotation;
      for (let i = integer(1, 5); i > 0; i--) {
        const [x, y] = points[points.length - 1], step = between(4, 20);
        points.push([snap(x + step * Math.cos(heading)), snap(y + step * Math.sin(heading))]);
        heading += between(-2.6, 2.6);
      }
      polylines.push(points);
    }
  }
  const geometry = new SceneGeometry(hulls, polylines);
  const lights: ReferenceLight[] = [];
  const lightCount = integer(1, 3);
  for (let attempt = 0; lights.length < lightCount && attempt < 1000; attempt++) {
    const position: Point = [snap(between(-8, width + 8)), snap(between(-8, height + 8))];
    if (geometry.isInsideHull(...position) || geometry.isNearOutline(...position, 0.5)) continue;
    const light: ReferenceLight = {
      position, range: snap(between(20, 100)), radius: random() < 0.2 ? 0 : snap(between(1, 30)),
    };
    if (random() < 0.3) light.color = [snap(between(0.3, 1)), snap(between(0.3, 1)), snap(between(0.3, 1))];
    const intensity = snap(between(0.5, 1.5));
    if (intensity !== 1) light.intensity = intensity;
    lights.push(light);
  }
  // One scene in four: a row of 5–8 thin posts across the first light's axis, before a disk wider
  // than their gaps (and clear of them), which cut it into more slices than the union keeps as
  // middles. Drawn last, so the rest of the scene is as without it.
  if (lights.length > 0 && random() < 0.25) {
    const light = lights[0], count = integer(5, 8), size = between(1, 3), gap = between(2, 5);
    const angle = between(0, 2 * Math.PI), distance = between(15, 35), radius = snap(between(10, distance - size - 1));
    const [lx, ly] = light.position, ax = Math.cos(angle), ay = Math.sin(angle);
    const posts = Array.from({ length: count }, (_, k): Point[] => {
      const along = (k - (count - 1) / 2) * (size + gap);
      const x = lx + distance * ax - along * ay, y = ly + distance * ay + along * ax;
      return transform([[-size / 2, -size / 2], [size / 2, -size / 2], [size / 2, size / 2], [-size / 2, size / 2]], x, y, angle, 1);
    });
    // Every disk clear of the posts (a disk overlapping many of them is the quadrature's case, not this one's).
    const clear = (x: number, y: number, r: number) => posts.every((post) => post.every(([px, py]) => Math.hypot(px - x, py - y) > r + size + 1));
    if (lights.every(({ position, radius: r }, i) => clear(position[0], position[1], i === 0 ? radius : r))) {
      hulls.push(...posts);
      light.radius = radius;
    }
  }
  // One scene in three lights the inside of hulls (Illuminated, the default shadow type): its dark
  // tiles with hulls in them are held, lit inside the hulls.
  const shadowType = seed % 3 === 0 ? 'illuminated' : 'solid';
  return { name: `random scene (seed ${seed})`, width, height, lights, hulls, polylines, shadowType };
}

/** `count` points at (radius, angle) pairs around (cx, cy). */
function polygon(count: number, pointAt: (i: number) => [number, number], cx: number, cy: number): Point[] {
  return Array.from({ length: count }, (_, i) => {
    const [radius, angle] = pointAt(i);
    return [snap(cx + radius * Math.cos(angle)), snap(cy + radius * Math.sin(angle))];
  });
}

/** Points scaled by `scale`, turned by `rotation` and moved to (cx, cy). */
function transform(points: readonly Point[], cx: number, cy: number, rotation: number, scale: number): Point[] {
  const cos = Math.cos(rotation), sin = Math.sin(rotation);
  return points.map(([x, y]) => [snap(cx + scale * (x * cos - y * sin)), snap(cy + scale * (x * sin + y * cos))]);
}
