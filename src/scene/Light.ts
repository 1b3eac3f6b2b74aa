import { Falloff } from './falloff';
import { Hull } from './Hull';
import {
  ALL_LAYERS, assertBoolean, assertFinite, assertLayerMask, assertNonNegative, assertOneOf, assertOptions, assertUnit, describeValue,
  FLOAT32_MAX, frozenColor, frozenPair, frozenVec2, type ColorLike, type Vec2Like,
} from '../util/validate';

/** How a light treats the inside of the hulls it shines on. */
export const ShadowType = {
  /** The light does not reach the inside of hulls: they stay dark. */
  Solid: 'solid',
  /** The light lights the hulls themselves (their outline is lit, only what lies behind them is shadowed). */
  Illuminated: 'illuminated',
  /**
   * The light lights the hulls only where it reaches them: a hull pixel sees the part of the disk
   * that neither another hull nor its own hull hides, with the same soft edge as shadows on the
   * floor. A segment from a pixel inside a hull leaves that hull once; the hull hides what lies
   * beyond a place where the segment enters it again, so a convex hull never shades itself and a
   * concave one shades its own parts behind its nearer walls.
   * Where hulls overlap, a pixel inside several is lit as from inside all of them at once, whatever
   * their order: the segment is hidden where it meets a hull that does not hold the pixel, or enters
   * one that does again.
   */
  Occluded: 'occluded',
} as const;
/** One of the {@link ShadowType} values. */
export type ShadowType = (typeof ShadowType)[keyof typeof ShadowType];

/** Options shared by every light; every field has the default shown. */
export interface LightOptions {
  /** World position of the light's centre (where shadows are cast from): `[x, y]` or `{ x, y }`. Default `[0, 0]`. */
  position?: Vec2Like;
  /** Distance, in world units, at which the light reaches zero. Not negative. Default `100`. */
  range?: number;
  /**
   * Radius of the emitting disk in world units: the penumbrae widen with it, 0 gives hard shadows.
   * Not negative. Default `10` ({@link DEFAULT_LIGHT_RADIUS}), a lamp's size in a view in pixels,
   * so that a light made with the defaults shows soft shadows.
   */
  radius?: number;
  /** Colour: `[r, g, b]` floats 0..1 per channel, `0xrrggbb` or a CSS string (see {@link ColorLike}). Default `[1, 1, 1]`. */
  color?: ColorLike;
  /** Multiplier on the colour; above 1 over-brightens. Not negative. Default `1`. */
  intensity?: number;
  /** Rotation in radians (positive turns +x towards +y). Default `0`. */
  rotation?: number;
  /** Normalised pivot (0..1) of the light's quad that sits at `position`. Default `[0.5, 0.5]`. */
  origin?: Vec2Like;
  /** {@link ShadowType.Solid}, {@link ShadowType.Illuminated} or {@link ShadowType.Occluded}. Default `Illuminated`. */
  shadowType?: ShadowType;
  /** How the light falls with distance (point lights and spotlights); see {@link Falloff}. Default `Linear`. */
  falloff?: Falloff;
  /**
   * Distance of the light above the plane, in world units, for normal-mapped lighting
   * (`PenumbraRenderer` option `normals`): the light reaches a pixel along `(light − pixel, height)`,
   * so a low light grazes the relief and a high one lights it from above. Not negative. Default: a
   * quarter of `range`, following the range until it is set (`null` goes back to that).
   */
  height?: number | null;
  /** A disabled light is not drawn. Default `true`. */
  enabled?: boolean;
  /** When false, the light ignores every hull. Default `true`. */
  castsShadows?: boolean;
  /** Hulls this light passes through (e.g. its own lamp housing). Default none. */
  ignoredHulls?: Iterable<Hull>;
  /**
   * The hull layers that shadow this light, a bit mask: a hull shadows it only when
   * `hull.layers & light.shadowLayers` is not 0. Default `0xffffffff` (every layer).
   */
  shadowLayers?: number;
  /**
   * The content layers this light lights, a bit mask: a lightmap built for content layers
   * `layers` (`renderer.draw(layers)`, `drawInPlace(layers)`, `renderLightmap(layers)`) holds the
   * light only when `light.litLayers & layers` is not 0 — e.g. a player's torch that lights the
   * player's sprites but not the walls, or sprites lit by some lights only, drawn and lit apart (the
   * engine integrations' lit groups do this). Default `0xffffffff` (every layer).
   */
  litLayers?: number;
  /**
   * Colour of this light's shadows: the fraction of each channel of the light that a point in
   * full shadow still gets, where {@link LightOptions.shadowStrength} is 1. Any {@link ColorLike}
   * form. Default `[0, 0, 0]`.
   */
  shadowColor?: ColorLike;
  /**
   * How dark this light's shadows are, 0..1: a point in full shadow gets
   * `1 − shadowStrength × (1 − shadowColor)` of the light per channel (and a point in part shadow
   * a mix of that and the full light by the visible fraction). Default `1`.
   */
  shadowStrength?: number;
}

