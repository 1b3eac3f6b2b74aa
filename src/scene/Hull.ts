import { isConvexPolygon, isSimplePolygon, signedArea2, simplifyPolygon, simplifyPolyline, triangulate } from '../geometry/polygon';
import { assertBoolean, assertFinite, assertLayerMask, assertOptions, describeValue, frozenPair, frozenVec2, vec2ListCoords, type Vec2Like } from '../util/validate';

/** Options of a {@link Hull}; every field has the default shown. */
export interface HullOptions {
  /** World position of the hull's `origin`: `[x, y]` or `{ x, y }` ({@link Vec2Like}). Default `[0, 0]`. */
  position?: Vec2Like;
  /** Pivot in the points' local space: rotation and scale happen around it. Default `[0, 0]`. */
  origin?: Vec2Like;
  /** Rotation in radians around `origin` (positive turns +x towards +y). Default `0`. */
  rotation?: number;
  /** Scale around `origin` along the local axes (before the rotation), one factor, `[sx, sy]` or `{ x, y }` (a Pixi sprite's `scale`); a negative factor mirrors. Default `1`. */
  scale?: number | Vec2Like;
  /** A disabled hull casts no shadow. Default `true`. */
  enabled?: boolean;
  /**
   * `false` makes the hull an open polyline: a thin wall, fence or cliff edge that blocks light
   * from both sides and has no inside (see {@link Hull.closed}). Fixed at construction. Default `true`.
   */
  closed?: boolean;
  /**
   * The layers the hull is in, a bit mask: it shadows only the lights whose `shadowLayers` share
   * a bit with it (a player's own hull left out of the player's torch, low walls that block some
   * lights only). Default `1`.
   */
  layers?: number;
}

/** The options a hull takes; any other key is an error (see {@link assertOptions}). */
const HULL_OPTION_KEYS: readonly string[] = Object.keys({
  position: true, origin: true, rotation: true, scale: true, enabled: true, closed: true, layers: true,
} satisfies Record<keyof HullOptions, true>);

/**
 * A polygon that blocks light, or with `closed: false` an open polyline that does. Points are in
 * the hull's local space, in either winding; `position`, `origin`, `rotation` and `scale` place
 * them in the world: scaled first, along the local axes, then rotated, both around `origin`, then
 * moved so that `origin` lands on `position` — world = position + R(rotation) · S(scale) · (point −
 * origin). So `[2, 1]` stretches the hull along its own x axis, whatever its rotation.
 *
 * A polygon with fewer than 3 distinct points, crossing edges or zero area is kept but flagged
 * `valid === false` and ignored by the renderer; giving it correct points makes it valid again.
 * Checking and triangulating the points takes O(n log n) for most outlines. A polyline needs 2
 * distinct points; it may cross itself.
 *
 * Setters and options are checked as the lights' are (`TypeError` for a wrong type or an options
 * key the class does not take, `RangeError` for NaN or ∞, naming the property). Points, `position`,
 * `origin` and `scale` are taken as `[x, y]` pairs or `{ x, y }` objects such as PixiJS `Point`s
 * and Phaser `Vector2`s ({@link Vec2Like}); `points`, `position`, `origin` and `scale` read back as
 * frozen `[x, y]` arrays whatever form was given: snapshots that never change and cannot be written
 * to; assign a new value, or call {@link Hull.setPosition}, to change them.
 */
