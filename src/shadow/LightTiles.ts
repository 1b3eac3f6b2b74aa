import { RECORD_FLOATS, RECORD_POINTS, ROW_INDICES, SHADOW_TYPE_CODES, TILE_CLASS_COUNT, TILE_CLASSES, TILE_GRID, tileCorner } from './shadowLayout';
import type { FiledDisk } from './ShadowBins';
import type { ShadowGeometry } from './ShadowGeometry';

/** Tiles per light. */
const TILE_COUNT = TILE_GRID * TILE_GRID;
/** The classes drawn, in the order their rectangles follow each other in a row's slot. */
const DRAWN_CLASSES = [TILE_CLASSES.lit, TILE_CLASSES.dark, TILE_CLASSES.held, TILE_CLASSES.lean, TILE_CLASSES.exact] as const;
/**
 * A row of tiles as a bit mask, tile i at bit i: marking a span, the classes' logic and counting
 * are word operations, not per tile (TILE_GRID ≤ 32). Masks are int32 (Int32Array), and no function
 * returns one: V8 boxes an int32 beyond 2^30 that crosses a call it does not inline.
 */
const FULL_ROW = TILE_GRID === 32 ? -1 : (1 << TILE_GRID) - 1;
/**
 * Slack of the geometric tests, relative to the scale of the light's box: float32 rounding in the
 * shader is about 1e-7 of the coordinates, so a pixel this far inside a region is classified as
 * the shader would shade it.
 */
const RELATIVE_SLACK = 1e-5;
/** Buckets of distance over the light's reach in which its still hulls are ordered, near first (see `addStillHulls`). */
const NEAR_BUCKETS = 32;
/** The shader's radius for a hard light (shadow-visibility's MIN_RADIUS). */
const MIN_RADIUS = 1e-3;
/** Room for a convex polygon clipped by the half-planes of one record: the box's 4 corners, one more per half-plane. */
const POLYGON_CAPACITY = 4 + 2 * RECORD_POINTS + RECORD_POINTS + 3;

/**
 * The per-light tile classes (see shadowLayout, TILE_CLASSES): every shadowed point light's box
 * (its filed bounds) cut into TILE_GRID² tiles, each found **lit** (no hull can hide any part of the
 * disk from any of its pixels), **dark** (one record hides the whole disk from all of them, and no
 * record lies in it where the light lights the inside of hulls), **outside** the light's reach, or
 * **held** (an Illuminated light's dark tile with a record in it: lit inside hulls, dark elsewhere),
 * or exact (anything else: the shader computes it), **lean** or **general**. Lit and dark are proven,
 * never guessed, by two convex regions per record P of disk D (centre o, radius R, with D and P apart):
 *
 * - **The shadow region** S(P), the points from which some segment to D meets P, lies on P's side
 *   of every line that separates P from D: the tangents from P's corners to D that have P and D on
 *   opposite sides, P's edges that face the whole disk, and the line through P's point nearest o.
 *   (For x beyond such a line, a segment from x to a point of D stays off P's side.) A tile that
 *   this clipped region misses is lit by P; a disk that meets P may shadow any point.
 * - **The umbra** with P, U(P) ∪ P, the points whose every segment to D meets P, is convex (the
 *   intersection over d ∈ D of the point shadows, each convex) and is exactly the intersection of
 *   the tangents from P's corners to D that have P and D on the same side, and the inner sides of
 *   P's edges that some point of D lies outside of: for each d its point shadow is bounded by the
 *   two lines from d through P's silhouette corners and by P's edges facing d, whose extremes over
 *   D are those tangents and edges. A tile wholly inside is dark (inside P too, for a Solid light).
 * - **In front.** From a point x of S(P), the disk lies wholly beyond P in P's wedge (the lean
 *   program's one case): S(P) lies on P's side of a line that separates P from D (above), so x
 *   and P lie on one side of it and D on the other, and every ray from x that meets P meets it
 *   before the line and D after. From a point outside S(P), P hides nothing. So an exact tile is
 *   lean unless a record meets the disk (then every exact tile is general) or, for an Occluded
 *   light, a record's box touches the tile (a pixel inside a hull takes the holder pass).
 *
 * Computed when a light is filed, from the still hulls (kept with the filing, so static lights and
 * walls cost nothing per frame), and per frame a lit tile that a moving hull's shadow region
 * touches becomes exact (and, but for a Solid light, a dark tile it lies in). Classified for the
 * filed disk and reach, which hold the light's own while the filing does, so the classes hold too.
 */