/** The kind of a light, used by the renderer to pick its light pass. */
export type LightKind = 'point' | 'spot' | 'textured' | 'directional';

/** The public class of each kind, for messages: a minifier renames the classes themselves. */
const CLASS_NAMES: Readonly<Record<LightKind, string>> = { point: 'PointLight', spot: 'Spotlight', textured: 'TexturedLight', directional: 'DirectionalLight' };

/**
 * The default {@link LightOptions.radius}, in world units: a lamp's size where a world unit is a
 * pixel, so that a light made with the defaults casts the soft shadows the library is for. The
 * scene format keeps its own default for a file without `radius` (0, see `SceneLightBase.radius`),
 * so what a file means does not depend on this.
 */
export const DEFAULT_LIGHT_RADIUS = 10;

/**
 * The options every light takes; a subclass adds its own, and any other key is an error (see
 * {@link assertOptions}).
 * @internal
 */
export const LIGHT_OPTION_KEYS: readonly string[] = Object.keys({
  position: true, range: true, radius: true, color: true, intensity: true, rotation: true, origin: true, shadowType: true, falloff: true,
  height: true, enabled: true, castsShadows: true, ignoredHulls: true, shadowLayers: true, litLayers: true, shadowColor: true, shadowStrength: true,
} satisfies Record<keyof LightOptions, true>);

/** Where {@link Light.inverseSquareCore} reads its value back. */
const coreScratch = new Float64Array(1);

/**
 * Common state of every light. Lights are plain data: add them to a renderer with
 * `renderer.addLight(light)`; every change shows in the next frame.
 *
 * Every setter and constructor option is checked: a value of the wrong type throws a
 * `TypeError`, one out of range (NaN, ∞, negative) a `RangeError`, both naming the property; an
 * options key the class does not take (a misspelt `positon`) throws a `TypeError` that names it.
 * Points and vectors are taken as `[x, y]` or `{ x, y }` ({@link Vec2Like}), colours as `[r, g, b]`,
 * `0xrrggbb` or a CSS string ({@link ColorLike}). Vector getters (`position`, `origin`, `color`,
 * `shadowColor`, `size`) return frozen arrays, `[x, y]` and `[r, g, b]` whatever form was given: a
 * snapshot that never changes and cannot be written to. To change a vector, assign a new one or call
 * {@link Light.setPosition}. `ignoredHulls` is a live set: adding and deleting hulls takes effect.
 */