export class Hull {
  /** The points as given, `[x0, y0, …]`; their frozen pairs are made when first asked for. */
  private givenCoords!: Float64Array;
  private _points: ReadonlyArray<readonly [number, number]> | null = null;
  // Frozen, so every hull can start with the same default pairs.
  private _position: readonly [number, number] = ZERO;
  private _origin: readonly [number, number] = ZERO;
  private _scale: readonly [number, number] = ONE;
  private _rotation = 0;
  private _enabled = true;
  private _layers = 1;
  private readonly _closed: boolean;
  private _shapeValid = false;
  private _convex = false;
  /** Cleaned local points: counter-clockwise for a polygon, in the given order for a polyline. */
  private localPoints!: Float64Array;
  private localTriangles: readonly number[] = [];
  /** `localTriangles` for mirrored world points (see {@link Hull.updateWorld}), made when first needed. */
  private mirroredTriangles: readonly number[] | null = null;
  private worldVersion = -1;
  private worldIsMirrored = false;
  private coarseVersion = -1;
  /** Largest distance of a local point from `origin`; NaN when points or origin changed since it was computed. */
  private pivotRadius = NaN;

  /**
   * Bumped by every change (setting a property to the value it has is none); the renderer compares
   * it to decide what to rebuild, and a hull it has not seen change for a while stands still (kept in
   * the lights' filings).
   * @internal
   */
  version = 0;
  /** World-space points, counter-clockwise, `[x0, y0, x1, y1, …]`; see {@link Hull.updateWorld}. @internal */
  worldPoints!: Float32Array;
  /** World-space bounds `[minX, minY, maxX, maxY]`. @internal */
  readonly worldBounds = new Float64Array(4);
  /**
   * Bounds that contain `worldBounds`, from position, scale and `pivotRadius` alone; see
   * {@link Hull.updateCoarseBounds}. @internal
   */
  readonly coarseBounds = new Float64Array(4);

  constructor(points: ReadonlyArray<Vec2Like>, options: HullOptions = {}) {
    assertOptions('Hull', options, HULL_OPTION_KEYS);
    this._closed = options.closed === undefined ? true : assertBoolean('Hull.closed', options.closed);
    this.points = points;
    if (options.position !== undefined) this.position = options.position;
    if (options.origin !== undefined) this.origin = options.origin;
    if (options.rotation !== undefined) this.rotation = options.rotation;
    if (options.scale !== undefined) this.scale = options.scale;
    if (options.enabled !== undefined) this.enabled = options.enabled;
    if (options.layers !== undefined) this.layers = options.layers;
  }

  /**
   * The points as given (local space), frozen `[x, y]` pairs in a frozen array. Assign a new array
   * of points (pairs or `{ x, y }` objects, see {@link Vec2Like}) to reshape the hull.
   */
  get points(): ReadonlyArray<readonly [number, number]> {
    const coords = this.givenCoords;
    return (this._points ??= Object.freeze(Array.from({ length: coords.length >> 1 }, (_, i) => Object.freeze([coords[2 * i], coords[2 * i + 1]] as const))));
  }
  set points(points: ReadonlyArray<Vec2Like>) {
    if (!Array.isArray(points)) throw new TypeError(`Hull.points must be an array of [x, y] pairs or { x, y } points, got ${describeValue(points)}`);
    this.setCoords(vec2ListCoords('Hull.points', points));
  }

  /**
   * A hull from flat, finite coordinates `[x0, y0, x1, y1, …]`, which it keeps (no copy): for the
   * library's own builders (tile maps make thousands of hulls), without a pair per point.
   * @internal
   */
  static fromCoords(coords: Float64Array, options?: HullOptions): Hull {
    const hull = new Hull(NO_POINTS, options);
    hull.setCoords(coords);
    return hull;
  }

  private setCoords(coords: Float64Array): void {
    this.givenCoords = coords;
    this._points = null;
    const closed = this._closed;
    const cleaned = closed ? simplifyPolygon(coords) : simplifyPolyline(coords);
    this._shapeValid = closed ? isSimplePolygon(cleaned) : cleaned.length >= 4;
    if (closed && this._shapeValid && signedArea2(cleaned) < 0) reversePoints(cleaned);
    this.localPoints = Float64Array.from(cleaned);
    this.localTriangles = closed && this._shapeValid ? triangulate(cleaned) : [];
    this._convex = closed && this._shapeValid && isConvexPolygon(cleaned);
    this.mirroredTriangles = null;
    this.worldPoints = new Float32Array(cleaned.length);
    this.pivotRadius = NaN;
    this.touch();
  }

