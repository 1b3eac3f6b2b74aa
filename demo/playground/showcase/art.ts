/**
 * The showcase's art, generated at start-up from height fields (no image files, so no licence to
 * track): tiling flagstones, wall blocks and grass, and an atlas of props, flames and decals.
 */
import { seededRandom } from '../textures';
import { fbm, hash, noise, smoothstep, SurfaceImage, type Texel } from './surfaceImage';

/** A rectangle of the props atlas, in pixels. */
export interface Cell {
  x: number;
  y: number;
  w: number;
  h: number;
}

/** Side of the props atlas, in pixels. */
export const ATLAS_SIZE = 512;
/** Flame animation frames in the atlas. */
export const FLAME_FRAMES = 4;

/** Where each prop lies in the atlas. */
export const CELLS = {
  crate: { x: 0, y: 0, w: 64, h: 64 },
  barrel: { x: 64, y: 0, w: 64, h: 64 },
  pillar: { x: 128, y: 0, w: 80, h: 80 },
  brazier: { x: 208, y: 0, w: 64, h: 64 },
  lantern: { x: 272, y: 0, w: 32, h: 32 },
  sconce: { x: 304, y: 0, w: 32, h: 32 },
  bar: { x: 336, y: 0, w: 16, h: 32 },
  ember: { x: 352, y: 0, w: 16, h: 16 },
  blob: { x: 384, y: 0, w: 64, h: 64 },
  edge: { x: 448, y: 0, w: 64, h: 32 },
  table: { x: 0, y: 80, w: 192, h: 96 },
  runes: { x: 192, y: 80, w: 160, h: 160 },
  rug: { x: 352, y: 80, w: 160, h: 224 },
  flame: { x: 0, y: 176, w: 32, h: 48 },
  books: { x: 0, y: 240, w: 96, h: 48 },
} as const satisfies Record<string, Cell>;

/** The n-th flame frame's cell (frames sit side by side from {@link CELLS}.flame). */
export function flameCell(frame: number): Cell {
  const { x, y, w, h } = CELLS.flame;
  return { x: x + (frame % FLAME_FRAMES) * w, y, w, h };
}

function set(t: Texel, r: number, g: number, b: number): void {
  t.r = r;
  t.g = g;
  t.b = b;
}

/**
 * Flagstones, 256 × 256 pixels, tiling: four rows of stones of random widths with a bevel, a
 * slight tilt each, pits and cracks, mortar between; a few stones polished (higher specular).
 */
export function floorImage(): SurfaceImage {
  const size = 256, rowHeight = 64;
  const random = seededRandom(31);
  const rows = [0, 1, 2, 3].map(() => {
    const widths: number[] = [];
    let total = 0;
    while (total < size) {
      const w = Math.min(size - total, 48 + Math.floor(random() * 4) * 16);
      widths.push(size - total - w < 40 ? size - total : w);
      total += widths[widths.length - 1];
    }
    return { offset: Math.floor(random() * size), widths };
  });
  return new SurfaceImage(size, size).paint(0, 0, size, size, (x, y, t) => {
    const r = Math.floor(y / rowHeight), row = rows[r];
    const rx = (x + row.offset) % size;
    let start = 0, index = 0;
    while (start + row.widths[index] <= rx) start += row.widths[index++];
    const w = row.widths[index];
    const lx = rx - start, ly = y - r * rowHeight;
    // Some stones are two half-height ones.
    const split = hash(r * 31 + index, 9, 5) < 0.3;
    const edge = Math.min(lx, w - lx, ly, rowHeight - ly, split ? Math.abs(ly - rowHeight / 2) : Infinity);
    const seed = r * 31 + index + (split && ly > rowHeight / 2 ? 500 : 0);
    const tone = hash(seed, 3, 5), tiltX = hash(seed, 1, 7) - 0.5, tiltY = hash(seed, 2, 7) - 0.5;
    const grain = fbm(x / 16, y / 16, 16, 3);
    const pits = noise(x / 2, y / 2, 128, 9);
    const crack = Math.abs(fbm(x / 40, y / 40, 256 / 40 | 0, 11 + seed, 3) - 0.5) < 0.008 && hash(seed, 4, 1) < 0.15;
    if (edge < 2.5) {
      // Mortar: low, dark, rough.
      t.height = -1 + grain;
      const m = 0.16 + grain * 0.08;
      set(t, m, m * 0.93, m * 0.85);
      return;
    }
    const bevel = smoothstep(2, 10, edge);
    t.height = 5 * bevel + tiltX * lx * 0.04 + tiltY * ly * 0.04 + grain * 1.4 - (pits > 0.9 ? 0.8 : 0) - (crack ? 1.5 : 0);
    const v = (0.3 + tone * 0.2) * (0.8 + grain * 0.4) * (0.78 + 0.22 * bevel) * (crack ? 0.65 : 1) * (pits > 0.9 ? 0.85 : 1);
    const warm = hash(seed, 6, 2);
    set(t, v * (1.02 + warm * 0.06), v * 0.96, v * (0.86 - warm * 0.06));
    const polished = hash(seed, 8, 3) < 0.3;
    t.specular = polished ? 0.35 : 0.12;
    t.shininess = polished ? 48 : 12;
  }, { wrap: true, bump: 0.7 });
}