export class LightTiles {
  /**
   * The classes as the light pass draws them: per filing row a slot of ROW_INDICES indices of the
   * tile grid's corners (`tileCorner`), its rectangles' triangles (six indices each), grouped by
   * class in the order of DRAWN_CLASSES. A rectangle is a run of tiles of one class along a tile
   * row, merged with the same run in the rows after it: few, large triangles, and few pixel blocks
   * shaded twice along their edges.
   */
  rectangles = new Uint16Array(ROW_INDICES);
  /** Per filing row, the indices at the start of its slot that its rectangles use. */
  usedIndices = new Int32Array(1);
  /** Per row: 1 when its rectangles were written since {@link LightTiles.beginFrame}. */
  dirtyRows = new Uint8Array(1);
  /** Per filing row and class: where the class's indices start in the row's slot, and how many. */
  private listFirst = new Int32Array(TILE_CLASS_COUNT);
  private listCount = new Int32Array(TILE_CLASS_COUNT);
  /**
   * Per filing row, TILE_GRID masks each (tile row j at `row × TILE_GRID + j`): the tiles beyond the
   * reach; the dark and exact ones from the still hulls alone (kept with the filing); and those the
   * rectangles show now. Outside, dark, held and exact are disjoint, general lies within exact; a
   * tile in none is lit.
   */
  private outside = new Int32Array(TILE_GRID);
  private keptDark = new Int32Array(TILE_GRID);
  private keptExact = new Int32Array(TILE_GRID);
  private dark = new Int32Array(TILE_GRID);
  private exact = new Int32Array(TILE_GRID);
  /** The exact tiles that take the general program (the others the lean one), kept and shown. */
  private keptGeneral = new Int32Array(TILE_GRID);
  private general = new Int32Array(TILE_GRID);
  /** The held tiles, kept and shown. */
  private keptHeld = new Int32Array(TILE_GRID);
  /** For an Illuminated light, the tiles wholly inside a still record: lit, whatever else hides the disk (kept only). */
  private keptInside = new Int32Array(TILE_GRID);
  private held = new Int32Array(TILE_GRID);
  /** Per row, its tiles of each class. */
  private counts = new Int32Array(TILE_CLASS_COUNT);
  /** Per tile row of the light being classified: the tiles it may be shadowed in, dark in, with a record in them. */
  private readonly shadowed = new Int32Array(TILE_GRID);
  private readonly darkened = new Int32Array(TILE_GRID);
  private readonly occupied = new Int32Array(TILE_GRID);
  /** Per tile row of the light being classified, for an Illuminated light: the tiles wholly inside a record. */
  private readonly inside = new Int32Array(TILE_GRID);
  /** Scratch of the near-first order of a light's still hulls: the order, each hull's bucket, where each bucket starts. */
  private order = new Int32Array(0);
  private bucketOfHull = new Uint8Array(0);
  private readonly bucketStarts = new Int32Array(NEAR_BUCKETS + 1);
  /**
   * The rectangles being written (see `writeRectangles`): those open at the current tile row and
   * at the next (first tile, last tile, class, first tile row), and per class its indices.
   */
  private openStart = new Int32Array(TILE_GRID);
  private openEnd = new Int32Array(TILE_GRID);
  private openClass = new Int32Array(TILE_GRID);
  private openRow = new Int32Array(TILE_GRID);
  private nextOpenStart = new Int32Array(TILE_GRID);
  private nextOpenEnd = new Int32Array(TILE_GRID);
  private nextOpenClass = new Int32Array(TILE_GRID);
  private nextOpenRow = new Int32Array(TILE_GRID);
  private readonly classIndices = Array.from({ length: TILE_CLASS_COUNT }, () => new Uint16Array(ROW_INDICES));
  private readonly classLengths = new Int32Array(TILE_CLASS_COUNT);
  /** One tile row's masks per class (`splitClasses`). */
  private readonly rowClasses = new Int32Array(TILE_CLASS_COUNT);
  /** A row's classes as a moving hull leaves them, before they are shown. */
  private readonly nextDark = new Int32Array(TILE_GRID);
  private readonly nextExact = new Int32Array(TILE_GRID);
  private readonly nextGeneral = new Int32Array(TILE_GRID);
  private readonly nextHeld = new Int32Array(TILE_GRID);
  private readonly noTiles = new Int32Array(TILE_GRID);
  /** The rasterization's x range per tile row (touched) and per tile row boundary (the polygon's chord there). */
  private readonly rowLeft = new Float64Array(TILE_GRID);
  private readonly rowRight = new Float64Array(TILE_GRID);
  private readonly chordLeft = new Float64Array(TILE_GRID + 1);
  private readonly chordRight = new Float64Array(TILE_GRID + 1);
  /** Polygon scratch (x, y pairs), ping-ponged by the clipping. */
  private polygon = new Float64Array(2 * POLYGON_CAPACITY);
  private clipped = new Float64Array(2 * POLYGON_CAPACITY);
  private polygonCount = 0;
  /** The polygon's least and greatest y, as `measurePolygonHeight` found them. */
  private polygonMinY = 0;
  private polygonMaxY = 0;
  /** The loaded record's corners without repeats, `pointCount` of them, counter-clockwise. */
  private readonly xs = new Float64Array(RECORD_POINTS);
  private readonly ys = new Float64Array(RECORD_POINTS);
  private pointCount = 0;
  /** Half-planes `a·x + b·y ≤ c`: the shadow region's and the umbra's, for the loaded record. */
  private readonly shadowPlanes = new Float64Array(3 * (3 * RECORD_POINTS + 2));
  /** The corners the shadow region's tangents touch: how many, and the first two. */
  private tangentCorners = 0;
  private readonly tangentX = new Float64Array(2);
  private readonly tangentY = new Float64Array(2);
  private shadowPlaneCount = 0;
  private readonly umbraPlanes = new Float64Array(3 * (3 * RECORD_POINTS));
  /** The half-planes of the loaded record's inside, its edges moved in by the slack. */
  private readonly insidePlanes = new Float64Array(3 * RECORD_POINTS);
  private umbraPlaneCount = 0;
  /** The plane being added, `[a, b, c]`. */
  private readonly plane = new Float64Array(3);
  /** The box being marked occupied, `[minX, minY, maxX, maxY]`. */
  private readonly box = new Float64Array(4);
  /** The light being classified: box, tile size, disk, reach, whether it is confined to its range disk and lights the inside of hulls. */
  private minX = 0;
  private minY = 0;
  private tileWidth = 1;
  private tileHeight = 1;
  private centreX = 0;
  private centreY = 0;
  private radius = 0;
  private reach = 0;
  private slack = 0;
  private confined = true;
  private solid = true;
  /** Whether a pixel inside a hull takes the holder pass (an Occluded light). */
  private holderPass = false;
  /** Whether a record added since `beginLight` met the disk: every exact tile is then general. */
  private diskMet = false;

  /** Starts a frame: no row is dirty. */
  beginFrame(): void {
    this.dirtyRows.fill(0);
  }

  /** Writes the tiles of each class in `row` (the light pass skips a class it has none of) into `out`, indexed by class. */
  writeCounts(row: number, out: Int32Array): void {
    for (let c = 0; c < TILE_CLASS_COUNT; c++) out[c] = this.counts[row * TILE_CLASS_COUNT + c];
  }

  /** Writes, per class of `row`, where its indices start in `rectangles` and how many there are, into `out[2 × class]` and `out[2 × class + 1]`. */
  writeLists(row: number, out: Int32Array): void {
    for (let c = 0; c < TILE_CLASS_COUNT; c++) {
      out[2 * c] = row * ROW_INDICES + this.listFirst[row * TILE_CLASS_COUNT + c];
      out[2 * c + 1] = this.listCount[row * TILE_CLASS_COUNT + c];
    }
  }

  /** The class (TILE_CLASSES) of tile `tile` (`j × TILE_GRID + i`) of `row`, as its rectangles show it. */
  tileClass(row: number, tile: number): number {
    this.splitClasses(row * TILE_GRID + Math.floor(tile / TILE_GRID));
    return this.classOfTile(tile % TILE_GRID);
  }

