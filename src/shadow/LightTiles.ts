import { ENTRY_MAX_RECORDS, ROW_INDICES, SHADOW_TYPE_CODES, TILE_CLASS_COUNT, TILE_CLASSES, TILE_COLUMNS, TILE_COUNT, TILE_ROWS } from './shadowLayout';
import { RecordMarks } from './RecordMarks';
import type { FiledDisk } from './ShadowBins';
import type { ShadowGeometry } from './ShadowGeometry';
import { bitCount, FULL_ROW } from './tileMasks';
import { TileRecordLists } from './TileRecordLists';
import { type ShownClasses, TileRectangles } from './TileRectangles';
/** Buckets of distance over the light's reach in which its still hulls are ordered, near first (see `addStillHulls`). */
const NEAR_BUCKETS = 32;

/**
 * The per-light tile classes (see shadowLayout, TILE_CLASSES): every shadowed point light's box
 * (its filed bounds) cut into TILE_COLUMNS × TILE_ROWS tiles, each found **lit** (no hull can hide
 * any part of the disk from any of its pixels), **dark** (one record hides the whole disk from all
 * of them, and no record lies in it where the light lights the inside of hulls), **outside** the
 * light's reach, or **held** (an Illuminated light's dark tile with a record in it: lit inside
 * hulls, dark elsewhere), or exact (anything else: the shader computes it), **lean** or
 * **general**. Lit, dark and lean are proven by each record's shadow region and umbra
 * (`RecordMarks`).
 *
 * Computed when a light is filed, from the still hulls (kept with the filing, so static lights and
 * walls cost nothing per frame), and per frame a lit tile that a moving hull's shadow region
 * touches becomes exact (and, but for a Solid light, a dark tile it lies in). Classified for the
 * filed disk and reach, which hold the light's own while the filing does, so the classes hold too.
 */
export class LightTiles {
  /**
   * The classes as the light pass draws them: per filing row a slot of ROW_INDICES indices of the
   * tile grid's corners (`tileCorner`), its rectangles' triangles (six indices each, see
   * `TileRectangles`), grouped by class.
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
   * Per filing row, TILE_ROWS masks each (tile row j at `row × TILE_ROWS + j`): the classes the
   * rectangles show now (`shown`, with the tiles beyond the reach); the dark, exact (and within
   * it general) and held ones from the still hulls alone (kept with the filing); for an
   * Illuminated light, the tiles wholly inside a still record (lit, whatever else hides the disk).
   */
  private readonly shown: ShownClasses = {
    outside: new Int32Array(TILE_ROWS),
    dark: new Int32Array(TILE_ROWS),
    held: new Int32Array(TILE_ROWS),
    exact: new Int32Array(TILE_ROWS),
    general: new Int32Array(TILE_ROWS),
    listed: new Int32Array(TILE_ROWS),
  };
  private keptDark = new Int32Array(TILE_ROWS);
  private keptExact = new Int32Array(TILE_ROWS);
  private keptGeneral = new Int32Array(TILE_ROWS);
  private keptHeld = new Int32Array(TILE_ROWS);
  private keptInside = new Int32Array(TILE_ROWS);
  private keptListed = new Int32Array(TILE_ROWS);
  /** Per row, its tiles of each class. */
  private counts = new Int32Array(TILE_CLASS_COUNT);
  /**
   * How many hulls added since `beginLight` a pixel may see past (their records reach into the
   * filed disk): a hull counts once when one of its records does or it is a fan (the shader takes a
   * fan as one), SEVERAL_HULLS when several of its records do otherwise; an Occluded light counts
   * SEVERAL_HULLS from the start (its holder pass may see past hulls anywhere). A hull passed over in
   * dark tiles needs no count: each of its points lies in a record R apart from the disk or in R's
   * umbra, which meets the disk only inside R, so it does not reach into the disk; and when a record
   * holds the whole disk, no tile is exact.
   */
  private pastHulls = 0;
  /**
   * Per row, the hulls that may be seen past: from the still hulls (kept with the filing) and as
   * shown now, with the moving ones; SEVERAL_HULLS when not looked at.
   */
  private keptPastHulls = new Int32Array(1);
  private shownPastHulls = new Int32Array(1);
  /** Per filing row: 1 while it shows its kept classes (see {@link LightTiles.restoreKept}). */
  private showsKept = new Int32Array(1);
  /** What the records of the light being classified prove about its tiles. */
  private readonly marks = new RecordMarks();
  private readonly writer = new TileRectangles();
  /** The records the listed tiles read, and the tiles' masks of them. */
  readonly lists = new TileRecordLists();
  /** Scratch of the near-first order of a light's still hulls: the order, each hull's bucket, where each bucket starts. */
  private order = new Int32Array(0);
  private bucketOfHull = new Uint8Array(0);
  private readonly bucketStarts = new Int32Array(NEAR_BUCKETS + 1);
  /** A row's classes as a moving hull leaves them, before they are shown. */
  private readonly nextDark = new Int32Array(TILE_ROWS);
  private readonly nextExact = new Int32Array(TILE_ROWS);
  private readonly nextGeneral = new Int32Array(TILE_ROWS);
  private readonly nextHeld = new Int32Array(TILE_ROWS);
  private readonly nextListed = new Int32Array(TILE_ROWS);
  private readonly noTiles = new Int32Array(TILE_ROWS);