export abstract class Light {
  private _position: readonly [number, number] = Object.freeze([0, 0] as const);
  private _origin: readonly [number, number] = Object.freeze([0.5, 0.5] as const);
  private _color: readonly [number, number, number] = Object.freeze([1, 1, 1] as const);
  private _range = 100;
  private _radius = DEFAULT_LIGHT_RADIUS;
  private _intensity = 1;
  private _rotation = 0;
  private _enabled = true;
  private _castsShadows = true;
  private _shadowType: ShadowType = ShadowType.Illuminated;
  private _falloff: Falloff = Falloff.Linear;
  /** The height set, NaN while it follows the range: a double field, since a null beside numbers would box the number on every read. */
  private _height = NaN;
  private _shadowLayers = ALL_LAYERS;
  private _litLayers = ALL_LAYERS;
  private _shadowColor: readonly [number, number, number] = Object.freeze([0, 0, 0] as const);
  private _shadowStrength = 1;
  /** Hulls this light passes through: they do not shadow it, nor hide the part of its disk inside them. */
  readonly ignoredHulls = new Set<Hull>();

  constructor(options: LightOptions = {}) {
    assertOptions(this.className, options, this.optionKeys);
    if (options.position !== undefined) this.position = options.position;
    if (options.range !== undefined) this.range = options.range;
    if (options.radius !== undefined) this.radius = options.radius;
    if (options.color !== undefined) this.color = options.color;
    if (options.intensity !== undefined) this.intensity = options.intensity;
    if (options.rotation !== undefined) this.rotation = options.rotation;
    if (options.origin !== undefined) this.origin = options.origin;
    if (options.shadowType !== undefined) this.shadowType = options.shadowType;
    if (options.falloff !== undefined) this.falloff = options.falloff;
    if (options.height !== undefined) this.height = options.height;
    if (options.enabled !== undefined) this.enabled = options.enabled;
    if (options.castsShadows !== undefined) this.castsShadows = options.castsShadows;
    if (options.ignoredHulls !== undefined) this.ignoreHulls(options.ignoredHulls);
    if (options.shadowLayers !== undefined) this.shadowLayers = options.shadowLayers;
    if (options.litLayers !== undefined) this.litLayers = options.litLayers;
    if (options.shadowColor !== undefined) this.shadowColor = options.shadowColor;
    if (options.shadowStrength !== undefined) this.shadowStrength = options.shadowStrength;
  }

  /** Which light pass draws this light. A getter, not a field: the constructor names the class by it. */
  abstract get kind(): LightKind;

  /** The class name that messages show. */
  protected get className(): string {
    return CLASS_NAMES[this.kind];
  }

  /** The options keys the class takes. A getter, as `kind` is, since the constructor checks the options by it. @internal */
  protected get optionKeys(): readonly string[] {
    return LIGHT_OPTION_KEYS;
  }

  /** World position of the light's centre, a frozen `[x, y]` pair whatever form was given (see {@link Vec2Like}). */
  get position(): readonly [number, number] {
    return this._position;
  }
  set position(value: Vec2Like) {
    this._position = frozenVec2(`${this.className}.position`, value);
  }
  /** Moves the light; allocates only the frozen pair that `position` then returns. */
  setPosition(x: number, y: number): this {
    this._position = frozenPair(`${this.className}.position`, x, y);
    return this;
  }

  /** Normalised pivot of the light's quad placed at `position` (matters for textured lights), frozen. */
  get origin(): readonly [number, number] {
    return this._origin;
  }
  set origin(value: Vec2Like) {
    this._origin = frozenVec2(`${this.className}.origin`, value);
  }

  /** Colour `[r, g, b]`, frozen, whatever form was given: `0xff8800` reads back as `[1, 0.533…, 0]` (see {@link ColorLike}). */
  get color(): readonly [number, number, number] {
    return this._color;
  }
  set color(value: ColorLike) {
    this._color = frozenColor(`${this.className}.color`, value);
  }

  /** Distance at which the light reaches zero. */
  get range(): number {
    return this._range;
  }
  set range(value: number) {
    this._range = assertNonNegative(`${this.className}.range`, value);
  }

  /** Radius of the emitting disk; see {@link LightOptions.radius}. */
  get radius(): number {
    return this._radius;
  }
  set radius(value: number) {
    this._radius = assertNonNegative(`${this.className}.radius`, value);
  }