  /**
   * Starts classifying a light: its box `[minX, minY, maxX, maxY]` (the grid), its filed disk and
   * reach (`[x, y, radius, reach, …]`, see {@link FiledDisk}); `confined`: it adds nothing beyond
   * its reach; `shadowType`: how it treats the inside of hulls (SHADOW_TYPE_CODES).
   */
  beginLight(bounds: Float64Array, disk: FiledDisk, confined: boolean, shadowType: number): void {
    const x = disk[0], y = disk[1], radius = disk[2], reach = disk[3];
    this.minX = bounds[0];
    this.minY = bounds[1];
    this.tileWidth = Math.max(bounds[2] - bounds[0], 1e-9) / TILE_GRID;
    this.tileHeight = Math.max(bounds[3] - bounds[1], 1e-9) / TILE_GRID;
    this.centreX = x;
    this.centreY = y;
    this.slack = RELATIVE_SLACK * Math.max(Math.abs(bounds[0]), Math.abs(bounds[1]), Math.abs(bounds[2]), Math.abs(bounds[3]), bounds[2] - bounds[0], bounds[3] - bounds[1]);
    this.radius = Math.max(radius, MIN_RADIUS) + this.slack;
    this.reach = reach;
    this.confined = confined;
    this.solid = shadowType === SHADOW_TYPE_CODES.solid;
    this.holderPass = shadowType === SHADOW_TYPE_CODES.occluded;
    this.diskMet = false;
    this.shadowed.fill(0);
    this.darkened.fill(0);
    this.occupied.fill(0);
    this.inside.fill(0);
  }

  /**
   * Adds the records of the `count` hulls at `indices` (prepared) to the light being classified,
   * nearest first, leaving out a hull that lies wholly in tiles already dark: each of its points
   * is then in some nearer record Q's umbra or in Q, so every segment through it to the disk meets
   * Q, and its shadow region and umbra lie in those of the records before it.
   */
  addStillHulls(geometry: ShadowGeometry, indices: Int32Array, count: number): void {
    const order = this.nearestFirst(geometry, indices, count);
    for (let i = 0; i < count; i++) {
      const hull = order[i];
      const first = geometry.firstRecords[hull], end = first + geometry.recordCounts[hull];
      if (this.boundsWithin(geometry.worldBounds, hull, this.darkened, 0)) {
        if (!this.solid) this.markBox(geometry.worldBounds, hull);
        if (this.illuminated()) for (let record = first; record < end; record++) this.markInside(geometry.records, record);
        continue;
      }
      for (let record = first; record < end; record++) {
        const apart = this.loadRecord(geometry.records, record);
        if (this.illuminated()) this.markInsideLoaded();
        if (!apart) continue;
        this.markShadowRegion();
        this.markUmbra();
        if (!this.solid) this.markRecordBox();
      }
    }
  }

  /** `indices`' first `count` hulls in buckets of their nearest distance to the light's centre (NEAR_BUCKETS over its reach), nearest first. */
  private nearestFirst(geometry: ShadowGeometry, indices: Int32Array, count: number): Int32Array {
    if (this.order.length < count) {
      this.order = new Int32Array(2 * count);
      this.bucketOfHull = new Uint8Array(2 * count);
    }
    const circles = geometry.circles, starts = this.bucketStarts, buckets = this.bucketOfHull, scale = NEAR_BUCKETS / Math.max(this.reach, 1e-9);
    starts.fill(0);
    for (let i = 0; i < count; i++) {
      const hull = indices[i], dx = circles[3 * hull] - this.centreX, dy = circles[3 * hull + 1] - this.centreY;
      const bucket = Math.min(NEAR_BUCKETS - 1, Math.max(0, Math.floor((Math.sqrt(dx * dx + dy * dy) - circles[3 * hull + 2]) * scale)));
      buckets[i] = bucket;
      starts[bucket + 1]++;
    }
    for (let b = 0; b < NEAR_BUCKETS; b++) starts[b + 1] += starts[b];
    for (let i = 0; i < count; i++) this.order[starts[buckets[i]]++] = indices[i];
    return this.order;
  }

  /** Whether hull `hull`'s box in `bounds` lies wholly in tiles set in `masks` (rows from `from`), inside the grid. */
  private boundsWithin(bounds: Float64Array, hull: number, masks: Int32Array, from: number): boolean {
    const tw = this.tileWidth, th = this.tileHeight;
    const first = Math.floor((bounds[4 * hull] - this.slack - this.minX) / tw), last = Math.floor((bounds[4 * hull + 2] + this.slack - this.minX) / tw);
    const firstRow = Math.floor((bounds[4 * hull + 1] - this.slack - this.minY) / th), lastRow = Math.floor((bounds[4 * hull + 3] + this.slack - this.minY) / th);
    if (first < 0 || last >= TILE_GRID || firstRow < 0 || lastRow >= TILE_GRID) return false;
    const span = (FULL_ROW >>> (TILE_GRID - 1 - last)) & (FULL_ROW << first);
    for (let j = firstRow; j <= lastRow; j++) if ((masks[from + j] & span) !== span) return false;
    return true;
  }

  /** Ends the still hulls' classification of `row` (a new filing): its kept classes, which its rectangles then show. */
  endLight(row: number): void {
    this.ensureRow(row);
    const at = row * TILE_GRID;
    for (let j = 0; j < TILE_GRID; j++) {
      this.writeOutside(at, j);
      const outside = this.outside[at + j], inside = this.inside[j];
      const dark = this.darkened[j] & ~outside & (this.solid ? FULL_ROW : ~this.occupied[j]);
      const held = this.illuminated() ? this.darkened[j] & this.occupied[j] & ~outside & ~inside : 0;
      this.keptDark[at + j] = dark;
      this.keptHeld[at + j] = held;
      this.keptInside[at + j] = inside;
      this.keptExact[at + j] = this.shadowed[j] & ~dark & ~held & ~outside & ~inside;
      this.keptGeneral[at + j] = this.keptExact[at + j] & this.generalMask(j);
    }
    this.show(row, this.keptDark, this.keptExact, this.keptGeneral, this.keptHeld, at, true);
  }

  /** Whether the light being classified lights the inside of hulls from anywhere (Illuminated): its dark tiles with a record in them are then held. */
  private illuminated(): boolean {
    return !this.solid && !this.holderPass;
  }

  /** The tiles of tile row `j` whose exact pixels take the general program, by the records added since {@link LightTiles.beginLight}. */
  private generalMask(j: number): number {
    return this.diskMet ? FULL_ROW : this.holderPass ? this.occupied[j] : 0;
  }

  /** Shows `row`'s kept classes (a light whose moving hulls left it). */
  restoreKept(row: number): void {
    this.ensureRow(row);
    this.show(row, this.keptDark, this.keptExact, this.keptGeneral, this.keptHeld, row * TILE_GRID, false);
  }

  /**
   * Ends the classification of `row` (a new filing, begun with {@link LightTiles.beginLight}) with
   * every tile within the reach exact: the classes of a light left unclassified.
   */
  endUnclassified(row: number): void {
    this.ensureRow(row);
    const at = row * TILE_GRID;
    for (let j = 0; j < TILE_GRID; j++) {
      this.writeOutside(at, j);
      this.keptDark[at + j] = this.keptHeld[at + j] = this.keptInside[at + j] = 0;
      this.keptExact[at + j] = this.keptGeneral[at + j] = FULL_ROW & ~this.outside[at + j];
    }
    this.show(row, this.keptDark, this.keptExact, this.keptGeneral, this.keptHeld, at, true);
  }

