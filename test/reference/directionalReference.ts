import { uShape, writeEdgesSeenFromInside } from './occludedReference';
import { SceneGeometry, segmentsCross } from './sceneGeometry';
import { box, type Point, type ReferenceScene } from './scenes';
import {
  diskSamples, DISK_SAMPLES, HARD_EDGE_BAND, LIT, OUTLINE_BAND, PENUMBRA, shareOfSamplesSeen, UMBRA, type ReferenceImage,
} from './softShadowReference';

/** A scene lit by one directional light (`DirectionalLight`), with world units = pixels. */
export interface DirectionalReferenceScene {
  name: string;
  width: number;
  height: number;
  /** Travels along `rotation` (0: towards +x); `angularSize` is its disk's apparent diameter in radians (0: hard). White, intensity 1 unless given. */
  light: { rotation: number; angularSize: number; color?: [number, number, number]; intensity?: number };
  /** What the light does inside hulls (`ShadowType`). */
  shadowType: 'solid' | 'illuminated' | 'occluded';
  /** World-space outlines, in either winding; for `'occluded'` they must not overlap. */
  hulls: Point[][];
  /** World-space open polylines: edges that block light from both sides, no inside. */
  polylines?: Point[][];
}

/** Length of the rays to the disk: far beyond any scene, hulls far upstream of the view included. */
const RAY_LENGTH = 1e5;

/**
 * The ground truth for a directional light, by sampling its disk at infinity, with none of the
 * renderer's math. The disk spans the directions within α = angularSize / 2 of u, the direction
 * towards the light (against its travel). Area-uniform samples of the unit disk (the sunflower of
 * {@link diskSamples}) stand for its points; a sample at height t across u (its chord) is seen in
 * the direction θ = asin(t sin α) off u, as a disk of radius D sin α at any distance D shows it. A
 * pixel centre sees a sample when the ray of RAY_LENGTH in that direction crosses no edge: hulls
 * anywhere upstream shadow it. The visible fraction gives `visibility[0]`, and `light` is colour ×
 * intensity × that fraction (ambient black, shadow colour black); every pixel is in range.
 *
 * Inside a hull: 0 for `'solid'`, 1 for `'illuminated'`, and for `'occluded'` the fraction past the
 * other hulls' edges and the edges of its own that face the pixel (as in computeOccludedReference).
 *
 * Ambiguous pixels: centres within OUTLINE_BAND of an outline, and for angular size 0 within
 * HARD_EDGE_BAND of a hard shadow edge (the line along the travel from a hull point).
 *
 * Accuracy: the sampling's, about 2e-3 of full light for 4,096 samples (see DISK_SAMPLES).
 */
export function computeDirectionalReference(scene: DirectionalReferenceScene, samples = DISK_SAMPLES): ReferenceImage {
  const { width, height, light, shadowType } = scene;
  const geometry = new SceneGeometry(scene.hulls, scene.polylines);
  const disk = new DiskAtInfinity(light.rotation, light.angularSize, samples, geometry.edges.length);
  const outlines = scene.hulls.map((hull) => Float64Array.from(hull.flat()));
  const polylineEdges = new SceneGeometry([], scene.polylines).edges;
  const edgesFromInside = new Float64Array(geometry.edges.length);
  const color = light.color ?? [1, 1, 1], intensity = light.intensity ?? 1;
  const pixels = width * height;
  const visibility = new Float32Array(pixels), lightmap = new Float32Array(pixels * 3);
  const ambiguous = new Uint8Array(pixels), shade = new Uint8Array(pixels);
  for (let y = 0; y < height; y++) {
    for (let x = 0; x < width; x++) {
      const px = x + 0.5, py = y + 0.5, pixel = y * width + x;
      if (geometry.isNearOutline(px, py, OUTLINE_BAND) || (light.angularSize === 0 && nearHardShadowEdge(geometry, px, py, light.rotation))) ambiguous[pixel] = 1;
      const holder = geometry.hullHolding(px, py);
      let fraction: number;
      if (holder >= 0 && shadowType !== 'occluded') {
        fraction = shadowType === 'illuminated' ? 1 : 0;
      } else if (holder >= 0) {
        const floats = writeEdgesSeenFromInside(outlines, px, py, edgesFromInside);
        edgesFromInside.set(polylineEdges, floats);
        fraction = disk.fractionSeen(px, py, edgesFromInside, floats + polylineEdges.length);
      } else {
        fraction = disk.fractionSeen(px, py, geometry.edges, geometry.edges.length);
      }
      visibility[pixel] = fraction;
      for (let c = 0; c < 3; c++) lightmap[pixel * 3 + c] = color[c] * intensity * fraction;
      shade[pixel] = fraction === 1 ? LIT : fraction === 0 ? UMBRA : PENUMBRA;
    }
  }
  return { width, height, visibility: [visibility], light: lightmap, inRange: new Uint8Array(pixels).fill(1), ambiguous, shade };
}