  /** Multiplier on the colour. */
  get intensity(): number {
    return this._intensity;
  }
  set intensity(value: number) {
    this._intensity = assertNonNegative(`${this.className}.intensity`, value);
  }

  /** Rotation in radians. */
  get rotation(): number {
    return this._rotation;
  }
  set rotation(value: number) {
    this._rotation = assertFinite(`${this.className}.rotation`, value);
  }

  /** A disabled light is not drawn. */
  get enabled(): boolean {
    return this._enabled;
  }
  set enabled(value: boolean) {
    this._enabled = assertBoolean(`${this.className}.enabled`, value);
  }

  /** When false the light passes through every hull. */
  get castsShadows(): boolean {
    return this._castsShadows;
  }
  set castsShadows(value: boolean) {
    this._castsShadows = assertBoolean(`${this.className}.castsShadows`, value);
  }

  /** Whether the light lights the inside of hulls; see {@link ShadowType}. */
  get shadowType(): ShadowType {
    return this._shadowType;
  }
  set shadowType(value: ShadowType) {
    this._shadowType = assertOneOf(`${this.className}.shadowType`, value, SHADOW_TYPES);
  }

  /** How the light falls with distance; see {@link Falloff}. Textured and directional lights ignore it. */
  get falloff(): Falloff {
    return this._falloff;
  }
  set falloff(value: Falloff) {
    this._falloff = assertOneOf(`${this.className}.falloff`, value, FALLOFFS);
  }

  /**
   * Distance above the plane in world units; see {@link LightOptions.height}. Reads a quarter of
   * `range` until a height is set; assign `null` to go back to that.
   */
  get height(): number {
    return Number.isNaN(this._height) ? this._range * DEFAULT_HEIGHT_PER_RANGE : this._height;
  }
  set height(value: number | null) {
    this._height = value === null ? NaN : assertNonNegative(`${this.className}.height`, value);
  }
  /** The height that was set, or `null` while it follows the range. */
  get givenHeight(): number | null {
    return Number.isNaN(this._height) ? null : this._height;
  }

  /** The hull layers that shadow this light; see {@link LightOptions.shadowLayers}. */
  get shadowLayers(): number {
    return this._shadowLayers;
  }
  set shadowLayers(value: number) {
    this._shadowLayers = assertLayerMask(`${this.className}.shadowLayers`, value);
  }

  /** The content layers this light lights; see {@link LightOptions.litLayers}. */
  get litLayers(): number {
    return this._litLayers;
  }
  set litLayers(value: number) {
    this._litLayers = assertLayerMask(`${this.className}.litLayers`, value);
  }

  /** Colour of this light's shadows, frozen; see {@link LightOptions.shadowColor}. */
  get shadowColor(): readonly [number, number, number] {
    return this._shadowColor;
  }
  set shadowColor(value: ColorLike) {
    this._shadowColor = frozenColor(`${this.className}.shadowColor`, value);
  }

  /** How dark this light's shadows are, 0..1; see {@link LightOptions.shadowStrength}. */
  get shadowStrength(): number {
    return this._shadowStrength;
  }
  set shadowStrength(value: number) {
    this._shadowStrength = assertUnit(`${this.className}.shadowStrength`, value);
  }

  /**
   * Writes into `out` the fraction of each channel of the light that a point in full shadow gets:
   * `1 − shadowStrength × (1 − shadowColor)`.
   * @internal
   */
  writeShadowKept(out: Float32Array): void {
    for (let c = 0; c < 3; c++) out[c] = 1 - this._shadowStrength * (1 - this._shadowColor[c]);
  }