  /** Starts a frame: no row is dirty. */
  beginFrame(): void {
    this.dirtyRows.fill(0);
    this.lists.beginFrame();
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

  /** The class (TILE_CLASSES) of tile `tile` (`j × TILE_COLUMNS + i`) of `row`, as its rectangles show it. */
  tileClass(row: number, tile: number): number {
    this.writer.splitClasses(this.shown, row * TILE_ROWS + Math.floor(tile / TILE_COLUMNS));
    return this.writer.classOfTile(tile % TILE_COLUMNS);
  }

  /**
   * Starts classifying a light: its box `[minX, minY, maxX, maxY]` (the grid), its filed disk and
   * reach (`[x, y, radius, reach, …]`, see {@link FiledDisk}); `confined`: it adds nothing beyond
   * its reach; `shadowType`: how it treats the inside of hulls (SHADOW_TYPE_CODES).
   */
  beginLight(bounds: Float64Array, disk: FiledDisk, confined: boolean, shadowType: number): void {
    this.marks.begin(bounds, disk, confined, shadowType);
    this.lists.beginLight();
    this.pastHulls = shadowType === SHADOW_TYPE_CODES.occluded ? SEVERAL_HULLS : 0;
  }

  /**
   * Adds the records of the `count` hulls at `indices` (prepared) to the light being classified,
   * nearest first, leaving out a hull that lies wholly in tiles already dark: each of its points
   * is then in some nearer record Q's umbra or in Q, so every segment through it to the disk meets
   * Q, and its shadow region and umbra lie in those of the records before it.
   */
  addStillHulls(geometry: ShadowGeometry, indices: Int32Array, count: number): void {
    const order = this.nearestFirst(geometry, indices, count), marks = this.marks;
    for (let i = 0; i < count; i++) {
      const hull = order[i];
      const first = geometry.firstRecords[hull], end = first + geometry.recordCounts[hull];
      if (marks.boundsWithin(geometry.worldBounds, hull, marks.darkened, 0)) {
        if (!marks.solid) marks.markBox(geometry.worldBounds, hull);
        if (marks.illuminated()) for (let record = first; record < end; record++) marks.markInside(geometry.records, record);
        continue;
      }
      const meetingBefore = marks.recordsMeetingDisk;
      for (let record = first; record < end; record++) {
        const apart = marks.loadRecord(geometry.records, record);
        if (marks.illuminated()) marks.markInsideLoaded();
        if (!marks.solid) marks.markRecordBox();
        if (!apart) continue;
        marks.markShadowRegion();
        marks.markUmbra();
        this.lists.addRecord(record, marks);
      }
      this.countPastHull(marks.recordsMeetingDisk - meetingBefore, isFan(geometry, hull));
    }
  }

  /** `indices`' first `count` hulls in buckets of their nearest distance to the light's centre (NEAR_BUCKETS over its reach), nearest first. */
  private nearestFirst(geometry: ShadowGeometry, indices: Int32Array, count: number): Int32Array {
    if (this.order.length < count) {
      this.order = new Int32Array(2 * count);
      this.bucketOfHull = new Uint8Array(2 * count);
    }
    const circles = geometry.circles, starts = this.bucketStarts, buckets = this.bucketOfHull, marks = this.marks, scale = NEAR_BUCKETS / Math.max(marks.reach, 1e-9);
    starts.fill(0);
    for (let i = 0; i < count; i++) {
      const hull = indices[i], dx = circles[3 * hull] - marks.centreX, dy = circles[3 * hull + 1] - marks.centreY;
      const bucket = Math.min(NEAR_BUCKETS - 1, Math.max(0, Math.floor((Math.sqrt(dx * dx + dy * dy) - circles[3 * hull + 2]) * scale)));
      buckets[i] = bucket;
      starts[bucket + 1]++;
    }
    for (let b = 0; b < NEAR_BUCKETS; b++) starts[b + 1] += starts[b];
    for (let i = 0; i < count; i++) this.order[starts[buckets[i]]++] = indices[i];
    return this.order;
  }

  /** Ends the still hulls' classification of `row` (a new filing): its kept classes, which its rectangles then show. */
  endLight(row: number): void {
    this.ensureRow(row);
    const at = row * TILE_ROWS, marks = this.marks;
    for (let j = 0; j < TILE_ROWS; j++) {
      marks.writeOutside(this.shown.outside, at, j);
      const outside = this.shown.outside[at + j], inside = marks.inside[j];
      const dark = marks.darkened[j] & ~outside & (marks.solid ? FULL_ROW : ~marks.occupied[j]);
      const held = marks.illuminated() ? marks.darkened[j] & marks.occupied[j] & ~outside & ~inside : 0;
      this.keptDark[at + j] = dark;
      this.keptHeld[at + j] = held;
      this.keptInside[at + j] = inside;
      this.keptExact[at + j] = marks.shadowed[j] & ~dark & ~held & ~outside & ~inside;
      this.keptGeneral[at + j] = this.keptExact[at + j] & marks.generalMask(j);
      // Lean, for the lists.
      this.keptListed[at + j] = this.keptExact[at + j] & ~this.keptGeneral[at + j];
    }
    this.lists.endLight(row, this.keptListed, at);
    this.keptListed.set(this.lists.listed, at);
    this.keptPastHulls[row] = this.shownPastHulls[row] = this.pastHulls;
    this.show(row, this.keptDark, this.keptExact, this.keptGeneral, this.keptHeld, this.keptListed, at, true);
    this.showsKept[row] = 1;
  }

  /** Shows `row`'s kept classes (a light whose moving hulls left it). */
  restoreKept(row: number): void {
    this.ensureRow(row);
    if (this.showsKept[row] === 1) return;
    this.shownPastHulls[row] = this.keptPastHulls[row];
    this.show(row, this.keptDark, this.keptExact, this.keptGeneral, this.keptHeld, this.keptListed, row * TILE_ROWS, false);
    this.showsKept[row] = 1;
  }

  /**
   * Ends the classification of `row` (a new filing, begun with {@link LightTiles.beginLight}) with
   * every tile within the reach exact: the classes of a light left unclassified. Lean when no
   * record of its `count` still hulls at `indices` (prepared) may reach into the filed disk and
   * the light is not Occluded (what a classification would find of its exact tiles), general
   * otherwise (in closed form when that is one hull's record or one convex hull's fan).
   */
  endUnclassified(row: number, geometry: ShadowGeometry, indices: Int32Array, count: number): void {
    this.ensureRow(row);
    const at = row * TILE_ROWS, pastHulls = this.hullsMayBeSeenPast(geometry, indices, count), general = pastHulls > 0;
    for (let j = 0; j < TILE_ROWS; j++) {
      this.marks.writeOutside(this.shown.outside, at, j);
      this.keptDark[at + j] = this.keptHeld[at + j] = this.keptInside[at + j] = this.keptListed[at + j] = 0;
      this.keptExact[at + j] = FULL_ROW & ~this.shown.outside[at + j];
      this.keptGeneral[at + j] = general ? this.keptExact[at + j] : 0;
    }
    this.keptPastHulls[row] = this.shownPastHulls[row] = pastHulls;
    this.show(row, this.keptDark, this.keptExact, this.keptGeneral, this.keptHeld, this.keptListed, at, true);
    this.showsKept[row] = 1;
  }

  /**
   * Shows `row`, a light left unclassified (see {@link LightTiles.endUnclassified}), with the
   * `count` moving hulls at `indices` (prepared): its kept classes, or every tile general when one
   * of them may reach into the filed disk (as set by {@link LightTiles.beginLight}).
   */
  addUnclassifiedMovingHulls(row: number, geometry: ShadowGeometry, indices: Int32Array, count: number): void {
    const pastHulls = this.hullsMayBeSeenPast(geometry, indices, count);
    if (pastHulls === 0) {
      this.restoreKept(row);
      return;
    }
    this.addUnknownHulls(row, this.keptPastHulls[row] + pastHulls);
  }

  /**
   * For a light left unclassified, the `count` hulls at `indices` that its pixels may see past,
   * counted as `pastHulls` is (so that one convex hull's fan or one record still takes the closed
   * program): those whose circle meets the filed disk; every hull for an Occluded light.
   */
  private hullsMayBeSeenPast(geometry: ShadowGeometry, indices: Int32Array, count: number): number {
    const marks = this.marks;
    if (marks.occluded()) return SEVERAL_HULLS;
    let pastHulls = 0;
    for (let i = 0; i < count && pastHulls < SEVERAL_HULLS; i++) {
      const hull = indices[i];
      if (marks.hullMayMeetDisk(geometry.circles, hull)) pastHulls += geometry.recordCounts[hull] > 1 && !isFan(geometry, hull) ? SEVERAL_HULLS : 1;
    }
    return pastHulls;
  }

  /**
   * Shows `row`'s kept classes as they may be with moving hulls not looked at: every lit tile
   * exact (general), and, unless the light is Solid (as set by {@link LightTiles.beginLight}),
   * every dark one; `pastHulls`: the hulls its pixels may see past, as `pastHulls` counts them
   * (several when unknown).
   */
  addUnknownHulls(row: number, pastHulls = SEVERAL_HULLS): void {
    const at = row * TILE_ROWS, dark = this.nextDark, exact = this.nextExact;
    for (let j = 0; j < TILE_ROWS; j++) {
      dark[j] = this.marks.solid ? this.keptDark[at + j] : 0;
      exact[j] = FULL_ROW & ~this.shown.outside[at + j] & ~dark[j] & ~this.keptInside[at + j];
    }
    this.shownPastHulls[row] = pastHulls;
    this.show(row, dark, exact, exact, this.noTiles, this.noTiles, 0, false);
    this.showsKept[row] = 0;
  }

  /**
   * Shows `row`'s kept classes less what the `count` moving hulls at `indices` (prepared) may
   * change: the lit tiles their shadow regions touch, and, unless `solid` (set by the last
   * {@link LightTiles.beginLight} for this light's filing, with `bounds`, disk and reach as there),
   * the dark tiles they lie in, become exact (general where `generalMask` says; held for an
   * Illuminated light). Held tiles stay held: outside hulls they lie in a still record's umbra.
   */
  addMovingHulls(row: number, geometry: ShadowGeometry, indices: Int32Array, count: number): void {
    const marks = this.marks;
    this.showsKept[row] = 0;
    for (let i = 0; i < count; i++) {
      const hull = indices[i];
      // Wholly in kept dark tiles, its shadow region lies in the still records' (as addStillHulls).
      if (marks.boundsWithin(geometry.worldBounds, hull, this.keptDark, row * TILE_ROWS)) {
        if (!marks.solid) marks.markBox(geometry.worldBounds, hull);
        continue;
      }
      const meetingBefore = marks.recordsMeetingDisk;
      for (let record = geometry.firstRecords[hull], end = record + geometry.recordCounts[hull]; record < end; record++) {
        const apart = marks.loadRecord(geometry.records, record);
        if (!marks.solid) marks.markRecordBox();
        if (apart) marks.markShadowRegion();
      }
      this.countPastHull(marks.recordsMeetingDisk - meetingBefore, isFan(geometry, hull));
    }
    this.shownPastHulls[row] = this.keptPastHulls[row] + this.pastHulls;
    const at = row * TILE_ROWS, dark = this.nextDark, exact = this.nextExact, general = this.nextGeneral, held = this.nextHeld, listed = this.nextListed;
    if (marks.diskHidden && marks.solid) {
      // A moving record holds a Solid light's disk: every tile within the reach is dark.
      for (let j = 0; j < TILE_ROWS; j++) dark[j] = FULL_ROW & ~this.shown.outside[at + j];
      this.show(row, dark, this.noTiles, this.noTiles, this.noTiles, this.noTiles, 0, false);
      return;
    }
    const illuminated = marks.illuminated();
    for (let j = 0; j < TILE_ROWS; j++) {
      const keptDark = this.keptDark[at + j], keptExact = this.keptExact[at + j], keptHeld = this.keptHeld[at + j];
      const keptInside = this.keptInside[at + j], lit = FULL_ROW & ~(this.shown.outside[at + j] | keptDark | keptExact | keptHeld | keptInside);
      const lost = marks.solid ? 0 : keptDark & marks.occupied[j];
      dark[j] = keptDark & ~lost;
      held[j] = keptHeld | (illuminated ? lost : 0);
      exact[j] = keptExact | (marks.shadowed[j] & lit) | (illuminated ? 0 : lost);
      general[j] = this.keptGeneral[at + j] | (exact[j] & marks.generalMask(j));
      // The lists hold the still records: a tile a moving record touches walks its bin.
      listed[j] = this.keptListed[at + j] & ~general[j] & ~marks.shadowed[j] & ~marks.occupied[j];
    }
    this.show(row, dark, exact, general, held, listed, 0, false);
  }

  /**
   * Shows `row` with the masks `dark[from + j]`, `exact[from + j]`, `general[from + j]` (within
   * exact) and `held[from + j]`: when a tile row changed (or `force`, for a new filing), rewrites
   * the row's rectangles, recounts it and marks it dirty.
   */
  private show(row: number, dark: Int32Array, exact: Int32Array, general: Int32Array, held: Int32Array, listed: Int32Array, from: number, force: boolean): void {
    const at = row * TILE_ROWS, shown = this.shown;
    let changed = false;
    for (let j = 0; j < TILE_ROWS; j++) {
      const d = dark[from + j], e = exact[from + j], g = general[from + j], h = held[from + j], l = listed[from + j];
      if (!force && d === shown.dark[at + j] && e === shown.exact[at + j] && g === shown.general[at + j] && h === shown.held[at + j] && l === shown.listed[at + j]) continue;
      shown.dark[at + j] = d;
      shown.exact[at + j] = e;
      shown.general[at + j] = g;
      shown.held[at + j] = h;
      shown.listed[at + j] = l;
      changed = true;
    }
    if (!changed) return;
    this.writer.write(shown, at);
    this.usedIndices[row] = this.writer.copyInto(this.rectangles, row * ROW_INDICES, this.listFirst, this.listCount, row * TILE_CLASS_COUNT);
    this.dirtyRows[row] = 1;
    let outside = 0, darkCount = 0, exactCount = 0, generalCount = 0, heldCount = 0, listedCount = 0;
    for (let j = 0; j < TILE_ROWS; j++) {
      outside += bitCount(shown.outside[at + j]);
      darkCount += bitCount(shown.dark[at + j]);
      exactCount += bitCount(shown.exact[at + j]);
      generalCount += bitCount(shown.general[at + j]);
      heldCount += bitCount(shown.held[at + j]);
      listedCount += bitCount(shown.listed[at + j]);
    }
    const counts = this.counts, c = row * TILE_CLASS_COUNT;
    counts[c + TILE_CLASSES.outside] = outside;
    counts[c + TILE_CLASSES.dark] = darkCount;
    counts[c + TILE_CLASSES.lean] = exactCount - generalCount - listedCount;
    counts[c + TILE_CLASSES.listed] = listedCount;
    counts[c + TILE_CLASSES.exact] = generalCount;
    counts[c + TILE_CLASSES.held] = heldCount;
    counts[c + TILE_CLASSES.lit] = TILE_COUNT - outside - darkCount - exactCount - heldCount;
  }

  /** Counts a hull whose records were added, `meeting` of them reaching into the disk (`fan`: one convex hull's fan), in `pastHulls`. */
  private countPastHull(meeting: number, fan: boolean): void {
    if (meeting > 0) this.pastHulls += meeting > 1 && !fan ? SEVERAL_HULLS : 1;
  }

  /**
   * Whether no pixel of `row`'s light can see several hulls past, so its general tiles may take the
   * closed program: the records reaching into its filed disk (which holds its disk) are one record
   * or one convex hull's fan, counting the moving hulls shown, and the light is not Occluded.
   */
  closedFormSuffices(row: number): boolean {
    return this.shownPastHulls[row] <= 1;
  }

  /** Grows the per-row arrays (at least doubling) to hold filing row `row`. */
  private ensureRow(row: number): void {
    const needed = (row + 1) * TILE_ROWS;
    if (this.keptDark.length >= needed) return;
    const words = Math.max(needed, 2 * this.keptDark.length), rows = words / TILE_ROWS;
    const shown = this.shown;
    shown.outside = grown(shown.outside, words);
    this.keptDark = grown(this.keptDark, words);
    this.keptExact = grown(this.keptExact, words);
    shown.dark = grown(shown.dark, words);
    shown.exact = grown(shown.exact, words);
    this.keptGeneral = grown(this.keptGeneral, words);
    shown.general = grown(shown.general, words);
    this.keptHeld = grown(this.keptHeld, words);
    this.keptInside = grown(this.keptInside, words);
    this.keptListed = grown(this.keptListed, words);
    shown.listed = grown(shown.listed, words);
    shown.held = grown(shown.held, words);
    const rectangles = new Uint16Array(rows * ROW_INDICES), used = new Int32Array(rows), dirty = new Uint8Array(rows);
    rectangles.set(this.rectangles);
    used.set(this.usedIndices);
    dirty.set(this.dirtyRows);
    this.rectangles = rectangles;
    this.usedIndices = used;
    this.dirtyRows = dirty;
    this.counts = grown(this.counts, rows * TILE_CLASS_COUNT);
    this.keptPastHulls = grown(this.keptPastHulls, rows);
    this.shownPastHulls = grown(this.shownPastHulls, rows);
    this.showsKept = grown(this.showsKept, rows);
    this.listFirst = grown(this.listFirst, rows * TILE_CLASS_COUNT);
    this.listCount = grown(this.listCount, rows * TILE_CLASS_COUNT);
  }
}

/** A count of hulls seen past (`LightTiles.pastHulls`) that the closed program does not take. */
const SEVERAL_HULLS = 2;

/** Whether hull `hull`'s records are one convex hull's fan, which the shader takes as one (an entry's fan, see `ShadowBins`). */
function isFan(geometry: ShadowGeometry, hull: number): boolean {
  return geometry.convex[hull] === 1 && geometry.recordCounts[hull] <= ENTRY_MAX_RECORDS;
}

/** `words` long, beginning with `from`. */
function grown(from: Int32Array, words: number): Int32Array<ArrayBuffer> {
  const to = new Int32Array(words);
  to.set(from);
  return to;
}