  /** World position of `origin`, frozen. */
  get position(): readonly [number, number] {
    return this._position;
  }
  set position(value: Vec2Like) {
    const position = frozenVec2('Hull.position', value);
    if (position[0] === this._position[0] && position[1] === this._position[1]) return;
    this._position = position;
    this.touch();
  }
  /** Moves the hull; allocates only the frozen pair that `position` then returns (nothing when it is already there). */
  setPosition(x: number, y: number): this {
    if (x === this._position[0] && y === this._position[1]) return this;
    this._position = frozenPair('Hull.position', x, y);
    this.touch();
    return this;
  }

  /** Pivot in local space, frozen. */
  get origin(): readonly [number, number] {
    return this._origin;
  }
  set origin(value: Vec2Like) {
    this._origin = frozenVec2('Hull.origin', value);
    this.pivotRadius = NaN;
    this.touch();
  }

  /** Rotation in radians around `origin`. */
  get rotation(): number {
    return this._rotation;
  }
  set rotation(value: number) {
    if (assertFinite('Hull.rotation', value) === this._rotation) return;
    this._rotation = value;
    this.touch();
  }

  /** Scale `[sx, sy]` around `origin`, frozen; assign a number for uniform scale. Negative mirrors. */
  get scale(): readonly [number, number] {
    return this._scale;
  }
  set scale(value: number | Vec2Like) {
    if (typeof value === 'number') assertFinite('Hull.scale', value);
    this._scale = typeof value === 'number' ? frozenPair('Hull.scale', value, value) : frozenVec2('Hull.scale', value);
    this.touch();
  }

  /** A disabled hull casts no shadow and is not drawn by the hull pass. */
  get enabled(): boolean {
    return this._enabled;
  }
  set enabled(value: boolean) {
    if (assertBoolean('Hull.enabled', value) === this._enabled) return;
    this._enabled = value;
    this.touch();
  }

  /** The layers the hull is in; see {@link HullOptions.layers}. */
  get layers(): number {
    return this._layers;
  }
  set layers(value: number) {
    if (assertLayerMask('Hull.layers', value) === this._layers) return;
    this._layers = value;
    this.touch();
  }

  /**
   * Whether the hull is closed (a polygon with an inside: see {@link Hull}) or an open polyline.
   * A polyline's shadow is exact as a polygon's is, to within a band about a thousandth of a world
   * unit wide along it (the renderer draws each segment as a box 2^-9 wide, or 2^-18 of the
   * coordinates' magnitude where that is more, so that float rounding cannot close it). It has no inside:
   * `ShadowType` and a light centre on it change nothing.
   */
  get closed(): boolean {
    return this._closed;
  }

  /**
   * Whether the points form a simple polygon (≥ 3 points, no crossing edges, non-zero area), or for
   * an open hull a polyline of ≥ 2 distinct points, and the scale is non-zero.
   */
  get valid(): boolean {
    return this._shapeValid && this._scale[0] !== 0 && this._scale[1] !== 0;
  }

  /** Whether the hull is valid and convex (its shadow records are a fan of its points, four at a time; a concave hull's are its triangles). */
  get convex(): boolean {
    return this._convex && this.valid;
  }

  /**
   * Number of edges the renderer uses: of a polygon, its points without duplicates and collinear
   * points; of an open polyline, one fewer.
   */
  get edgeCount(): number {
    return this.pointCount - (this._closed ? 0 : 1);
  }

  /** Number of points the renderer uses (of `worldPoints`). @internal */
  get pointCount(): number {
    return this.localPoints.length >> 1;
  }