  /**
   * Shows `row`'s kept classes as they may be with moving hulls not looked at: every lit tile
   * exact (general), and, unless the light is Solid (as set by {@link LightTiles.beginLight}),
   * every dark one.
   */
  addUnknownHulls(row: number): void {
    const at = row * TILE_GRID, dark = this.nextDark, exact = this.nextExact;
    for (let j = 0; j < TILE_GRID; j++) {
      dark[j] = this.solid ? this.keptDark[at + j] : 0;
      exact[j] = FULL_ROW & ~this.outside[at + j] & ~dark[j] & ~this.keptInside[at + j];
    }
    this.show(row, dark, exact, exact, this.noTiles, 0, false);
  }

  /**
   * Shows `row`'s kept classes less what the `count` moving hulls at `indices` (prepared) may
   * change: the lit tiles their shadow regions touch, and, unless `solid` (set by the last
   * {@link LightTiles.beginLight} for this light's filing, with `bounds`, disk and reach as there),
   * the dark tiles they lie in, become exact (general where `generalMask` says; held for an
   * Illuminated light). Held tiles stay held: outside hulls they lie in a still record's umbra.
   */
  addMovingHulls(row: number, geometry: ShadowGeometry, indices: Int32Array, count: number): void {
    for (let i = 0; i < count; i++) {
      const hull = indices[i];
      // Wholly in kept dark tiles, its shadow region lies in the still records' (as addStillHulls).
      if (this.boundsWithin(geometry.worldBounds, hull, this.keptDark, row * TILE_GRID)) {
        if (!this.solid) this.markBox(geometry.worldBounds, hull);
        continue;
      }
      for (let record = geometry.firstRecords[hull], end = record + geometry.recordCounts[hull]; record < end; record++) {
        if (!this.loadRecord(geometry.records, record)) continue;
        this.markShadowRegion();
        if (!this.solid) this.markRecordBox();
      }
    }
    const at = row * TILE_GRID, dark = this.nextDark, exact = this.nextExact, general = this.nextGeneral, held = this.nextHeld;
    const illuminated = this.illuminated();
    for (let j = 0; j < TILE_GRID; j++) {
      const keptDark = this.keptDark[at + j], keptExact = this.keptExact[at + j], keptHeld = this.keptHeld[at + j];
      const keptInside = this.keptInside[at + j], lit = FULL_ROW & ~(this.outside[at + j] | keptDark | keptExact | keptHeld | keptInside);
      const lost = this.solid ? 0 : keptDark & this.occupied[j];
      dark[j] = keptDark & ~lost;
      held[j] = keptHeld | (illuminated ? lost : 0);
      exact[j] = keptExact | (this.shadowed[j] & lit) | (illuminated ? 0 : lost);
      general[j] = this.keptGeneral[at + j] | (exact[j] & this.generalMask(j));
    }
    this.show(row, dark, exact, general, held, 0, false);
  }

  /**
   * Shows `row` with the masks `dark[from + j]`, `exact[from + j]`, `general[from + j]` (within
   * exact) and `held[from + j]`: when a tile row changed (or `force`, for a new filing), rewrites
   * the row's rectangles, recounts it and marks it dirty.
   */
  private show(row: number, dark: Int32Array, exact: Int32Array, general: Int32Array, held: Int32Array, from: number, force: boolean): void {
    const at = row * TILE_GRID;
    let changed = false;
    for (let j = 0; j < TILE_GRID; j++) {
      const d = dark[from + j], e = exact[from + j], g = general[from + j], h = held[from + j];
      if (!force && d === this.dark[at + j] && e === this.exact[at + j] && g === this.general[at + j] && h === this.held[at + j]) continue;
      this.dark[at + j] = d;
      this.exact[at + j] = e;
      this.general[at + j] = g;
      this.held[at + j] = h;
      changed = true;
    }
    if (!changed) return;
    this.writeRectangles(row);
    this.dirtyRows[row] = 1;
    let outside = 0, darkCount = 0, exactCount = 0, generalCount = 0, heldCount = 0;
    for (let j = 0; j < TILE_GRID; j++) {
      outside += bitCount(this.outside[at + j]);
      darkCount += bitCount(this.dark[at + j]);
      exactCount += bitCount(this.exact[at + j]);
      generalCount += bitCount(this.general[at + j]);
      heldCount += bitCount(this.held[at + j]);
    }
    const counts = this.counts, c = row * TILE_CLASS_COUNT;
    counts[c + TILE_CLASSES.outside] = outside;
    counts[c + TILE_CLASSES.dark] = darkCount;
    counts[c + TILE_CLASSES.lean] = exactCount - generalCount;
    counts[c + TILE_CLASSES.exact] = generalCount;
    counts[c + TILE_CLASSES.held] = heldCount;
    counts[c + TILE_CLASSES.lit] = TILE_COUNT - outside - darkCount - exactCount - heldCount;
  }

  /**
   * Writes `row`'s rectangles from its masks: per tile row, its runs of one class, each merged
   * with an open rectangle of the rows above that spans the same tiles in the same class, else
   * opening one; a rectangle not continued is closed and written into its class's list.
   */
  private writeRectangles(row: number): void {
    let open = 0;
    this.classLengths.fill(0);
    for (let j = 0; j <= TILE_GRID; j++) {
      let kept = 0, k = 0;
      if (j < TILE_GRID) this.splitClasses(row * TILE_GRID + j);
      for (let i = 0; i < TILE_GRID && j < TILE_GRID;) {
        const value = this.classOfTile(i), last = i + runFrom(this.rowClasses[value], i) - 1;
        while (k < open && this.openStart[k] < i) this.closeRectangle(k++, j);
        if (k < open && this.openStart[k] === i && this.openEnd[k] === last && this.openClass[k] === value) {
          this.keepOpen(kept++, i, last, value, this.openRow[k++]);
        } else {
          if (k < open && this.openStart[k] === i) this.closeRectangle(k++, j);
          if (value !== TILE_CLASSES.outside) this.keepOpen(kept++, i, last, value, j);
        }
        i = last + 1;
      }
      while (k < open) this.closeRectangle(k++, j);
      this.swapOpen();
      open = kept;
    }
    this.gatherLists(row);
  }