/**
 * The unit direction of the ray to each disk sample, `[x, y, …]`: θ = asin(t sin α) off the
 * direction towards the light, t the sample's height across it; one ray straight at the light for
 * angular size 0.
 */
function rayDirections(rotation: number, angularSize: number, count: number): Float64Array {
  const towards = rotation + Math.PI, sinAlpha = Math.sin(angularSize / 2);
  const disk = diskSamples(0, 0, angularSize > 0 ? 1 : 0, count);
  const rays = new Float64Array(disk.length);
  for (let i = 0; i < disk.length; i += 2) {
    const direction = towards + Math.asin(disk[i + 1] * sinAlpha);
    rays[i] = Math.cos(direction);
    rays[i + 1] = Math.sin(direction);
  }
  return rays;
}

/**
 * The light's disk at infinity, as rays from a pixel centre. Only edges that meet the wedge of
 * directions within α of the direction towards the light can cross a ray, so the others are left
 * out before the rays are tested (an edge meets the wedge when an end lies in it or it crosses one
 * of its two sides: the wedge, under 90° wide, is convex).
 */
class DiskAtInfinity {
  /** Unit directions of the rays, `[x, y, …]` (see rayDirections). */
  private readonly rays: Float64Array;
  private readonly towardsX: number;
  private readonly towardsY: number;
  private readonly tangent: number;
  /** The wedge's two sides' directions, `[x0, y0, x1, y1]`. */
  private readonly sides: Float64Array;
  /** The ends of the rays from the current pixel centre, and the edges that meet its wedge. */
  private readonly ends: Float64Array;
  private readonly candidates: Float64Array;

  /** `maxEdgeFloats`: the most edge floats `fractionSeen` is given. */
  constructor(rotation: number, angularSize: number, samples: number, maxEdgeFloats: number) {
    const towards = rotation + Math.PI, half = angularSize / 2;
    this.rays = rayDirections(rotation, angularSize, samples);
    this.towardsX = Math.cos(towards);
    this.towardsY = Math.sin(towards);
    this.tangent = Math.tan(half);
    this.sides = Float64Array.of(Math.cos(towards - half), Math.sin(towards - half), Math.cos(towards + half), Math.sin(towards + half));
    this.ends = new Float64Array(this.rays.length);
    this.candidates = new Float64Array(maxEdgeFloats);
  }

  /** The share of the rays from (px, py) that cross none of the first `floats / 4` edges of `edges`. */
  fractionSeen(px: number, py: number, edges: Float64Array, floats: number): number {
    const candidates = this.candidates;
    let count = 0;
    for (let e = 0; e < floats; e += 4) {
      if (!this.meets(px, py, edges[e], edges[e + 1], edges[e + 2], edges[e + 3])) continue;
      for (let k = 0; k < 4; k++) candidates[count++] = edges[e + k];
    }
    if (count === 0) return 1;
    const rays = this.rays, ends = this.ends;
    for (let i = 0; i < rays.length; i += 2) {
      ends[i] = px + RAY_LENGTH * rays[i];
      ends[i + 1] = py + RAY_LENGTH * rays[i + 1];
    }
    return shareOfSamplesSeen(px, py, ends, candidates, count);
  }

  /** Whether the edge a → b meets the wedge from (px, py). */
  private meets(px: number, py: number, ax: number, ay: number, bx: number, by: number): boolean {
    if (this.holds(ax - px, ay - py) || this.holds(bx - px, by - py)) return true;
    const s = this.sides;
    return segmentsCross(px, py, px + RAY_LENGTH * s[0], py + RAY_LENGTH * s[1], ax, ay, bx, by)
      || segmentsCross(px, py, px + RAY_LENGTH * s[2], py + RAY_LENGTH * s[3], ax, ay, bx, by);
  }