/**
 * Wall tops, 128 × 128 pixels, tiling: dressed blocks two per row, rows offset by half a block,
 * pillowed (rounded) edges, deep mortar joints. Cooler and darker than the floor.
 */
export function wallImage(): SurfaceImage {
  const size = 128, rowHeight = 32, blockWidth = 64;
  return new SurfaceImage(size, size).paint(0, 0, size, size, (x, y, t) => {
    const r = Math.floor(y / rowHeight);
    const rx = (x + (r % 2) * (blockWidth / 2)) % size;
    const index = Math.floor(rx / blockWidth);
    const lx = rx - index * blockWidth, ly = y - r * rowHeight;
    const edge = Math.min(lx, blockWidth - lx, ly, rowHeight - ly);
    const seed = r * 7 + index;
    const grain = fbm(x / 12, y / 12, 128 / 12 | 0, 21);
    const fine = noise(x / 2.5, y / 2.5, 51, 23);
    if (edge < 2) {
      t.height = -2;
      set(t, 0.09, 0.085, 0.08);
      return;
    }
    const chipped = edge + (noise(x / 3, y / 3, 43, 25) - 0.5) * 6;
    const pillow = Math.sqrt(smoothstep(1, 10, chipped));
    t.height = 7 * pillow + grain * 2.5 + fine * 0.6;
    const tone = hash(seed, 1, 13);
    const v = (0.2 + tone * 0.1) * (0.75 + grain * 0.5) * (0.6 + 0.4 * pillow);
    set(t, v * 1.04, v, v * 0.94);
    t.specular = 0.1;
    t.shininess = 10;
  }, { wrap: true, bump: 0.8 });
}

/**
 * The face of a wall seen from the south (the 3/4 view's depth): brick courses on a surface that
 * faces down the image, 128 × 32 pixels, tiling across. The heights fall down the image, so the
 * normals lean south; the courses and joints add relief, darker towards the floor.
 */
export function wallFaceImage(): SurfaceImage {
  const w = 128, h = 32, course = 16, brick = 48;
  return new SurfaceImage(w, h).paint(0, 0, w, h, (x, y, t) => {
    const row = Math.floor(y / course);
    const lx = (x + (row % 2) * (brick / 2)) % brick, ly = y % course;
    const edge = Math.min(lx, brick - lx, ly, course - ly);
    const grain = fbm(x / 8, y / 8, 16, 29, 3);
    const joint = edge < 1.5;
    // A steep fall down the image leans every normal south; bricks stand out of the joints.
    t.height = -1.5 * y + (joint ? -1.5 : smoothstep(1, 4, edge) * 1.5) + grain;
    const tone = hash(Math.floor((x + (row % 2) * (brick / 2)) / brick), row, 27);
    const v = joint ? 0.1 : (0.26 + tone * 0.1) * (0.75 + grain * 0.5) * (1 - (y / h) * 0.3);
    set(t, v * 1.04, v, v * 0.94);
    t.specular = 0.08;
    t.shininess = 10;
  }, { wrap: 'x', bump: 1 });
}