  /**
   * Sets `rowClasses` to the masks of each class in tile row `word`: outside before dark before
   * held before exact (general or lean), the rest lit.
   */
  private splitClasses(word: number): void {
    const masks = this.rowClasses, outside = this.outside[word], dark = this.dark[word] & ~outside;
    const held = this.held[word] & ~outside & ~dark, exact = this.exact[word] & ~outside & ~dark & ~held;
    masks[TILE_CLASSES.outside] = outside;
    masks[TILE_CLASSES.dark] = dark;
    masks[TILE_CLASSES.held] = held;
    masks[TILE_CLASSES.exact] = exact & this.general[word];
    masks[TILE_CLASSES.lean] = exact & ~this.general[word];
    masks[TILE_CLASSES.lit] = FULL_ROW & ~(outside | dark | held | exact);
  }

  /** The class of tile `i` in the row `splitClasses` split. */
  private classOfTile(i: number): number {
    let value = 0;
    while (((this.rowClasses[value] >> i) & 1) === 0) value++;
    return value;
  }

  /** Sets open rectangle `k` of the next tile row: tiles `start` to `end` of class `value`, from tile row `firstRow`. */
  private keepOpen(k: number, start: number, end: number, value: number, firstRow: number): void {
    this.nextOpenStart[k] = start;
    this.nextOpenEnd[k] = end;
    this.nextOpenClass[k] = value;
    this.nextOpenRow[k] = firstRow;
  }

  /** Makes the next tile row's open rectangles the current ones. */
  private swapOpen(): void {
    const start = this.openStart, end = this.openEnd, value = this.openClass, first = this.openRow;
    this.openStart = this.nextOpenStart;
    this.openEnd = this.nextOpenEnd;
    this.openClass = this.nextOpenClass;
    this.openRow = this.nextOpenRow;
    this.nextOpenStart = start;
    this.nextOpenEnd = end;
    this.nextOpenClass = value;
    this.nextOpenRow = first;
  }

  /** Writes open rectangle `k`, which ends above tile row `j`, as two triangles into its class's list. */
  private closeRectangle(k: number, j: number): void {
    const value = this.openClass[k], list = this.classIndices[value];
    const left = this.openStart[k], right = this.openEnd[k] + 1, top = this.openRow[k];
    const a = tileCorner(left, top), b = tileCorner(right, top), c = tileCorner(left, j), d = tileCorner(right, j);
    let n = this.classLengths[value];
    list[n++] = a;
    list[n++] = b;
    list[n++] = c;
    list[n++] = c;
    list[n++] = b;
    list[n++] = d;
    this.classLengths[value] = n;
  }

  /** Copies the classes' lists into `row`'s slot, one after the other, and notes where each starts. */
  private gatherLists(row: number): void {
    const slot = row * ROW_INDICES, at = row * TILE_CLASS_COUNT;
    let n = 0;
    this.listCount[at + TILE_CLASSES.outside] = 0;
    for (let c = 0; c < DRAWN_CLASSES.length; c++) {
      const value = DRAWN_CLASSES[c], list = this.classIndices[value], length = this.classLengths[value];
      this.listFirst[at + value] = n;
      this.listCount[at + value] = length;
      for (let k = 0; k < length; k++) this.rectangles[slot + n + k] = list[k];
      n += length;
    }
    this.usedIndices[row] = n;
  }

  private ensureRow(row: number): void {
    const needed = (row + 1) * TILE_GRID;
    if (this.keptDark.length >= needed) return;
    const words = Math.max(needed, 2 * this.keptDark.length), rows = words / TILE_GRID;
    this.outside = grown(this.outside, words);
    this.keptDark = grown(this.keptDark, words);
    this.keptExact = grown(this.keptExact, words);
    this.dark = grown(this.dark, words);
    this.exact = grown(this.exact, words);
    this.keptGeneral = grown(this.keptGeneral, words);
    this.general = grown(this.general, words);
    this.keptHeld = grown(this.keptHeld, words);
    this.keptInside = grown(this.keptInside, words);
    this.held = grown(this.held, words);
    const rectangles = new Uint16Array(rows * ROW_INDICES), used = new Int32Array(rows), dirty = new Uint8Array(rows);
    rectangles.set(this.rectangles);
    used.set(this.usedIndices);
    dirty.set(this.dirtyRows);
    this.rectangles = rectangles;
    this.usedIndices = used;
    this.dirtyRows = dirty;
    this.counts = grown(this.counts, rows * TILE_CLASS_COUNT);
    this.listFirst = grown(this.listFirst, rows * TILE_CLASS_COUNT);
    this.listCount = grown(this.listCount, rows * TILE_CLASS_COUNT);
  }

  /** Writes the mask of the tiles of tile row `j` that lie wholly beyond the reach of the filing's centre (none for a light not confined to it) at `outside[at + j]`. */
  private writeOutside(at: number, j: number): void {
    const y0 = this.minY + j * this.tileHeight, reach = this.reach + this.slack;
    const dy = Math.max(y0 - this.centreY, 0, this.centreY - y0 - this.tileHeight);
    this.outside[at + j] = this.confined ? FULL_ROW : 0;
    if (!this.confined || dy > reach) return;
    // Tile i is within reach when it meets [centre − w, centre + w] (its nearest point within the reach).
    const w = Math.sqrt(reach * reach - dy * dy);
    const first = Math.max(0, Math.ceil((this.centreX - w - this.minX) / this.tileWidth - 1));
    const last = Math.min(TILE_GRID - 1, Math.floor((this.centreX + w - this.minX) / this.tileWidth));
    if (first <= last) this.outside[at + j] = FULL_ROW & ~((FULL_ROW >>> (TILE_GRID - 1 - last)) & (FULL_ROW << first));
  }

  /**
   * Loads the record's distinct corners and the half-planes of its shadow region and umbra; false
   * when the disk meets the record (its shadow region is then every tile, which it marks, and it
   * has no umbra taken).
   */
  private loadRecord(records: Float32Array, record: number): boolean {
    this.loadPoints(records, record);
    this.shadowPlaneCount = 0;
    this.umbraPlaneCount = 0;
    if (this.diskMeetsRecord()) {
      this.shadowed.fill(FULL_ROW);
      this.diskMet = true;
      return false;
    }
    this.findPlanes();
    return true;
  }

  /** Loads the record's distinct corners into `xs`, `ys` and `pointCount`. */
  private loadPoints(records: Float32Array, record: number): void {
    const xs = this.xs, ys = this.ys;
    let n = 0;
    for (let k = 0; k < RECORD_POINTS; k++) {
      const x = records[record * RECORD_FLOATS + 2 * k], y = records[record * RECORD_FLOATS + 2 * k + 1];
      if (n > 0 && x === xs[n - 1] && y === ys[n - 1]) continue;
      if (k === RECORD_POINTS - 1 && n > 0 && x === xs[0] && y === ys[0]) continue;
      xs[n] = x;
      ys[n] = y;
      n++;
    }
    this.pointCount = n;
  }