  /** Whether the offset (dx, dy) from the apex lies in the wedge. */
  private holds(dx: number, dy: number): boolean {
    const along = dx * this.towardsX + dy * this.towardsY, across = dx * this.towardsY - dy * this.towardsX;
    return along >= 0 && Math.abs(across) <= along * this.tangent;
  }
}

/** Whether (px, py) lies within HARD_EDGE_BAND of a hard shadow edge: the half-line from a hull point along the light's travel. */
function nearHardShadowEdge(geometry: SceneGeometry, px: number, py: number, rotation: number): boolean {
  const v = geometry.vertices, travelX = Math.cos(rotation), travelY = Math.sin(rotation);
  for (let i = 0; i < v.length; i += 2) {
    const dx = px - v[i], dy = py - v[i + 1];
    if (dx * travelX + dy * travelY > 0 && Math.abs(dx * travelY - dy * travelX) < HARD_EDGE_BAND) return true;
  }
  return false;
}

const WIDTH = 160, HEIGHT = 120;
const tiles = (x: number, y: number, count: number, size: number): Point[][] => Array.from({ length: count }, (_, i) => box(x, y + i * size, size, size));

/** A directional reference scene, and whether it is a tile wall (held to UMBRA_LIMIT in its umbra). */
export type DirectionalScene = DirectionalReferenceScene & { tileWall?: boolean };
const scene = (name: string, light: DirectionalScene['light'], hulls: Point[][], extra: Partial<DirectionalScene> = {}): DirectionalScene => ({
  name, width: WIDTH, height: HEIGHT, light, shadowType: 'solid', hulls, ...extra,
});

/** Scenes of one directional light, rendered on headless-gl and in Chromium. */
export const DIRECTIONAL_SCENES: DirectionalScene[] = [
  scene('a wall under a low sun', { rotation: 0.3, angularSize: 0.1 }, [box(40, 30, 10, 40)]),
  scene('a row of posts under a hard noon sun', { rotation: Math.PI / 2, angularSize: 0 }, [box(30, 20, 6, 6), box(60, 24, 6, 6), box(90, 20, 6, 6), box(120, 28, 6, 6)]),
  scene('crates under an overcast sky', { rotation: 2.2, angularSize: 0.6, color: [0.6, 0.7, 1] }, [box(50, 40, 20, 20), box(95, 60, 16, 24), [[120, 30], [140, 36], [128, 50]]]),
  scene('a hull far upstream, out of view, shadows into it', { rotation: 0.05, angularSize: 0.03 }, [box(-400, 40, 20, 30)]),
  scene('a wall of touching tiles lets no light through', { rotation: -0.2, angularSize: 0.08 }, tiles(60, 10, 12, 8), { tileWall: true }),
  scene('a concave building under the sun with Occluded hulls', { rotation: 0.4, angularSize: 0.12 }, [uShape(30, 30, 70, 56, 14, 32), box(120, 20, 14, 14)], { shadowType: 'occluded' }),
  scene('Illuminated hulls are lit and cast shadows', { rotation: -2.5, angularSize: 0.2 }, [box(70, 50, 24, 16), [[30, 80], [50, 70], [44, 100]]], { shadowType: 'illuminated' }),
  scene('fences and posts across a slanted sun', { rotation: 0.9, angularSize: 0.05 }, [box(100, 80, 8, 8)], { polylines: [[[20, 40], [60, 30], [80, 50]], [[110, 20], [140, 25]]] }),
  // Seen from behind, the boxes cut the wide sun into up to eight slices: more disjoint intervals
  // than the union keeps as middles.
  scene('a column of eight 6 × 6 boxes under a wide sun', { rotation: 0.1, angularSize: 1.4 }, Array.from({ length: 8 }, (_, k) => box(40, 6 + 14 * k, 6, 6))),
];

/** The scene as compareToReference counts full light: one light of the sun's colour × intensity. */
export function asLitScene(scene: DirectionalReferenceScene): ReferenceScene {
  const { color, intensity } = scene.light;
  return { name: scene.name, width: scene.width, height: scene.height, hulls: scene.hulls, lights: [{ position: [0, 0], range: 1, radius: 0, color, intensity }] };
}