/** Trodden grass and earth for outside the walls, 128 × 128 pixels, tiling. */
export function grassImage(): SurfaceImage {
  const size = 128;
  return new SurfaceImage(size, size).paint(0, 0, size, size, (x, y, t) => {
    const patch = fbm(x / 32, y / 32, 4, 41);
    const blades = noise(x / 1.5, y / 4, 85, 43) * 0.6 + noise(x / 3, y / 1.5, 42, 47) * 0.4;
    const earth = smoothstep(0.55, 0.7, patch);
    t.height = blades * 2.5 * (1 - earth) + patch * 2;
    const g = 0.13 + blades * 0.1 + patch * 0.06;
    set(t, g * (0.7 + earth * 0.5), g * (0.95 - earth * 0.3), g * (0.45 + earth * 0.2));
    t.specular = 0.05;
    t.shininess = 8;
  }, { wrap: true, bump: 1.2 });
}

/** The props atlas: every prop, flame frame and decal in one set of three images. */
export function propsImage(): SurfaceImage {
  const image = new SurfaceImage(ATLAS_SIZE, ATLAS_SIZE);
  const paint = (cell: Cell, painter: (x: number, y: number, t: Texel) => void, bump = 1) =>
    image.paint(cell.x, cell.y, cell.w, cell.h, painter, { bump });
  paint(CELLS.crate, crate, 1.2);
  paint(CELLS.barrel, barrel, 1.4);
  paint(CELLS.pillar, pillar, 1.3);
  paint(CELLS.brazier, brazier, 1.3);
  paint(CELLS.lantern, lantern);
  paint(CELLS.sconce, sconce, 1.2);
  paint(CELLS.bar, bar, 1.5);
  paint(CELLS.ember, ember);
  paint(CELLS.blob, blob);
  paint(CELLS.edge, edgeShade);
  paint(CELLS.table, table, 1);
  paint(CELLS.runes, runes, 1);
  paint(CELLS.rug, rug, 1);
  for (let frame = 0; frame < FLAME_FRAMES; frame++) paint(flameCell(frame), (x, y, t) => flame(x, y, t, frame));
  paint(CELLS.books, books, 1.2);
  return image;
}

/** Distance from the centre of a cell of `size`, in pixels, and the angle. */
function polar(x: number, y: number, size: number): [number, number] {
  const dx = x + 0.5 - size / 2, dy = y + 0.5 - size / 2;
  return [Math.hypot(dx, dy), Math.atan2(dy, dx)];
}

/** Soft coverage of a disc of `radius` (one pixel of anti-aliasing). */
const disc = (d: number, radius: number) => Math.min(1, Math.max(0, radius - d + 0.5));

function crate(x: number, y: number, t: Texel): void {
  const edge = Math.min(x, 63 - x, y, 63 - y);
  const frame = edge < 7;
  // The brace runs corner to corner; planks run across.
  const brace = Math.abs(x - y) < 6 && !frame;
  const plank = Math.floor(y / 14.2);
  const grain = noise(x / 10, y / 1.2 + plank * 9, 64, 51) * 0.7 + noise(x / 3, y / 0.7, 64, 53) * 0.3;
  const seam = !frame && !brace && (y % 14.2) < 1.2;
  t.height = frame ? 6 + smoothstep(0, 3, edge) * 2 : brace ? 6 : seam ? -1 : 3;
  t.height += grain * 0.8;
  const v = frame || brace ? 0.42 : 0.5 - (plank % 2) * 0.05;
  const shade = (0.72 + grain * 0.45) * (seam ? 0.5 : 1);
  set(t, v * shade * 1.0, v * shade * 0.68, v * shade * 0.38);
  // Iron nails at the frame's corners.
  for (const [nx, ny] of [[3.5, 3.5], [60, 3.5], [3.5, 60], [60, 60]]) {
    const d = Math.hypot(x - nx, y - ny);
    if (d < 2.6) {
      t.height += (2.6 - d) * 1.5;
      set(t, 0.35, 0.33, 0.32);
      t.specular = 0.8;
      t.shininess = 64;
      return;
    }
  }
  t.specular = 0.08;
  t.shininess = 8;
}

