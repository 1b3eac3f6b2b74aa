import { ROW_INDICES, TILE_CLASS_COUNT, TILE_CLASSES, TILE_COLUMNS, TILE_ROWS, tileCorner } from './shadowLayout';
import { FULL_ROW, runFrom } from './tileMasks';

/** The classes drawn, in the order their rectangles follow each other in a row's slot. */
const DRAWN_CLASSES = [TILE_CLASSES.lit, TILE_CLASSES.dark, TILE_CLASSES.held, TILE_CLASSES.lean, TILE_CLASSES.listed, TILE_CLASSES.exact] as const;

/**
 * The classes a light's tiles are shown in, one int32 mask per tile row (see `tileMasks`):
 * outside, dark, held and exact are disjoint, general and listed lie within exact, apart; a tile in
 * none is lit.
 */
export interface ShownClasses {
  outside: Int32Array;
  dark: Int32Array;
  held: Int32Array;
  exact: Int32Array;
  general: Int32Array;
  listed: Int32Array;
}

/**
 * Writes a light's tile classes as rectangles of tiles of one class, each two triangles of the
 * grid's corners (`tileCorner`): a rectangle is a run of tiles of one class along a tile row,
 * merged with the same run in the rows after it, so a light draws few, large triangles and few
 * pixel blocks are shaded twice along their edges.
 */
export class TileRectangles {
  /** One tile row's masks per class (`splitClasses`). */
  readonly rowClasses = new Int32Array(TILE_CLASS_COUNT);
  /**
   * The rectangles being written: those open at the current tile row and at the next (first tile,
   * last tile, class, first tile row), and per class its indices.
   */
  private openStart = new Int32Array(TILE_COLUMNS);
  private openEnd = new Int32Array(TILE_COLUMNS);
  private openClass = new Int32Array(TILE_COLUMNS);
  private openRow = new Int32Array(TILE_COLUMNS);
  private nextOpenStart = new Int32Array(TILE_COLUMNS);
  private nextOpenEnd = new Int32Array(TILE_COLUMNS);
  private nextOpenClass = new Int32Array(TILE_COLUMNS);
  private nextOpenRow = new Int32Array(TILE_COLUMNS);
  private readonly classIndices = Array.from({ length: TILE_CLASS_COUNT }, () => new Uint16Array(ROW_INDICES));
  private readonly classLengths = new Int32Array(TILE_CLASS_COUNT);

  /**
   * Writes the rectangles of the grid whose tile rows are `masks`' words `at` to `at + TILE_ROWS − 1`:
   * per tile row, its runs of one class, each merged with an open rectangle of the rows above that
   * spans the same tiles in the same class, else opening one; a rectangle not continued is closed
   * and written into its class's list (see {@link TileRectangles.copyInto}).
   */
  write(masks: ShownClasses, at: number): void {
    let open = 0;
    this.classLengths.fill(0);
    for (let j = 0; j <= TILE_ROWS; j++) {
      let kept = 0, k = 0;
      if (j < TILE_ROWS) this.splitClasses(masks, at + j);
      for (let i = 0; i < TILE_COLUMNS && j < TILE_ROWS;) {
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
  }

  /**
   * Sets `rowClasses` to the masks of each class in tile row `word` of `shown`: outside before
   * dark before held before exact (general, listed or lean), the rest lit.
   */
  splitClasses(shown: ShownClasses, word: number): void {
    const masks = this.rowClasses, outside = shown.outside[word], dark = shown.dark[word] & ~outside;
    const held = shown.held[word] & ~outside & ~dark, exact = shown.exact[word] & ~outside & ~dark & ~held;
    masks[TILE_CLASSES.outside] = outside;
    masks[TILE_CLASSES.dark] = dark;
    masks[TILE_CLASSES.held] = held;
    masks[TILE_CLASSES.exact] = exact & shown.general[word];
    masks[TILE_CLASSES.listed] = exact & shown.listed[word];
    masks[TILE_CLASSES.lean] = exact & ~shown.general[word] & ~shown.listed[word];
    masks[TILE_CLASSES.lit] = FULL_ROW & ~(outside | dark | held | exact);
  }

  /** The class of tile `i` in the row `splitClasses` split. */
  classOfTile(i: number): number {
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

  /**
   * Copies the classes' lists written by {@link TileRectangles.write} into `rectangles` from
   * `slot`, one after the other in the order of DRAWN_CLASSES, noting per class where its indices
   * start (from `slot`) and how many there are in `listFirst[at + class]` and `listCount[at + class]`;
   * returns the indices written.
   */
  copyInto(rectangles: Uint16Array, slot: number, listFirst: Int32Array, listCount: Int32Array, at: number): number {
    let n = 0;
    listCount[at + TILE_CLASSES.outside] = 0;
    for (let c = 0; c < DRAWN_CLASSES.length; c++) {
      const value = DRAWN_CLASSES[c], list = this.classIndices[value], length = this.classLengths[value];
      listFirst[at + value] = n;
      listCount[at + value] = length;
      for (let k = 0; k < length; k++) rectangles[slot + n + k] = list[k];
      n += length;
    }
    return n;
  }
}
