/**
 * The reference scenes: lights (white unless stated, Solid shadows) and world-space hulls, as
 * plain JSON-able data so the headless-gl test and the Chromium page render the very same scenes.
 * Sizes are small (the sampling reference tests thousands of disk points per shadowed pixel).
 */
export type Point = [number, number];

export interface ReferenceLight {
  position: Point;
  range: number;
  radius: number;
  color?: [number, number, number];
  intensity?: number;
}

export interface ReferenceScene {
  name: string;
  width: number;
  height: number;
  /** Every light adds its own light (ambient black): the expected lightmap is their sum. */
  lights: ReferenceLight[];
  /** World-space outlines, in either winding. */
  hulls: Point[][];
  /** World-space open polylines (`new Hull(points, { closed: false })`): edges that block light from both sides, no inside. */
  polylines?: Point[][];
  /**
   * Also held to UMBRA_LIMIT (test/reference/limits.ts) in its umbra: set on the tile walls, where
   * light leaking through the seams between tiles shows as lit pixels the reference calls umbra.
   */
  darkUmbra?: boolean;
  /**
   * How the lights treat hull insides: `'solid'` (the default: dark), `'illuminated'` (lit), both as
   * computeReference has them, or `'occluded'` (lit where the light reaches them: computeOccludedReference).
   */
  shadowType?: 'solid' | 'illuminated' | 'occluded';
}

const WIDTH = 160;
const HEIGHT = 120;

export const box = (x: number, y: number, w: number, h: number): Point[] => [[x, y], [x + w, y], [x + w, y + h], [x, y + h]];

/** A U opening towards +x (away from a light on its left): its arms cast a concave shadow. */
const uShape: Point[] = [[70, 35], [100, 35], [100, 45], [80, 45], [80, 75], [100, 75], [100, 85], [70, 85]];
/** The same U opening towards the light: the pixels in its mouth see the light past its arms. */
const openU: Point[] = [[70, 35], [100, 35], [100, 85], [70, 85], [70, 75], [90, 75], [90, 45], [70, 45]];
/** An L: its inner corner faces the light, so a part of the hull hides another part. */
const lShape: Point[] = [[75, 30], [85, 30], [85, 70], [110, 70], [110, 80], [75, 80]];

/** A regular polygon of `count` points: more than eight (`VARYING_POINT_COUNTS`) takes the stages that fetch points. */
const roundHull = (x: number, y: number, radius: number, count: number): Point[] =>
  Array.from({ length: count }, (_, i) => [x + radius * Math.cos((2 * Math.PI * i) / count), y + radius * Math.sin((2 * Math.PI * i) / count)]);
/** A comb of three teeth pointing away from a light on its left: 12 points, concave. */
const comb: Point[] = [[70, 30], [80, 30], [80, 45], [100, 45], [100, 55], [80, 55], [80, 65], [100, 65], [100, 75], [80, 75], [80, 90], [70, 90]];

/** `count` touching square tiles of side `size` in a column from (x, y) downwards: a tile map's wall, one hull per tile. */
const tileColumn = (x: number, y: number, size: number, count: number): Point[][] =>
  Array.from({ length: count }, (_, i) => box(x, y + i * size, size, size));

/** A U whose notch opens upwards (towards −y): 12 wide, 16 deep, between arms 8 wide. */
const notchUp: Point[] = [[62, 70], [70, 70], [70, 86], [82, 86], [82, 70], [90, 70], [90, 96], [62, 96]];