function barrel(x: number, y: number, t: Texel): void {
  const [d, angle] = polar(x, y, 64);
  t.alpha = disc(d, 30);
  const rim = d > 25 && d < 30;
  const hoop = (d > 17 && d < 20) || rim;
  const stave = Math.abs(Math.sin(angle * 9)) < 0.06 && d > 20;
  const lid = d < 17;
  const grain = noise(x / 2, y / 8, 32, 61);
  // The lid is sunk below the rim; the hoops stand proud.
  t.height = lid ? 3 + grain * 0.6 - (Math.abs(x - 32) < 0.8 ? 0.8 : 0) : hoop ? 7 : 5;
  if (d > 29) t.height = 5 - (d - 29) * 3;
  if (hoop) {
    set(t, 0.22, 0.2, 0.19);
    t.specular = 0.7;
    t.shininess = 48;
    return;
  }
  const v = (lid ? 0.46 : 0.4) * (0.75 + grain * 0.4) * (stave ? 0.5 : 1);
  set(t, v, v * 0.62, v * 0.34);
  t.specular = 0.1;
  t.shininess = 10;
}

function pillar(x: number, y: number, t: Texel): void {
  const [d, angle] = polar(x, y, 80);
  t.alpha = disc(d, 38);
  const grain = fbm(x / 8, y / 8, 10, 71, 3);
  // A round capital: a rim, a groove, a domed top.
  const dome = Math.sqrt(Math.max(0, 1 - (d / 38) ** 2));
  const groove = d > 27 && d < 30;
  t.height = 16 * dome + grain * 2 - (groove ? 2.5 : 0) + (d < 27 ? 2 : 0);
  const flute = 0.5 + 0.5 * Math.cos(angle * 12);
  const v = (0.25 + grain * 0.14) * (groove ? 0.6 : 1) * (d > 30 ? 0.86 + flute * 0.14 : 1);
  set(t, v * 1.02, v, v * 0.95);
  t.specular = 0.2;
  t.shininess = 20;
}

function brazier(x: number, y: number, t: Texel): void {
  const [d] = polar(x, y, 64);
  t.alpha = disc(d, 30);
  if (d > 23) {
    // The iron bowl's rim, rounded.
    t.height = 5 * Math.sin(((d - 23) / 7) * Math.PI);
    set(t, 0.16, 0.14, 0.13);
    t.specular = 0.6;
    t.shininess = 40;
    return;
  }
  // Coals: dark lumps with glowing cracks between them.
  const lumps = noise(x / 4, y / 4, 16, 81);
  const cracks = 1 - smoothstep(0.04, 0.16, Math.abs(noise(x / 5, y / 5, 13, 83) - 0.5));
  const heat = Math.max(cracks, smoothstep(0.6, 0.2, d / 23) * 0.8) * (0.6 + lumps * 0.4);
  t.height = lumps * 4 - cracks * 2;
  set(t, 0.12 + heat * 1.0, 0.05 + heat * 0.45, 0.03 + heat * 0.08);
  t.emissive = smoothstep(0.15, 0.6, heat);
}

function lantern(x: number, y: number, t: Texel): void {
  const edge = Math.min(x, 31 - x, y, 31 - y);
  const bar = Math.abs(x - 15.5) < 1 || Math.abs(y - 15.5) < 1;
  if (edge < 4 || bar) {
    t.height = edge < 4 ? 3 + smoothstep(0, 2, edge) : 4;
    set(t, 0.2, 0.17, 0.13);
    t.specular = 0.7;
    t.shininess = 56;
    return;
  }
  // Glass over the flame: bright at the centre.
  const [d] = polar(x, y, 32);
  const glow = 1 - smoothstep(2, 14, d);
  set(t, 1, 0.75 + glow * 0.2, 0.35 + glow * 0.3);
  t.emissive = 0.6 + glow * 0.4;
  t.height = 2;
}

function sconce(x: number, y: number, t: Texel): void {
  const [d] = polar(x, y, 32);
  // A round iron cup on a bracket that runs up to the wall (top of the cell).
  const bracket = Math.abs(x - 15.5) < 3 && y < 16;
  t.alpha = Math.max(disc(d, 9), bracket ? 1 : 0);
  t.height = d < 9 ? 4 * Math.cos((d / 9) * Math.PI / 2) + 1 : 2 * Math.cos(((x - 15.5) / 3) * Math.PI / 2);
  set(t, 0.2, 0.18, 0.16);
  t.specular = 0.7;
  t.shininess = 40;
  if (d < 5) {
    // Charred wood in the cup.
    set(t, 0.35, 0.15, 0.05);
    t.emissive = 0.5;
  }
}