  /** Marks in `inside` the tiles wholly inside the record (see {@link LightTiles.markInsideLoaded}). */
  private markInside(records: Float32Array, record: number): void {
    this.loadPoints(records, record);
    this.markInsideLoaded();
  }

  /**
   * Marks in `inside` the tiles wholly inside the loaded record, its edges moved in by the slack:
   * an Illuminated light lights a pixel inside a hull fully, whatever hides the disk from it (the
   * shader's walk finds the record holding it). A record too small to hold a tile is passed over.
   */
  private markInsideLoaded(): void {
    const xs = this.xs, ys = this.ys, n = this.pointCount, slack = this.slack;
    if (n < 3) return;
    let minX = Infinity, minY = Infinity, maxX = -Infinity, maxY = -Infinity;
    for (let k = 0; k < n; k++) {
      minX = Math.min(minX, xs[k]);
      minY = Math.min(minY, ys[k]);
      maxX = Math.max(maxX, xs[k]);
      maxY = Math.max(maxY, ys[k]);
    }
    if (maxX - minX < this.tileWidth + 2 * slack || maxY - minY < this.tileHeight + 2 * slack) return;
    const planes = this.insidePlanes;
    let count = 0;
    for (let k = 0; k < n; k++) {
      const ax = xs[k], ay = ys[k], ex = xs[(k + 1) % n] - ax, ey = ys[(k + 1) % n] - ay, length = Math.sqrt(ex * ex + ey * ey);
      // The outward normal of a counter-clockwise edge; inside lies a slack within.
      const nx = ey / length, ny = -ex / length;
      planes[3 * count] = nx;
      planes[3 * count + 1] = ny;
      planes[3 * count + 2] = nx * ax + ny * ay - slack;
      count++;
    }
    this.clipBox(planes, count);
    this.markCovered(this.inside);
  }

  /** Whether the disk, widened by the slack, meets the loaded record: its centre inside, or within a radius of an edge. */
  private diskMeetsRecord(): boolean {
    const xs = this.xs, ys = this.ys, n = this.pointCount, cx = this.centreX, cy = this.centreY, r = this.radius;
    let inside = n >= 3;
    for (let k = 0; k < n; k++) {
      const ax = xs[k], ay = ys[k], bx = xs[(k + 1) % n], by = ys[(k + 1) % n];
      const ex = bx - ax, ey = by - ay, length2 = ex * ex + ey * ey;
      const along = length2 > 0 ? Math.min(Math.max(((cx - ax) * ex + (cy - ay) * ey) / length2, 0), 1) : 0;
      const ox = cx - ax - along * ex, oy = cy - ay - along * ey;
      if (ox * ox + oy * oy <= r * r) return true;
      if (ex * (cy - ay) - ey * (cx - ax) < 0) inside = false;
    }
    return inside;
  }

  /**
   * The half-planes of the loaded record (the disk apart from it): per corner, its two tangents to
   * the disk that have the whole record on one side; per edge, its line when it faces the whole disk
   * (shadow region) or some of it (umbra); the line through the point nearest the centre; and for a
   * light that lights the inside of hulls, the chord between the shadow region's two tangent
   * corners (see `addChordPlane`).
   */
  private findPlanes(): void {
    const xs = this.xs, ys = this.ys, n = this.pointCount, cx = this.centreX, cy = this.centreY, r = this.radius;
    this.tangentCorners = 0;
    for (let k = 0; k < n; k++) {
      const vx = xs[k], vy = ys[k];
      const dx = cx - vx, dy = cy - vy, distance = Math.sqrt(dx * dx + dy * dy);
      const sine = r / distance, cosine = Math.sqrt(Math.max(0, 1 - sine * sine));
      for (let side = -1; side <= 1; side += 2) {
        // The tangent's direction: towards the centre turned by ±asin(r / distance); its normal.
        const ux = (dx * cosine - side * dy * sine) / distance, uy = (dy * cosine + side * dx * sine) / distance;
        const nx = -uy, ny = ux;
        let least = Infinity, most = -Infinity;
        for (let m = 0; m < n; m++) {
          const s = nx * (xs[m] - vx) + ny * (ys[m] - vy);
          if (s < least) least = s;
          if (s > most) most = s;
        }
        const diskSide = nx * dx + ny * dy;
        const eps = this.slack;
        // The record on the + side (sign −1: the plane keeps that side) or the − side; the disk on
        // the same side (the umbra's plane) or the other (the shadow region's).
        const sign = least >= -eps ? -1 : most <= eps ? 1 : 0;
        if (sign === 0) continue;
        const umbra = sign * diskSide < 0, plane = this.plane;
        plane[0] = sign * nx;
        plane[1] = sign * ny;
        plane[2] = sign * (nx * vx + ny * vy) + (umbra ? -eps : eps);
        this.addPlane(umbra);
        if (!umbra) this.noteTangentCorner(k);
      }
    }
    if (!this.solid && !this.holderPass) this.addChordPlane();
    let nearest2 = Infinity, nearestX = 0, nearestY = 0;
    for (let k = 0; k < n; k++) {
      const ax = xs[k], ay = ys[k], bx = xs[(k + 1) % n], by = ys[(k + 1) % n];
      const ex = bx - ax, ey = by - ay, length = Math.sqrt(ex * ex + ey * ey);
      if (length > 0) {
        // Outward normal of a counter-clockwise edge; the centre's distance outward.
        const nx = ey / length, ny = -ex / length, outward = nx * (cx - ax) + ny * (cy - ay);
        const plane = this.plane;
        plane[0] = nx;
        plane[1] = ny;
        plane[2] = nx * ax + ny * ay + this.slack;
        if (outward > r) this.addPlane(false);
        // The umbra needs every edge some disk point lies outside of.
        plane[2] = nx * ax + ny * ay - this.slack;
        if (outward > -r) this.addPlane(true);
      }
      const along = length > 0 ? Math.min(Math.max(((cx - ax) * ex + (cy - ay) * ey) / (length * length), 0), 1) : 0;
      const px = ax + along * ex, py = ay + along * ey, d2 = (px - cx) * (px - cx) + (py - cy) * (py - cy);
      if (d2 < nearest2) {
        nearest2 = d2;
        nearestX = px;
        nearestY = py;
      }
    }
    const distance = Math.sqrt(nearest2);
    if (distance > 0) {
      const nx = (cx - nearestX) / distance, ny = (cy - nearestY) / distance;
      const plane = this.plane;
      plane[0] = nx;
      plane[1] = ny;
      plane[2] = nx * nearestX + ny * nearestY + this.slack;
      this.addPlane(false);
    }
  }