  /**
   * Triangles of the hull as point indices into `worldPoints`, three per triangle.
   * @internal
   */
  get worldTriangles(): readonly number[] {
    if (!this.worldIsMirrored) return this.localTriangles;
    const last = this.pointCount - 1;
    return (this.mirroredTriangles ??= this.localTriangles.map((index) => last - index));
  }

  /**
   * Recomputes `worldPoints` and `worldBounds` if the hull changed since the last call.
   * Keeps counter-clockwise order also when a negative scale mirrors the hull.
   * @returns true when the world points changed.
   * @internal
   */
  updateWorld(): boolean {
    if (this.worldVersion === this.version) return false;
    this.worldVersion = this.version;
    const n = this.pointCount;
    const cos = Math.cos(this._rotation), sin = Math.sin(this._rotation);
    // Indexed, not destructured (see Hot-path rules in docs/architecture.md).
    const sx = this._scale[0], sy = this._scale[1];
    const ox = this._origin[0], oy = this._origin[1];
    const px = this._position[0], py = this._position[1];
    this.worldIsMirrored = sx * sy < 0;
    const bounds = this.worldBounds;
    bounds[0] = bounds[1] = Infinity;
    bounds[2] = bounds[3] = -Infinity;
    for (let i = 0; i < n; i++) {
      const source = this.worldIsMirrored ? n - 1 - i : i;
      const lx = (this.localPoints[2 * source] - ox) * sx;
      const ly = (this.localPoints[2 * source + 1] - oy) * sy;
      const x = px + lx * cos - ly * sin;
      const y = py + lx * sin + ly * cos;
      this.worldPoints[2 * i] = x;
      this.worldPoints[2 * i + 1] = y;
      if (x < bounds[0]) bounds[0] = x;
      if (y < bounds[1]) bounds[1] = y;
      if (x > bounds[2]) bounds[2] = x;
      if (y > bounds[3]) bounds[3] = y;
    }
    return true;
  }

  /**
   * Recomputes `coarseBounds` if the hull changed since the last call, in constant time: every
   * world point lies within `max(|sx|, |sy|) × pivotRadius` of `position` whatever the rotation,
   * so the renderer can cull a hull without transforming its points.
   * @internal
   */
  updateCoarseBounds(): void {
    if (this.coarseVersion === this.version) return;
    this.coarseVersion = this.version;
    if (Number.isNaN(this.pivotRadius)) this.pivotRadius = this.farthestFromOrigin();
    const scale = Math.max(Math.abs(this._scale[0]), Math.abs(this._scale[1]));
    // Padded by a relative hair, so rounding in the exact transform never lands a point outside.
    const reach = scale * this.pivotRadius * (1 + 1e-9);
    const b = this.coarseBounds;
    b[0] = this._position[0] - reach;
    b[1] = this._position[1] - reach;
    b[2] = this._position[0] + reach;
    b[3] = this._position[1] + reach;
  }

  private farthestFromOrigin(): number {
    const local = this.localPoints;
    const ox = this._origin[0], oy = this._origin[1];
    let farthest = 0;
    for (let i = 0; i < local.length; i += 2) {
      const dx = local[i] - ox, dy = local[i + 1] - oy;
      farthest = Math.max(farthest, dx * dx + dy * dy);
    }
    return Math.sqrt(farthest);
  }

  private touch(): void {
    this.version++;
  }
}

const ZERO = Object.freeze([0, 0] as const);
const ONE = Object.freeze([1, 1] as const);
const NO_POINTS: ReadonlyArray<Vec2Like> = Object.freeze([]);

function reversePoints(coords: number[]): void {
  const n = coords.length >> 1;
  for (let i = 0; i < n >> 1; i++) {
    const j = n - 1 - i;
    [coords[2 * i], coords[2 * j]] = [coords[2 * j], coords[2 * i]];
    [coords[2 * i + 1], coords[2 * j + 1]] = [coords[2 * j + 1], coords[2 * i + 1]];
  }
}