export const REFERENCE_SCENES: readonly ReferenceScene[] = [
  { name: 'convex, hard (r=0)', width: WIDTH, height: HEIGHT,
    lights: [{ position: [40, 60], range: 140, radius: 0 }], hulls: [box(70, 45, 16, 30)] },
  { name: 'convex rotated, soft (r=8)', width: WIDTH, height: HEIGHT,
    lights: [{ position: [40, 60], range: 140, radius: 8 }], hulls: [[[72, 50], [90, 42], [98, 62], [80, 74]]] },
  { name: 'concave U, hard (r=0)', width: WIDTH, height: HEIGHT,
    lights: [{ position: [30, 60], range: 150, radius: 0 }], hulls: [uShape] },
  { name: 'concave U, soft (r=6)', width: WIDTH, height: HEIGHT,
    lights: [{ position: [30, 60], range: 150, radius: 6 }], hulls: [uShape] },
  { name: 'U open towards the light, soft (r=6)', width: WIDTH, height: HEIGHT,
    lights: [{ position: [30, 60], range: 150, radius: 6 }], hulls: [openU] },
  { name: 'concave L, soft (r=6)', width: WIDTH, height: HEIGHT,
    lights: [{ position: [35, 100], range: 150, radius: 6, color: [1, 0.6, 0.3], intensity: 0.8 }], hulls: [lShape] },
  { name: 'two hulls, same-side penumbrae (r=10)', width: WIDTH, height: HEIGHT,
    lights: [{ position: [30, 60], range: 150, radius: 10 }], hulls: [box(60, 30, 10, 22), box(95, 22, 10, 22)] },
  { name: 'light between pillars (r=6)', width: WIDTH, height: HEIGHT,
    lights: [{ position: [80, 60], range: 90, radius: 6 }], hulls: [box(50, 52, 10, 16), box(100, 52, 10, 16)] },
  // Each post hides only a middle slice of the disk from the pixels far behind both: the visible
  // fraction there is the disk less the union of the two slices.
  { name: 'two posts, middle slices (r=12)', width: WIDTH, height: HEIGHT,
    lights: [{ position: [30, 60], range: 150, radius: 12 }], hulls: [box(70, 54, 3, 3), box(70, 63, 3, 3)] },
  // The wall's lower face passes through the light disk: seen from the upper part of the disk that
  // face is a back face, so the pixels just below the wall lose part of the disk.
  { name: 'wall grazing the disk (r=10)', width: WIDTH, height: HEIGHT,
    lights: [{ position: [40, 60], range: 150, radius: 10 }], hulls: [box(60, 48, 80, 6)] },
  // Close to the disk: a region that opens wide (about 67° either side).
  { name: 'box close to the disk (r=10)', width: WIDTH, height: HEIGHT,
    lights: [{ position: [40, 60], range: 140, radius: 10 }], hulls: [box(55, 50, 10, 20)] },
  // Closer still (80° either side): too wide for one region, a convex hull cast as one quad per edge.
  { name: 'box very close to the disk (r=10)', width: WIDTH, height: HEIGHT,
    lights: [{ position: [40, 60], range: 140, radius: 10 }], hulls: [box(52, 50, 10, 20)] },
  // Hulls of more than eight points: their stages read the points from the texture, not varyings.
  { name: 'round pillar of 16 points (r=8)', width: WIDTH, height: HEIGHT,
    lights: [{ position: [40, 60], range: 140, radius: 8 }], hulls: [roundHull(85, 62, 12, 16)] },
  { name: 'comb of 12 points (r=6)', width: WIDTH, height: HEIGHT,
    lights: [{ position: [30, 60], range: 150, radius: 6 }], hulls: [comb] },
  { name: 'round pillar of 12 points close to the disk (r=10)', width: WIDTH, height: HEIGHT,
    lights: [{ position: [40, 60], range: 140, radius: 10 }], hulls: [roundHull(62, 60, 10, 12)] },
  { name: 'three hulls, hard (r=0)', width: WIDTH, height: HEIGHT,
    // Off the pixel grid: from a light on it, rows of pixel centres line up exactly with a hull corner,
    // where a grazing segment is neither clearly lit nor clearly hidden.
    lights: [{ position: [80.3, 60.2], range: 100, radius: 0 }],
    hulls: [box(95, 30, 12, 12), [[55, 75], [70, 85], [50, 95]], box(60, 40, 8, 8)] },

  // Tile maps: a wall of touching 8×8 tiles, one hull per tile, with the light four tiles away. No
  // light may pass between two tiles (their shared edges hide the disk together), and a disk as
  // wide as a tile or two hides behind the wall only when the tiles' shadows are joined exactly.
  { name: 'wall of 12 touching tiles (r=8)', width: WIDTH, height: HEIGHT,
    lights: [{ position: [56, 60], range: 150, radius: 8 }], hulls: tileColumn(88, 12, 8, 12), darkUmbra: true },
  { name: 'wall of 12 touching tiles (r=16)', width: WIDTH, height: HEIGHT,
    lights: [{ position: [56, 60], range: 150, radius: 16 }], hulls: tileColumn(88, 12, 8, 12), darkUmbra: true },
  // Thin posts with gaps across the light's axis: behind them the disk is cut into several slices
  // by hulls that each hide a different part of it.
  { name: 'row of three 2×2 posts (r=12)', width: WIDTH, height: HEIGHT,
    lights: [{ position: [30, 60], range: 150, radius: 12 }], hulls: [box(70, 53, 2, 2), box(70, 59, 2, 2), box(70, 65, 2, 2)] },
  // Six posts across a light wider than their column: behind them the disk is cut into up to six
  // slices, more disjoint intervals than the union keeps as middles.
  { name: 'column of six 3×3 posts before a wide light (r=40)', width: WIDTH, height: HEIGHT,
    lights: [{ position: [24, 60], range: 150, radius: 40 }], hulls: Array.from({ length: 6 }, (_, k) => box(70, 40 + 7 * k, 3, 3)) },
  // Four touching crates, each its own hull, lit from two sides: the lights add up, and neither
  // may leak through the seams between crates.
  // Crates in a wall's umbra, lit inside and dark around (an Illuminated light's held tiles), and
  // one half in it.
  { name: 'crates behind a wall, Illuminated (r=6)', width: WIDTH, height: HEIGHT, shadowType: 'illuminated',
    lights: [{ position: [30, 60], range: 150, radius: 6 }], hulls: [box(60, 30, 8, 60), box(100, 50, 12, 12), box(120, 70, 10, 10), box(110, 88, 10, 10)] },
  // Blocks several tiles wide behind a wall and at its edge: an Illuminated light's tiles wholly
  // inside a hull are lit, in the umbra and in the penumbra alike.
  { name: 'blocks behind a wall, Illuminated (r=6)', width: WIDTH, height: HEIGHT, shadowType: 'illuminated',
    lights: [{ position: [30, 60], range: 150, radius: 6 }], hulls: [box(60, 30, 8, 60), box(90, 40, 40, 40), box(80, 92, 30, 20)] },
  { name: '2×2 touching crates, two lights (r=8, r=6)', width: WIDTH, height: HEIGHT,
    lights: [
      { position: [40, 35], range: 130, radius: 8 },
      { position: [125, 90], range: 110, radius: 6, color: [1, 0.7, 0.4], intensity: 0.8 },
    ],
    hulls: [box(72, 48, 10, 10), box(82, 48, 10, 10), box(72, 58, 10, 10), box(82, 58, 10, 10)] },
  // One post behind the other along the light's axis, offset sideways: from far behind both each
  // hides a different middle slice of the disk, and the slices overlap in part.
  { name: 'two posts along the axis, middle slices (r=12)', width: WIDTH, height: HEIGHT,
    lights: [{ position: [30, 60], range: 150, radius: 12 }], hulls: [box(58, 57, 3, 3), box(86, 61, 3, 3)] },
  // A light above a notch, looking into it: the notch's floor and walls see the disk past the
  // arms, which hide parts of it from each other (a hull hiding itself).
  { name: 'light above a concave notch (r=8)', width: WIDTH, height: HEIGHT,
    lights: [{ position: [76, 52], range: 120, radius: 8 }], hulls: [notchUp] },
  // Disks overlapping hulls (centres outside every hull): the part of the disk inside a hull is
  // hidden from every pixel outside it.
  // A torch on a wall: its centre half a pixel off the wall's top face, its disk half inside.
  { name: 'torch half inside a wall (r=8)', width: WIDTH, height: HEIGHT,
    lights: [{ position: [80, 59.5], range: 120, radius: 8 }], hulls: [box(30, 60, 100, 10), box(60, 28, 10, 10)] },
  // A lamp whose disk takes in a crate's corner.
  { name: 'lamp over a crate corner (r=10)', width: WIDTH, height: HEIGHT,
    lights: [{ position: [74, 44], range: 120, radius: 10 }], hulls: [box(80, 50, 16, 16)] },
  // A wide light whose disk reaches a little into two hulls on either side.
  { name: 'wide light grazing two hulls (r=20)', width: WIDTH, height: HEIGHT,
    lights: [{ position: [80, 60], range: 110, radius: 20 }], hulls: [box(44, 45, 18, 10), box(93, 73, 14, 14)] },

  // Centres inside hulls: what of the disk lies outside them still emits, what lies inside is hidden.
  // A torch that drifted two pixels into a wall: the half of its disk above the wall lights the room.
  { name: 'torch with its centre inside a wall (r=8)', width: WIDTH, height: HEIGHT,
    lights: [{ position: [80, 62], range: 120, radius: 8 }], hulls: [box(30, 60, 100, 10), box(60, 28, 10, 10)] },
  // A wide lamp on a small table: the ring of its disk around the table.
  { name: 'wide lamp centred on a small crate (r=12)', width: WIDTH, height: HEIGHT,
    lights: [{ position: [80, 60], range: 110, radius: 12 }], hulls: [box(75, 56, 9, 8), box(110, 40, 10, 30)] },
  // A lamp wholly inside a block: dark everywhere but inside the block (Solid: dark there too).
  { name: 'lamp wholly inside a block (r=4)', width: WIDTH, height: HEIGHT,
    lights: [{ position: [80, 60], range: 110, radius: 4 }], hulls: [box(70, 50, 20, 20)] },
  { name: 'torch with its centre inside a wall, Illuminated (r=8)', width: WIDTH, height: HEIGHT, shadowType: 'illuminated',
    lights: [{ position: [80, 62], range: 120, radius: 8 }], hulls: [box(30, 60, 100, 10), box(60, 28, 10, 10)] },

  // Open polylines: thin walls and fences with no inside, blocking light from both sides.
  { name: 'fence across the light (r=8)', width: WIDTH, height: HEIGHT,
    lights: [{ position: [40, 60], range: 140, radius: 8 }], hulls: [], polylines: [[[80, 35], [80, 85]]] },
  { name: 'zigzag fence, hard (r=0)', width: WIDTH, height: HEIGHT,
    lights: [{ position: [40.3, 60.2], range: 140, radius: 0 }], hulls: [], polylines: [[[70, 30], [85, 45], [70, 60], [85, 75], [70, 90]]] },
  // The pixels inside the V see the disk past its arms, each arm hiding part of it from the other's side.
  { name: 'V fence opening towards the light (r=6)', width: WIDTH, height: HEIGHT,
    lights: [{ position: [30, 60], range: 150, radius: 6 }], hulls: [], polylines: [[[105, 30], [75, 60], [105, 90]]] },
  // A path that crosses itself, and a box behind it: the union of everything between pixel and disk.
  { name: 'self-crossing fence and a box (r=10)', width: WIDTH, height: HEIGHT,
    lights: [{ position: [35, 60], range: 140, radius: 10 }], hulls: [box(115, 52, 10, 16)], polylines: [[[65, 40], [95, 80], [95, 40], [65, 80]]] },
  // A torch on a thin wall: the line cuts its disk, and each side sees only its own part of it.
  { name: 'torch on a thin wall, disk cut in two (r=8)', width: WIDTH, height: HEIGHT,
    lights: [{ position: [80, 58], range: 120, radius: 8 }], hulls: [], polylines: [[[20, 60], [140, 60]]] },
  { name: 'light centred on a thin wall (r=8)', width: WIDTH, height: HEIGHT,
    lights: [{ position: [80, 60], range: 120, radius: 8 }], hulls: [], polylines: [[[20, 60], [140, 60]]] },
  // A ring of fence around the light with one gap: light leaves only through the gap.
  { name: 'light inside a fence ring with a gap (r=6)', width: WIDTH, height: HEIGHT,
    lights: [{ position: [80, 60], range: 110, radius: 6 }], hulls: [], polylines: [[[60, 48], [60, 30], [100, 30], [100, 90], [60, 90], [60, 62]]] },
];