  /** Notes corner `k` as one a tangent of the shadow region touches (the first two in `tangentX`, `tangentY`). */
  private noteTangentCorner(k: number): void {
    if (this.tangentCorners < 2) {
      this.tangentX[this.tangentCorners] = this.xs[k];
      this.tangentY[this.tangentCorners] = this.ys[k];
    }
    this.tangentCorners++;
  }

  /**
   * For an Illuminated light, whose pixels inside a hull are lit: the record shades only the part
   * of its shadow region outside it, which lies beyond the chord between the two corners t1, t2 the
   * region's tangents touch, when the disk lies wholly on the other side. (A point x outside P
   * whose segment to d in D meets P leaves P through its chain between t1 and t2 away from D, which
   * lies beyond the chord; the segment from d, on the near side, goes on beyond it.) Left out when
   * more than two corners touch a tangent (an edge along one) or the disk meets the chord's line.
   */
  private addChordPlane(): void {
    if (this.tangentCorners !== 2) return;
    const ax = this.tangentX[0], ay = this.tangentY[0], ex = this.tangentX[1] - ax, ey = this.tangentY[1] - ay, length = Math.sqrt(ex * ex + ey * ey);
    if (length === 0) return;
    // The chord's normal towards the side away from the centre.
    let nx = ey / length, ny = -ex / length;
    const centreSide = nx * (this.centreX - ax) + ny * (this.centreY - ay);
    if (Math.abs(centreSide) <= this.radius) return;
    if (centreSide > 0) {
      nx = -nx;
      ny = -ny;
    }
    const plane = this.plane;
    plane[0] = -nx;
    plane[1] = -ny;
    plane[2] = -(nx * ax + ny * ay) + this.slack;
    this.addPlane(false);
  }

  /** Adds `plane` (`a·x + b·y ≤ c`, the slack already in c) to the umbra's half-planes or the shadow region's. */
  private addPlane(umbra: boolean): void {
    const planes = umbra ? this.umbraPlanes : this.shadowPlanes, k = 3 * (umbra ? this.umbraPlaneCount++ : this.shadowPlaneCount++);
    planes[k] = this.plane[0];
    planes[k + 1] = this.plane[1];
    planes[k + 2] = this.plane[2];
  }

  /** Marks in `shadowed` the tiles the loaded record's shadow region touches. */
  private markShadowRegion(): void {
    this.clipBox(this.shadowPlanes, this.shadowPlaneCount);
    this.markTouched(this.shadowed);
  }

  /** Marks in `darkened` the tiles wholly inside the loaded record's umbra. */
  private markUmbra(): void {
    this.clipBox(this.umbraPlanes, this.umbraPlaneCount);
    this.markCovered(this.darkened);
  }

  /** Marks in `occupied` the tiles the loaded record's bounding box touches. */
  private markRecordBox(): void {
    const xs = this.xs, ys = this.ys, box = this.box;
    box[0] = box[1] = Infinity;
    box[2] = box[3] = -Infinity;
    for (let k = 0; k < this.pointCount; k++) {
      box[0] = Math.min(box[0], xs[k]);
      box[1] = Math.min(box[1], ys[k]);
      box[2] = Math.max(box[2], xs[k]);
      box[3] = Math.max(box[3], ys[k]);
    }
    this.markOccupied();
  }

  /** Marks in `occupied` the tiles hull `hull`'s box in `bounds` touches. */
  private markBox(bounds: Float64Array, hull: number): void {
    for (let k = 0; k < 4; k++) this.box[k] = bounds[4 * hull + k];
    this.markOccupied();
  }

  /** Marks in `occupied` the tiles `box` touches, widened by the slack. */
  private markOccupied(): void {
    const minX = this.box[0], minY = this.box[1], maxX = this.box[2], maxY = this.box[3];
    const first = Math.max(0, Math.floor((minX - this.slack - this.minX) / this.tileWidth));
    const last = Math.min(TILE_GRID - 1, Math.floor((maxX + this.slack - this.minX) / this.tileWidth));
    const firstRow = Math.max(0, Math.floor((minY - this.slack - this.minY) / this.tileHeight));
    const lastRow = Math.min(TILE_GRID - 1, Math.floor((maxY + this.slack - this.minY) / this.tileHeight));
    if (first > last) return;
    for (let j = firstRow; j <= lastRow; j++) markSpan(this.occupied, j, first, last);
  }

  /** Sets the polygon to the light's box clipped by `count` half-planes. */
  private clipBox(planes: Float64Array, count: number): void {
    const p = this.polygon, x0 = this.minX, y0 = this.minY, x1 = x0 + TILE_GRID * this.tileWidth, y1 = y0 + TILE_GRID * this.tileHeight;
    p[0] = x0; p[1] = y0; p[2] = x1; p[3] = y0; p[4] = x1; p[5] = y1; p[6] = x0; p[7] = y1;
    this.polygonCount = 4;
    for (let k = 0; k < count && this.polygonCount > 0; k++) this.clip(planes, k);
  }

  /** Clips the polygon to the `k`-th of `planes`, `a·x + b·y ≤ c` (Sutherland–Hodgman; a convex polygon stays convex); a plane it lies within changes nothing. */
  private clip(planes: Float64Array, k: number): void {
    const a = planes[3 * k], b = planes[3 * k + 1], c = planes[3 * k + 2];
    const from = this.polygon, to = this.clipped, n = this.polygonCount;
    let outside = false;
    for (let i = 0; i < n; i++) {
      if (a * from[2 * i] + b * from[2 * i + 1] > c) {
        outside = true;
        break;
      }
    }
    if (!outside) return;
    let m = 0, px = from[2 * n - 2], py = from[2 * n - 1], sp = a * px + b * py - c;
    for (let i = 0; i < n; i++) {
      const qx = from[2 * i], qy = from[2 * i + 1], sq = a * qx + b * qy - c;
      // The edge from the previous corner p to q: its crossing, then q if inside.
      if ((sp < 0 && sq > 0) || (sp > 0 && sq < 0)) {
        const t = sp / (sp - sq);
        to[2 * m] = px + t * (qx - px);
        to[2 * m + 1] = py + t * (qy - py);
        m++;
      }
      if (sq <= 0) {
        to[2 * m] = qx;
        to[2 * m + 1] = qy;
        m++;
      }
      px = qx;
      py = qy;
      sp = sq;
    }
    this.polygon = to;
    this.clipped = from;
    this.polygonCount = m;
  }