function bar(x: number, _y: number, t: Texel): void {
  // A round iron bar along the cell's height.
  const u = (x + 0.5) / 16 * 2 - 1;
  t.alpha = Math.min(1, Math.max(0, (1 - Math.abs(u)) * 8));
  t.height = 6 * Math.sqrt(Math.max(0, 1 - u * u));
  set(t, 0.18, 0.17, 0.17);
  t.specular = 0.9;
  t.shininess = 64;
}

function ember(x: number, y: number, t: Texel): void {
  const [d] = polar(x, y, 16);
  t.alpha = Math.max(0, 1 - d / 7) ** 1.5;
  set(t, 1, 0.55, 0.18);
  t.emissive = 1;
}

/** A soft round contact shadow, drawn as a decal that only darkens the colour. */
function blob(x: number, y: number, t: Texel): void {
  const [d] = polar(x, y, 64);
  t.alpha = (1 - smoothstep(8, 32, d)) * 0.85;
  set(t, 0, 0, 0);
}

/** A shadow along an edge, darkest at the cell's top (against the wall). */
function edgeShade(_x: number, y: number, t: Texel): void {
  t.alpha = (1 - smoothstep(0, 31, y)) ** 1.6 * 0.8;
  set(t, 0, 0, 0);
}

function table(x: number, y: number, t: Texel): void {
  const edge = Math.min(x, 191 - x, y, 95 - y);
  t.alpha = Math.min(1, Math.max(0, edge + 0.5));
  const board = Math.floor(y / 24);
  const lx = (x + board * 53) % 191;
  const grain = noise(lx / 24, y / 1.3, 8, 91 + board) * 0.6 + noise(lx / 6, y / 0.8, 32, 93) * 0.4;
  const knot = Math.hypot(((lx * 1.0) % 97) - 48, (y % 24) - 12) < 3;
  const seam = y % 24 < 1.5 && y > 2;
  const bevel = smoothstep(0, 5, edge);
  t.height = 3 + bevel * 3 + grain * 0.7 - (seam ? 1.5 : 0) - (knot ? 0.6 : 0);
  const v = (0.4 + (board % 2) * 0.04) * (0.72 + grain * 0.5) * (seam ? 0.45 : 1) * (knot ? 0.6 : 1) * (0.75 + 0.25 * bevel);
  set(t, v, v * 0.64, v * 0.38);
  // Varnish: a soft sheen.
  t.specular = 0.35;
  t.shininess = 28;
}

/** A ring of glowing glyphs carved into the floor; transparent between the strokes. */
function runes(x: number, y: number, t: Texel): void {
  const [d, angle] = polar(x, y, 160);
  const ring = (r: number, w: number) => 1 - smoothstep(w * 0.5, w * 0.5 + 1, Math.abs(d - r));
  // Glyphs: short strokes between the rings, chosen per sector by a hash.
  const sectors = 18, sector = Math.floor(((angle / (Math.PI * 2)) + 1) * sectors) % sectors;
  const local = (((angle / (Math.PI * 2)) + 1) * sectors) % 1;
  const radial = (d - 52) / 18;
  let glyph = 0;
  if (radial > 0 && radial < 1) {
    const pick = hash(sector, 1, 101);
    const stroke = (a: number, b: number) => 1 - smoothstep(0.06, 0.12, Math.abs(a - b));
    glyph = Math.max(
      stroke(local, 0.5) * (pick < 0.7 ? 1 : 0),
      stroke(radial, pick < 0.5 ? 0.2 : 0.8) * (local > 0.25 && local < 0.75 ? 1 : 0),
      stroke(local - 0.5, (radial - 0.5) * (pick < 0.35 ? 0.6 : -0.6)) * (hash(sector, 2, 103) < 0.6 ? 1 : 0),
    );
  }
  const star = Math.max(0, 1 - smoothstep(1, 2.2, Math.abs(d * Math.cos(((angle % (Math.PI * 2 / 5)) + Math.PI * 2 / 5) % (Math.PI * 2 / 5) - Math.PI / 5) - 30)));
  const glow = Math.max(ring(76, 3), ring(48, 2), glyph, d < 48 ? star : 0);
  t.alpha = glow;
  t.height = -2 * glow;
  set(t, 0.45, 0.9, 1);
  t.emissive = 0.9;
}