  /**
   * Writes colour × intensity into `out`, each channel at most {@link FLOAT32_MAX}: what a light
   * pass's colour uniform takes (the product of two numbers of float32 size may not be one).
   * @internal
   */
  writeEmittedColor(out: Float32Array): void {
    // The bounds are literals here and in writeInverseSquareCore (see Hot-path rules in docs/architecture.md).
    for (let c = 0; c < 3; c++) out[c] = Math.min(this._color[c] * this._intensity, 3.4028234663852886e38 /* FLOAT32_MAX */);
  }

  /** Adds `hulls` to {@link Light.ignoredHulls} after checking that every one is a `Hull`; on an error none is added. */
  private ignoreHulls(hulls: Iterable<Hull>): void {
    const name = `${this.className}.ignoredHulls`;
    if (typeof hulls !== 'object' || hulls === null || typeof (hulls as Partial<Iterable<Hull>>)[Symbol.iterator] !== 'function') {
      throw new TypeError(`${name} must be an iterable of Hulls, got ${describeValue(hulls)}`);
    }
    const list = [...hulls];
    list.forEach((hull, i) => {
      if (!(hull instanceof Hull)) throw new TypeError(`${name}[${i}] must be a Hull, got ${describeValue(hull)}`);
    });
    for (const hull of list) this.ignoredHulls.add(hull);
  }

  /**
   * The inverse-square falloff's core s in ranges (see {@link Falloff.InverseSquare}):
   * max(radius, 1) / range, within [2^−60, 2^16].
   * @internal
   */
  inverseSquareCore(): number {
    this.writeInverseSquareCore(coreScratch, 0);
    return coreScratch[0];
  }

  /** Writes {@link Light.inverseSquareCore} into `out[at]` (the light pass's path, each frame). @internal */
  writeInverseSquareCore(out: Float32Array | Float64Array, at: number): void {
    const core = Math.max(this._radius, 1) / this._range;
    out[at] = core > 65536 /* 2^16 */ ? 65536 : core < 8.673617379884035e-19 /* 2^−60 */ ? 8.673617379884035e-19 : core;
  }

  /**
   * The light's quad in world space: a corner and the two edge vectors, written into `out`
   * as `[cornerX, cornerY, axisXx, axisXy, axisYx, axisYy]`. Procedural lights use a square
   * of side `2 × range` centred on `position`.
   * @internal
   */
  writeQuad(out: Float32Array): void {
    const width = this.quadWidth(), height = this.quadHeight();
    const cos = Math.cos(this._rotation), sin = Math.sin(this._rotation);
    const pivot = this.quadPivot();
    const ox = pivot[0], oy = pivot[1];
    out[2] = cos * width;
    out[3] = sin * width;
    out[4] = -sin * height;
    out[5] = cos * height;
    out[0] = this._position[0] - ox * out[2] - oy * out[4];
    out[1] = this._position[1] - ox * out[3] - oy * out[5];
  }

  /**
   * Distance from `position` beyond which the light adds nothing, so its shadows need reach no
   * further: `range` for the procedural lights, whose falloff ends there.
   * @internal
   */
  reach(): number {
    return this._range;
  }

  /**
   * Whether the light adds nothing outside the disk of its range inscribed in its quad, so that the
   * passes may draw that disk instead of the quad: true for the procedural lights.
   * @internal
   */
  isConfinedToRangeDisk(): boolean {
    return true;
  }

  /** Normalised point of the quad placed at `position`. */
  protected quadPivot(): readonly [number, number] {
    return CENTRE;
  }
  /** Quad width in world units. */
  protected quadWidth(): number {
    return 2 * this._range;
  }
  /** Quad height in world units. */
  protected quadHeight(): number {
    return 2 * this._range;
  }
}

const CENTRE = [0.5, 0.5] as const;
/** A light's height while none is set, per unit of range: high enough that flat normals are well lit across most of the range. */
const DEFAULT_HEIGHT_PER_RANGE = 0.25;
const SHADOW_TYPES: readonly ShadowType[] = Object.values(ShadowType);
const FALLOFFS: readonly Falloff[] = Object.values(Falloff);