  /** Sets `polygonMinY` and `polygonMaxY` (fields, not a result: see FULL_ROW on doubles across calls). */
  private measurePolygonHeight(): void {
    const p = this.polygon;
    let minY = Infinity, maxY = -Infinity;
    for (let k = 0; k < this.polygonCount; k++) {
      minY = Math.min(minY, p[2 * k + 1]);
      maxY = Math.max(maxY, p[2 * k + 1]);
    }
    this.polygonMinY = minY;
    this.polygonMaxY = maxY;
  }

  /**
   * Marks in `mask` the tiles the convex polygon touches: per tile row, the x range of its corners
   * in the row's band (both rows, for a corner on their boundary) and of its edges' crossings of the
   * band's sides, in one pass over the edges.
   */
  private markTouched(mask: Int32Array): void {
    const p = this.polygon, n = this.polygonCount, th = this.tileHeight, y0 = this.minY;
    if (n < 3) return;
    this.measurePolygonHeight();
    const minY = this.polygonMinY, maxY = this.polygonMaxY;
    const firstRow = Math.max(0, Math.floor((minY - y0) / th)), lastRow = Math.min(TILE_GRID - 1, Math.floor((maxY - y0) / th));
    if (firstRow > lastRow) return;
    const left = this.rowLeft, right = this.rowRight;
    left.fill(Infinity, firstRow, lastRow + 1);
    right.fill(-Infinity, firstRow, lastRow + 1);
    for (let k = 0; k < n; k++) {
      const px = p[2 * k], py = p[2 * k + 1], q = k + 1 < n ? k + 1 : 0, qx = p[2 * q], qy = p[2 * q + 1];
      // A corner on a boundary is in both rows (written by hand, as below: a double passed to a
      // call V8 does not inline would be boxed).
      const at = (py - y0) / th, row = Math.floor(at);
      for (let r = row === at ? row - 1 : row; r <= row; r++) {
        if (r < firstRow || r > lastRow) continue;
        if (px < left[r]) left[r] = px;
        if (px > right[r]) right[r] = px;
      }
      if (py === qy) continue;
      const low = Math.min(py, qy), high = Math.max(py, qy);
      for (let b = Math.max(firstRow, Math.floor((low - y0) / th)), end = Math.min(lastRow + 1, Math.ceil((high - y0) / th)); b <= end; b++) {
        const y = y0 + b * th;
        if (y <= low || y >= high) continue;
        const x = px + ((y - py) / (qy - py)) * (qx - px);
        for (let r = b - 1; r <= b; r++) {
          if (r < firstRow || r > lastRow) continue;
          if (x < left[r]) left[r] = x;
          if (x > right[r]) right[r] = x;
        }
      }
    }
    const tw = this.tileWidth;
    for (let j = firstRow; j <= lastRow; j++) {
      if (left[j] > right[j]) continue;
      const first = Math.max(0, Math.floor((left[j] - this.minX) / tw)), last = Math.min(TILE_GRID - 1, Math.floor((right[j] - this.minX) / tw));
      if (first <= last) markSpan(mask, j, first, last);
    }
  }

  /**
   * Marks in `mask` the tiles the convex polygon wholly covers: within a row's band its left edge is
   * convex and its right edge concave in y, so the x it covers at every height of the band lies
   * between the larger of its chord's left ends at the band's two sides and the smaller of the right
   * ends (when it spans the band). The chords come from one pass over the edges.
   */
  private markCovered(mask: Int32Array): void {
    const p = this.polygon, n = this.polygonCount, th = this.tileHeight, y0 = this.minY;
    if (n < 3) return;
    this.measurePolygonHeight();
    const minY = this.polygonMinY, maxY = this.polygonMaxY;
    // The tile row boundaries within the polygon's height.
    const first = Math.max(0, Math.ceil((minY - y0) / th)), last = Math.min(TILE_GRID, Math.floor((maxY - y0) / th));
    if (last - first < 1) return;
    const left = this.chordLeft, right = this.chordRight;
    left.fill(Infinity, first, last + 1);
    right.fill(-Infinity, first, last + 1);
    for (let k = 0; k < n; k++) {
      const px = p[2 * k], py = p[2 * k + 1], q = k + 1 < n ? k + 1 : 0, qx = p[2 * q], qy = p[2 * q + 1];
      const b = Math.round((py - y0) / th);
      if (b >= first && b <= last && y0 + b * th === py) {
        if (px < left[b]) left[b] = px;
        if (px > right[b]) right[b] = px;
      }
      if (py === qy) continue;
      const low = Math.min(py, qy), high = Math.max(py, qy);
      for (let c = Math.max(first, Math.floor((low - y0) / th)), end = Math.min(last, Math.ceil((high - y0) / th)); c <= end; c++) {
        const y = y0 + c * th;
        if (y <= low || y >= high) continue;
        const x = px + ((y - py) / (qy - py)) * (qx - px);
        if (x < left[c]) left[c] = x;
        if (x > right[c]) right[c] = x;
      }
    }
    const tw = this.tileWidth;
    for (let j = first; j < last; j++) {
      if (y0 + j * th < minY || y0 + (j + 1) * th > maxY) continue;
      const from = Math.max(left[j], left[j + 1]), to = Math.min(right[j], right[j + 1]);
      const firstTile = Math.max(0, Math.ceil((from - this.minX) / tw)), lastTile = Math.min(TILE_GRID - 1, Math.floor((to - this.minX) / tw) - 1);
      if (firstTile <= lastTile) markSpan(mask, j, firstTile, lastTile);
    }
  }

}

/** Sets tiles `first` to `last` (0 ≤ first ≤ last < TILE_GRID) in the mask `masks[index]`. */
function markSpan(masks: Int32Array, index: number, first: number, last: number): void {
  masks[index] |= (FULL_ROW >>> (TILE_GRID - 1 - last)) & (FULL_ROW << first);
}

/**
 * The set bits of `mask` from bit `i` (set) on, before the first clear one: at least 1. Int32
 * shifts only: `>>>` makes a uint32 that unoptimized code boxes.
 */
function runFrom(mask: number, i: number): number {
  // Its lowest set bit is the first clear bit from i on; none when the bits from i on are all set
  // (the shift copies bit 31 into those above 31 − i).
  const rest = ~(mask >> i);
  return rest === 0 ? TILE_GRID - i : 31 - Math.clz32(rest & -rest);
}

/** The set bits of a 32-bit word. */
function bitCount(word: number): number {
  let v = word - ((word >>> 1) & 0x55555555);
  v = (v & 0x33333333) + ((v >>> 2) & 0x33333333);
  return Math.imul((v + (v >>> 4)) & 0x0f0f0f0f, 0x01010101) >>> 24;
}

/** `words` long, beginning with `from`. */
function grown(from: Int32Array, words: number): Int32Array<ArrayBuffer> {
  const to = new Int32Array(words);
  to.set(from);
  return to;
}