/** A woven rug: a border, a field with a lozenge, fringes at the short ends. */
function rug(x: number, y: number, t: Texel): void {
  const w = 160, h = 224;
  const fringe = y < 8 || y > h - 9;
  if (fringe) {
    t.alpha = x > 10 && x < w - 10 && x % 4 < 2.5 ? 1 : 0;
    t.height = 0.5;
    set(t, 0.75, 0.68, 0.55);
    return;
  }
  const ex = Math.min(x, w - 1 - x), ey = Math.min(y - 8, h - 9 - y);
  const edge = Math.min(ex, ey);
  const weave = (x % 3 < 1.5 ? 0.5 : 0) + (y % 3 < 1.5 ? 0.5 : 0);
  const wear = fbm(x / 20, y / 20, 8, 111, 3);
  const cx = Math.abs(x - w / 2) / (w / 2 - 24), cy = Math.abs(y - h / 2) / (h / 2 - 28);
  const lozenge = cx + cy;
  let r = 0.45, g = 0.07, b = 0.06;
  if (edge < 14) [r, g, b] = edge < 4 || edge > 11 ? [0.75, 0.58, 0.2] : [0.1, 0.12, 0.25];
  else if (lozenge < 0.45) [r, g, b] = lozenge < 0.2 ? [0.75, 0.58, 0.2] : [0.1, 0.12, 0.25];
  else if (Math.abs(lozenge - 0.75) < 0.04) [r, g, b] = [0.75, 0.58, 0.2];
  const shade = (0.8 + weave * 0.2) * (0.75 + wear * 0.4);
  t.height = weave * 0.6 + 1;
  set(t, r * shade, g * shade, b * shade);
  t.specular = 0.02;
  t.shininess = 4;
}

/** A flame seen from above and slightly south: a teardrop with a white-hot core, one frame of a loop. */
function flame(x: number, y: number, t: Texel, frame: number): void {
  const u = (x + 0.5) / 32 * 2 - 1, v = (y + 0.5) / 48;
  const phase = (frame / FLAME_FRAMES) * Math.PI * 2;
  const sway = Math.sin(v * 5 + phase) * 0.12 * (1 - v);
  const widthAt = Math.sin(Math.min(1, v * 1.05) * Math.PI) ** 0.7 * (0.55 + 0.45 * v) * 0.8;
  const lick = noise(x / 5, y / 6 - frame * 2, 64, 121) * 0.3;
  const inside = widthAt + lick * (1 - v) - Math.abs(u - sway);
  t.alpha = smoothstep(0, 0.15, inside);
  const core = smoothstep(0.15, 0.5, inside) * smoothstep(0.3, 0.8, v);
  set(t, 1, 0.45 + core * 0.5, 0.1 + core * 0.6);
  t.emissive = 1;
}

/** A row of books on a shelf, spines up. */
function books(x: number, y: number, t: Texel): void {
  const index = Math.floor(x / 8);
  const lx = x % 8;
  const colour = hash(index, 1, 131);
  const tall = 30 + Math.floor(hash(index, 2, 131) * 16);
  const inBook = y > 47 - tall && lx > 0.5 && lx < 7.5;
  t.alpha = inBook ? 1 : 0;
  t.height = inBook ? 3 * Math.sin((lx / 8) * Math.PI) : 0;
  const palette: [number, number, number][] = [[0.4, 0.1, 0.08], [0.12, 0.22, 0.14], [0.14, 0.14, 0.3], [0.45, 0.32, 0.15]];
  const [r, g, b] = palette[Math.floor(colour * palette.length)];
  const band = Math.abs(y - (47 - tall + 6)) < 1.2 ? 1.8 : 1;
  set(t, r * band, g * band, b * band);
  t.specular = 0.2;
  t.shininess = 16;
}
