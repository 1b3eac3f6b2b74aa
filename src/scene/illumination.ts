import { DiskVisibility } from '../geometry/diskVisibility';
import { HullGrid } from '../geometry/HullGrid';
import { isInsidePolygon } from '../geometry/polygon';
import type { Hull } from './Hull';
import { DirectionalLight } from './DirectionalLight';
import { falloffAt } from './falloff';
import { ShadowType, type Light } from './Light';
import { Spotlight } from './Spotlight';
import { TexturedLight } from './TexturedLight';
import { ALL_LAYERS, assertBoolean, assertLayerMask, assertOptions, describeValue } from '../util/validate';

/** Every content layer, as an int32 (0xffffffff | 0). */
const EVERY_LAYER = -1;

/**
 * The value of a {@link TexturedLight}'s cookie (what the light pass reads from its texture's red
 * channel, 0..1) at texture coordinates (u, v) of the light's quad: (0, 0) is the quad's corner at
 * `−origin × size` from `position` before rotation (the texture's first texel as uploaded, which a
 * top-left world shows at the top left), (1, 1) the opposite corner. The GPU's texture cannot be
 * read without stalling it, so sample the CPU copy of the image you uploaded, with the same
 * filtering for the closest match. A number outside 0..1 (±Infinity included) is clamped to it, as
 * an 8-bit texture holds; a result that is not a number, or NaN, throws.
 */
export type CookieSampler = (light: TexturedLight, u: number, v: number) => number;

/** Options of `PenumbraRenderer.illuminationAt`; every field has the default shown. */
export interface IlluminationOptions {
  /**
   * Fill {@link Illumination.lights} with each light that reaches the point. `false` leaves it empty
   * and allocates no entries. Default `true`.
   */
  perLight?: boolean;
  /**
   * Add the renderer's `ambientColor` to {@link Illumination.color} (and so to its luminance), as
   * the lightmap does. Default `true`.
   */
  includeAmbient?: boolean;
  /**
   * The cookie of textured lights, read on the CPU (see {@link CookieSampler}). Default `null`: a
   * textured light counts as a cookie of 1 all over its quad, the most its texture can give from
   * an 8-bit image, so its figures are an upper bound (return 0 to leave textured lights out).
   */
  cookie?: CookieSampler | null;
  /**
   * Content layers (a bit mask): only the lights whose `litLayers` share a bit with it, as the
   * lightmap `renderer.draw(layers)` builds. Default every layer.
   */
  layers?: number;
}

/** What one light adds at a point; see `PenumbraRenderer.illuminationAt`. */
export interface LightIllumination {
  /** The light. */
  light: Light;
  /**
   * Linear RGB it adds: `color × intensity × strength × (visibility + (1 − visibility) × kept)`,
   * with `kept = 1 − shadowStrength × (1 − shadowColor)` per channel.
   */
  color: [number, number, number];
  /** Rec. 709 luminance of `color`: `0.2126 r + 0.7152 g + 0.0722 b`. */
  luminance: number;
  /**
   * Fraction of the light's disk visible from the point past the hulls that shadow it, 0..1 (the
   * exact soft shadow; 0 or 1 for a light of radius 0 or a {@link DirectionalLight} of angular size 0). Inside a hull it is 0 for a
   * {@link ShadowType.Solid} light, 1 for an {@link ShadowType.Illuminated} one and the part of the
   * disk that reaches it for an {@link ShadowType.Occluded} one; 1 for a light with `castsShadows` off.
   */
  visibility: number;
  /**
   * How much of `color × intensity` the light would give the point without shadows: the distance
   * falloff, times the cone factor of a {@link Spotlight}, the cookie of a {@link TexturedLight}, or
   * 1 for a {@link DirectionalLight}. Above 0 for every light listed.
   */
  strength: number;
}

/** The light arriving at a point; see `PenumbraRenderer.illuminationAt`. */
export interface Illumination {
  /** Linear RGB: the sum of the lights' colours, plus the ambient colour unless left out. What the lightmap holds there. */
  color: [number, number, number];
  /** Rec. 709 luminance of `color`: `0.2126 r + 0.7152 g + 0.0722 b`. */
  luminance: number;
  /**
   * The lights that reach the point (strength above 0), in the renderer's order, shadowed or not;
   * empty with `perLight: false`. Lights that add nothing there are left out: disabled, out of
   * range, or outside a spotlight's cone.
   */
  lights: LightIllumination[];
}

/** The options `PenumbraRenderer.illuminationAt` takes. @internal */
export const ILLUMINATION_OPTION_KEYS: readonly string[] = Object.keys({
  perLight: true, includeAmbient: true, cookie: true, layers: true,
} satisfies Record<keyof IlluminationOptions, true>);
/** The options `PenumbraRenderer.isLit` takes: it makes no per-light list and compares the lights alone. @internal */
export const IS_LIT_OPTION_KEYS: readonly string[] = ['cookie', 'layers'] satisfies (keyof IlluminationOptions)[];

/**
 * Checks the options and the result to reuse of `PenumbraRenderer.illuminationAt` and `isLit` (`name`,
 * for messages): a TypeError or RangeError naming the field and showing the value, or a TypeError
 * naming a key not in `keys`, before the query reads or writes anything.
 * @internal
 */
export function checkIlluminationQuery(name: string, options: IlluminationOptions | undefined, keys: readonly string[], out?: Illumination): void {
  if (options !== undefined) {
    assertOptions(`${name}:`, options, keys);
    if (options.perLight !== undefined) assertBoolean(`${name}: options.perLight`, options.perLight);
    if (options.includeAmbient !== undefined) assertBoolean(`${name}: options.includeAmbient`, options.includeAmbient);
    const cookie: unknown = options.cookie;
    if (cookie !== undefined && cookie !== null && typeof cookie !== 'function') {
      throw new TypeError(`${name}: options.cookie must be a function (light, u, v) => number, or null, got ${describeValue(cookie)}`);
    }
    if (options.layers !== undefined) assertLayerMask(`${name}: options.layers`, options.layers);
  }
  if (out !== undefined) checkResult(name, out);
}

/** Throws unless `out` has the shape of an {@link Illumination} that a query can overwrite. */
function checkResult(name: string, out: Illumination): void {
  if (typeof out !== 'object' || out === null) throw new TypeError(`${name}: out must be an earlier result (an Illumination), got ${describeValue(out)}`);
  if (!isColor(out.color)) throw new TypeError(`${name}: out.color must be an array of 3 numbers, got ${describeValue(out.color)}`);
  const list: unknown = out.lights;
  if (!Array.isArray(list)) throw new TypeError(`${name}: out.lights must be an array, got ${describeValue(list)}`);
  for (let i = 0; i < list.length; i++) {
    const entry: unknown = list[i];
    if (typeof entry !== 'object' || entry === null || !isColor((entry as Partial<LightIllumination>).color)) {
      throw new TypeError(`${name}: out.lights[${i}] must be an earlier result's entry (with a color array of 3 numbers), got ${describeValue(entry)}`);
    }
  }
}

function isColor(value: unknown): boolean {
  return Array.isArray(value) && value.length === 3;
}

/** The cookie's value `value` at (u, v), clamped to 0..1; throws for a result that is not a number, or NaN. */
function cookieValue(value: unknown, u: number, v: number): number {
  if (typeof value !== 'number' || Number.isNaN(value)) {
    const problem = typeof value === 'number' ? RangeError : TypeError;
    throw new problem(`IlluminationOptions.cookie must return a number from 0 to 1, got ${describeValue(value)} at (u, v) = (${u}, ${v})`);
  }
  return value < 0 ? 0 : value > 1 ? 1 : value;
}

/** Rec. 709 luminance weights (linear RGB). */
const LUMA_R = 0.2126, LUMA_G = 0.7152, LUMA_B = 0.0722;
/** Slots of `IlluminationQuery.values`. */
const X = 0, Y = 1, STRENGTH = 2, VISIBILITY = 3;
/** Flags of a prepared hull. */
const CLOSED = 1, CONVEX = 2;
/** The grid files every hull: queries may be anywhere in the world, on screen or not. */
const EVERYWHERE = [-Infinity, -Infinity, Infinity, Infinity] as const;

/**
 * The CPU side of `PenumbraRenderer.illuminationAt` and `isLit`: the renderer's light model at one
 * world point, from the lights and hulls themselves (no GPU read-back). Per light: the falloff, the
 * cone or cookie, and the exact visible fraction of its disk ({@link DiskVisibility}) past the hulls
 * that shadow it, found through a {@link HullGrid} of the hulls' bounds, so a query looks only at
 * the hulls between the point and each light's disk. The rules follow the renderer's frame: a
 * light is skipped when disabled or of intensity or range 0 (one whose centre is inside a hull is
 * not: what of its disk lies outside the hulls still shines); a hull shadows a light when it is enabled, valid, shares a layer with the
 * light's `shadowLayers`, is not one of its `ignoredHulls`, and overlaps the light's bounds.
 *
 * A {@link DirectionalLight} has no centre, range or bounds: it gives every point its colour ×
 * intensity, is never skipped but when disabled or of intensity 0, and every hull upstream of the
 * point may shadow it, however far. Its disk at infinity is replaced, per query, by a finite disk
 * that looks the same from the point (see `startFarDisk`), so the same {@link DiskVisibility} gives
 * its exact fraction.
 *
 * The grid is rebuilt when a hull changed (its `version`) or the list did: every query compares
 * each hull's version, O(hulls) reads. Hulls are transformed and their bounds, layers and flags
 * copied into flat arrays when a search first finds them after a change. Nothing is allocated per
 * query but the result, and not that when one is passed in to be reused: numbers between the
 * methods go through typed arrays (`values`, `DiskVisibility.input` and `output`; see Hot-path
 * rules in docs/architecture.md).
 * @internal
 */
export class IlluminationQuery {
  private readonly grid = new HullGrid();
  private readonly visibility = new DiskVisibility();
  /** The hulls the grid was built from, and their versions then. */
  private known: Hull[] = [];
  private versions = new Float64Array(0);
  private coarse = new Float64Array(0);
  private filed = new Uint8Array(0);
  /** Per hull, as of its version in `prepared`: world bounds (4 per hull), layers, CLOSED and CONVEX flags. */
  private prepared = new Float64Array(0);
  private bounds = new Float64Array(0);
  private layers = new Uint32Array(0);
  private flags = new Uint8Array(0);
  private readonly quad = new Float32Array(6);
  private readonly lightBounds = new Float64Array(4);
  /** The query point (x, y), then the last light's strength and visibility. */
  private readonly values = new Float64Array(4);
  private readonly box = new Float64Array(4);
  /** A directional light's cone of directions from the query point: towards the light (x, y), then sin and cos of its half-angle. */
  private readonly cone = new Float64Array(4);
  /** Entries cut from a result's `lights`, reused when a result lists more. */
  private readonly spareEntries: LightIllumination[] = [];
  /** Per light, for `isLit`: the strength, and bounds of its luminance at the point. */
  private strengths = new Float64Array(0);
  private lows = new Float64Array(0);
  private highs = new Float64Array(0);

  /** The light arriving at (x, y) from `lights` past `hulls`, with `ambient`; written into `out` when given. */
  at(
    lights: readonly Light[], hulls: readonly Hull[], ambient: readonly [number, number, number],
    x: number, y: number, options: IlluminationOptions | undefined, out: Illumination | undefined,
  ): Illumination {
    const perLight = options?.perLight ?? true;
    const includeAmbient = options?.includeAmbient ?? true;
    const cookie = options?.cookie ?? null;
    // An int32 (see Hot-path rules in docs/architecture.md).
    const layers = (options?.layers ?? ALL_LAYERS) | 0;
    // NaN, not 0: double fields from the start (see Hot-path rules in docs/architecture.md).
    const result = out ?? { color: [NaN, NaN, NaN], luminance: NaN, lights: [] };
    this.sync(hulls);
    const values = this.values;
    values[X] = x;
    values[Y] = y;
    let red = includeAmbient ? ambient[0] : 0, green = includeAmbient ? ambient[1] : 0, blue = includeAmbient ? ambient[2] : 0;
    let listed = 0;
    for (let i = 0; i < lights.length; i++) {
      const light = lights[i];
      if ((light.litLayers & layers) === 0 || !this.strengthOf(light, cookie)) continue;
      this.visibilityOf(light, hulls);
      const strength = values[STRENGTH], visibility = values[VISIBILITY];
      const color = light.color, shadowColor = light.shadowColor, shadowStrength = light.shadowStrength;
      const scale = light.intensity * strength, hidden = 1 - visibility;
      const r = color[0] * scale * (visibility + hidden * (1 - shadowStrength * (1 - shadowColor[0])));
      const g = color[1] * scale * (visibility + hidden * (1 - shadowStrength * (1 - shadowColor[1])));
      const b = color[2] * scale * (visibility + hidden * (1 - shadowStrength * (1 - shadowColor[2])));
      red += r;
      green += g;
      blue += b;
      if (!perLight) continue;
      const list = result.lights;
      let entry = list[listed];
      if (entry === undefined) {
        entry = this.spareEntries.pop() ?? { light, color: [NaN, NaN, NaN], luminance: NaN, visibility: NaN, strength: NaN };
        list.push(entry);
      }
      entry.light = light;
      entry.color[0] = r;
      entry.color[1] = g;
      entry.color[2] = b;
      entry.luminance = LUMA_R * r + LUMA_G * g + LUMA_B * b;
      entry.visibility = visibility;
      entry.strength = strength;
      listed++;
    }
    // Entries cut from the list wait for the next call that lists more: a list that grows and shrinks allocates nothing.
    const list = result.lights;
    while (list.length > listed) this.spareEntries.push(list.pop()!);
    result.color[0] = red;
    result.color[1] = green;
    result.color[2] = blue;
    result.luminance = LUMA_R * red + LUMA_G * green + LUMA_B * blue;
    return result;
  }

  /**
   * Whether the luminance the lights (not the ambient colour) give (x, y) exceeds `threshold`. First
   * bounds each light's share from its strength alone (the shadows keep between 0 and all of it),
   * then works out visibilities only while the bounds leave the answer open.
   */
  isLit(lights: readonly Light[], hulls: readonly Hull[], x: number, y: number, threshold: number, cookie: CookieSampler | null, layers = EVERY_LAYER): boolean {
    this.sync(hulls);
    if (this.strengths.length < lights.length) {
      const capacity = Math.ceil(lights.length * 1.5);
      this.strengths = new Float64Array(capacity);
      this.lows = new Float64Array(capacity);
      this.highs = new Float64Array(capacity);
    }
    const strengths = this.strengths, lows = this.lows, highs = this.highs, values = this.values;
    values[X] = x;
    values[Y] = y;
    let low = 0, high = 0;
    for (let i = 0; i < lights.length; i++) {
      const light = lights[i];
      lows[i] = highs[i] = strengths[i] = 0;
      if ((light.litLayers & layers) === 0 || !this.strengthOf(light, cookie)) continue;
      const strength = strengths[i] = values[STRENGTH];
      const color = light.color;
      const full = (LUMA_R * color[0] + LUMA_G * color[1] + LUMA_B * color[2]) * light.intensity * strength;
      highs[i] = full;
      // A light that casts shadows may be wholly hidden: at least nothing.
      lows[i] = light.castsShadows ? 0 : full;
      low += lows[i];
      high += full;
    }
    if (low > threshold) return true;
    if (high <= threshold) return false;
    for (let i = 0; i < lights.length; i++) {
      if (lows[i] === highs[i]) continue;
      const light = lights[i];
      this.visibilityOf(light, hulls);
      const visibility = values[VISIBILITY], color = light.color, shadowColor = light.shadowColor, shadowStrength = light.shadowStrength, hidden = 1 - visibility;
      const exact = (LUMA_R * color[0] * (visibility + hidden * (1 - shadowStrength * (1 - shadowColor[0])))
        + LUMA_G * color[1] * (visibility + hidden * (1 - shadowStrength * (1 - shadowColor[1])))
        + LUMA_B * color[2] * (visibility + hidden * (1 - shadowStrength * (1 - shadowColor[2])))) * light.intensity * strengths[i];
      low += exact - lows[i];
      high += exact - highs[i];
      if (low > threshold) return true;
      if (high <= threshold) return false;
    }
    return low > threshold;
  }

  /**
   * What the light gives the query point before shadows, as a multiplier on colour × intensity: its
   * distance falloff curve (`falloffAt`; times the cone of a spotlight, as shaders/light-spot.frag.glsl),
   * or the cookie over a textured light's quad, or 1 for a directional light (which has no range). Written to
   * `values[STRENGTH]`; false when it is 0 (as for a light the renderer skips).
   */
  private strengthOf(light: Light, cookie: CookieSampler | null): boolean {
    const values = this.values;
    values[STRENGTH] = 0;
    if (!light.enabled || light.intensity === 0) return false;
    if (light instanceof DirectionalLight) {
      values[STRENGTH] = 1;
      return true;
    }
    if (light.range === 0) return false;
    const x = values[X], y = values[Y];
    if (light instanceof TexturedLight) {
      // The quad as the renderer draws it (float32): x = corner + u · axisX + v · axisY.
      const q = this.quad;
      light.writeQuad(q);
      const determinant = q[2] * q[5] - q[3] * q[4];
      if (determinant === 0) return false;
      const rx = x - q[0], ry = y - q[1];
      const u = (rx * q[5] - ry * q[4]) / determinant, v = (q[2] * ry - q[3] * rx) / determinant;
      if (!(u >= 0 && u <= 1 && v >= 0 && v <= 1)) return false;
      const value = cookie ? cookieValue(cookie(light, u, v), u, v) : 1;
      if (!(value > 0)) return false;
      values[STRENGTH] = value;
      return true;
    }
    const dx = x - light.position[0], dy = y - light.position[1];
    const distance = Math.sqrt(dx * dx + dy * dy);
    const falloff = falloffAt(light.falloff, distance / light.range, light.inverseSquareCore());
    if (!(falloff > 0)) return false;
    if (!(light instanceof Spotlight)) {
      values[STRENGTH] = falloff;
      return true;
    }
    const along = distance > 0 ? (dx * Math.cos(light.rotation) + dy * Math.sin(light.rotation)) / distance : 1;
    const angle = Math.acos(along < -1 ? -1 : along > 1 ? 1 : along);
    const inside = 1 - angle / Math.max(light.coneAngle / 2, 1e-6);
    if (!(inside > 0)) return false;
    values[STRENGTH] = light.coneDecay === 0 ? falloff : falloff * Math.pow(inside, light.coneDecay);
    return true;
  }

  /**
   * The fraction of the light's disk visible from the query point past the hulls that shadow it (1
   * or 0 inside one, by the light's shadow type), written to `values[VISIBILITY]`. Two searches of
   * the grid: the hulls at the point, then those between the point and the disk, until they hide
   * it all.
   */
  private visibilityOf(light: Light, hulls: readonly Hull[]): void {
    const values = this.values;
    values[VISIBILITY] = 1;
    if (!light.castsShadows) return;
    const directional = light instanceof DirectionalLight;
    if (directional) this.lightBounds.set(EVERYWHERE);
    else this.writeLightBounds(light);
    const holder = this.holderOf(light, hulls);
    if (holder >= 0 && light.shadowType !== ShadowType.Occluded) {
      values[VISIBILITY] = light.shadowType === ShadowType.Illuminated ? 1 : 0;
      return;
    }
    const visibility = this.visibility, grid = this.grid, flags = this.flags;
    const region = directional ? this.startFarDisk(light) : this.startDisk(light);
    for (let i = 0, found = grid.search(region); i < found && !visibility.covered; i++) {
      const index = grid.found[i];
      if (!this.shadows(light, hulls, index) || !(directional ? this.nearCone(index) : this.nearSegment(index))) continue;
      const hull = hulls[index], flag = flags[index];
      // Lit as from inside every hull holding it (Occluded): a segment from the point hides where it
      // enters one of them again, through an outline edge facing the point (see ShadowType.Occluded).
      if (holder >= 0 && this.holds(hull, index, values)) visibility.addFacingEdges(hull.worldPoints, hull.pointCount);
      else visibility.addOutline(hull.worldPoints, hull.pointCount, (flag & CLOSED) !== 0, (flag & CONVEX) !== 0);
    }
    visibility.computeFraction();
    values[VISIBILITY] = visibility.output[0];
  }

  /** A closed hull that holds the query point and shadows the light (whichever the grid finds first), or −1. */
  private holderOf(light: Light, hulls: readonly Hull[]): number {
    const grid = this.grid, box = this.box, values = this.values;
    box[0] = box[2] = values[X];
    box[1] = box[3] = values[Y];
    for (let i = 0, found = grid.search(box); i < found; i++) {
      const index = grid.found[i];
      if (this.shadows(light, hulls, index) && this.holds(hulls[index], index, values)) return index;
    }
    return -1;
  }

  /** Starts `visibility` on the light's disk from the query point; returns the box to search for hulls (the capsule's). */
  private startDisk(light: Light): Readonly<Float64Array> {
    const input = this.visibility.input, values = this.values;
    input[0] = values[X];
    input[1] = values[Y];
    input[2] = light.position[0];
    input[3] = light.position[1];
    input[4] = light.radius;
    this.visibility.start();
    return this.visibility.bounds;
  }

  /**
   * Starts `visibility` on a finite disk that stands in for the directional light's disk at
   * infinity, writes `cone`, and returns the box to search for hulls.
   *
   * Seen from the point p, the light's disk spans the directions within α = angularSize / 2 of u,
   * the direction towards the light; a direction θ off u meets it along the chord at height
   * sin θ / sin α. A disk of radius D sin α centred at p + D u spans the same directions with the
   * same chords, for any D: its area between two directions is that of the strip between their
   * chords. So its visible fraction is the light's as long as every edge a ray meets lies nearer
   * than the disk, where DiskVisibility counts a hidden direction whole. No hull point lies more
   * than `reach` upstream of p (along u), found from the grid's extent, so every point of the cone
   * of directions a hull can hold lies within reach / cos α of p, while the disk's nearest point is
   * D (1 − sin α) away: D = (2 reach / cos α + 1) / (1 − sin α) leaves it twice as far (the + 1
   * keeps D above 0 when nothing lies upstream). The keeping test (edges within D sin α of the
   * segment p → centre) holds the whole cone up to reach / cos α, so no edge in it is left out.
   *
   * Accuracy: exact to rounding, as DiskVisibility. The directions are measured at p to about
   * 1e-16 rad, plus |p| / D × 1e-16 from rounding the centre, so the chord heights are good to
   * that over sin α, and the fraction to about (1 + |p| / D) × 2e-16 / angularSize: 2e-7 for an
   * angular size of 1e-9 near the origin, 1e-13 for the sun. With angularSize 0 the radius is 0 and
   * DiskVisibility makes a single segment test p → p + D u: a ray that meets every hull upstream
   * (hard shadows).
   *
   * The hulls to search are those meeting the cone up to `reach` upstream: the box of that
   * triangle, whose half-width grows by tan α per unit upstream. For a slanted light that box may
   * hold much of the world; `nearCone` then drops the hulls off the cone at one test each.
   */
  private startFarDisk(light: DirectionalLight): Readonly<Float64Array> {
    const values = this.values, x = values[X], y = values[Y], cone = this.cone, input = this.visibility.input;
    const half = 0.5 * light.angularSize, sine = Math.sin(half), cosine = Math.cos(half);
    // Towards the light: against its travel.
    const ux = cone[0] = -Math.cos(light.rotation), uy = cone[1] = -Math.sin(light.rotation);
    cone[2] = sine;
    cone[3] = cosine;
    // leastAlong is +∞ with no hull in the grid: nothing upstream then.
    const reach = Math.max(0, -(x * ux + y * uy) - this.grid.leastAlong(-ux, -uy));
    const distance = (2 * reach / cosine + 1) / (1 - sine);
    input[0] = x;
    input[1] = y;
    input[2] = x + distance * ux;
    input[3] = y + distance * uy;
    input[4] = distance * sine;
    this.visibility.start();
    const box = this.box, spread = reach * sine / cosine;
    const endX = x + reach * ux, endY = y + reach * uy, spreadX = Math.abs(spread * uy), spreadY = Math.abs(spread * ux);
    box[0] = Math.min(x, endX - spreadX);
    box[1] = Math.min(y, endY - spreadY);
    box[2] = Math.max(x, endX + spreadX);
    box[3] = Math.max(y, endY + spreadY);
    return box;
  }

  /**
   * Whether the hull at `index` shadows the light: in one of its layers, not ignored, and
   * overlapping its bounds (the renderer gives a light only those). Brings the hull's flat data up
   * to date first.
   */
  private shadows(light: Light, hulls: readonly Hull[], index: number): boolean {
    if (this.prepared[index] !== this.versions[index]) this.prepare(hulls[index], index);
    if ((this.layers[index] & light.shadowLayers) === 0) return false;
    const b = this.bounds, k = 4 * index, l = this.lightBounds;
    if (b[k] > l[2] || b[k + 2] < l[0] || b[k + 1] > l[3] || b[k + 3] < l[1]) return false;
    const ignored = light.ignoredHulls;
    return ignored.size === 0 || !ignored.has(hulls[index]);
  }

  /** Whether the closed hull at `index` (prepared) holds `point` (its first two values). */
  private holds(hull: Hull, index: number, point: ArrayLike<number>): boolean {
    const b = this.bounds, k = 4 * index, x = point[0], y = point[1];
    return (this.flags[index] & CLOSED) !== 0 && b[k] <= x && x <= b[k + 2] && b[k + 1] <= y && y <= b[k + 3] && isInsidePolygon(hull.worldPoints, point);
  }

  /**
   * Whether the circle around the bounds of the hull at `index` meets the cone of directions from
   * the query point to a directional light's disk (`cone`): {@link IlluminationQuery.nearSegment}
   * for a disk at infinity.
   */
  private nearCone(index: number): boolean {
    const b = this.bounds, k = 4 * index, cone = this.cone, values = this.values;
    const hx = 0.5 * (b[k] + b[k + 2]) - values[X], hy = 0.5 * (b[k + 1] + b[k + 3]) - values[Y];
    const halfX = 0.5 * (b[k + 2] - b[k]), halfY = 0.5 * (b[k + 3] - b[k + 1]);
    const radius2 = halfX * halfX + halfY * halfY;
    const ux = cone[0], uy = cone[1], sine = cone[2], cosine = cone[3];
    // The circle's centre in the cone's frame (the cone is symmetric: one side will do).
    const along = hx * ux + hy * uy, across = Math.abs(hx * uy - hy * ux);
    // Nearest the apex when it projects behind it onto the side's ray (never so from inside the cone).
    if (along * cosine + across * sine < 0) return hx * hx + hy * hy <= radius2;
    // Else its distance from the side's line, negative inside the cone.
    const outside = across * cosine - along * sine;
    return outside <= 0 || outside * outside <= radius2;
  }

  /**
   * Whether the circle around the bounds of the hull at `index` comes within the disk's radius of
   * the segment from the point to the centre (`visibility.input`): the test before a hull's edges,
   * since the grid finds hulls by boxes, and the box around a long slanted segment holds much more
   * than the capsule around it.
   */
  private nearSegment(index: number): boolean {
    const b = this.bounds, k = 4 * index, input = this.visibility.input;
    const px = input[0], py = input[1], r = input[4];
    const hx = 0.5 * (b[k] + b[k + 2]), hy = 0.5 * (b[k + 1] + b[k + 3]);
    const halfX = 0.5 * (b[k + 2] - b[k]), halfY = 0.5 * (b[k + 3] - b[k + 1]);
    const reach = Math.sqrt(halfX * halfX + halfY * halfY) + r;
    const ex = input[2] - px, ey = input[3] - py, length2 = ex * ex + ey * ey;
    let t = length2 > 0 ? ((hx - px) * ex + (hy - py) * ey) / length2 : 0;
    t = t < 0 ? 0 : t > 1 ? 1 : t;
    const dx = hx - px - t * ex, dy = hy - py - t * ey;
    return dx * dx + dy * dy <= reach * reach;
  }

  /** Transforms the hull's points if it changed, and copies what the searches read into flat arrays. */
  private prepare(hull: Hull, index: number): void {
    this.prepared[index] = this.versions[index];
    hull.updateWorld();
    this.bounds.set(hull.worldBounds, 4 * index);
    this.layers[index] = hull.layers;
    this.flags[index] = (hull.closed ? CLOSED : 0) | (hull.convex ? CONVEX : 0);
  }

  /** The light's bounds as the renderer's shadow cache has them: its quad and its centre. */
  private writeLightBounds(light: Light): void {
    const q = this.quad, b = this.lightBounds;
    light.writeQuad(q);
    const lx = light.position[0], ly = light.position[1];
    b[0] = Math.min(lx, q[0], q[0] + q[2], q[0] + q[4], q[0] + q[2] + q[4]);
    b[1] = Math.min(ly, q[1], q[1] + q[3], q[1] + q[5], q[1] + q[3] + q[5]);
    b[2] = Math.max(lx, q[0], q[0] + q[2], q[0] + q[4], q[0] + q[2] + q[4]);
    b[3] = Math.max(ly, q[1], q[1] + q[3], q[1] + q[5], q[1] + q[3] + q[5]);
  }

  /**
   * Rebuilds the grid when the hull list or a hull changed since it was built (from coarse bounds,
   * which need no transform: a hull is transformed when a search first finds it, see `prepare`).
   */
  private sync(hulls: readonly Hull[]): void {
    const count = hulls.length, known = this.known, versions = this.versions;
    let same = count === known.length;
    for (let i = 0; same && i < count; i++) same = hulls[i] === known[i] && hulls[i].version === versions[i];
    if (same) return;
    if (this.filed.length < count) {
      const capacity = Math.ceil(count * 1.5);
      this.versions = new Float64Array(capacity);
      this.prepared = new Float64Array(capacity).fill(-1);
      this.coarse = new Float64Array(4 * capacity);
      this.bounds = new Float64Array(4 * capacity);
      this.filed = new Uint8Array(capacity);
      this.layers = new Uint32Array(capacity);
      this.flags = new Uint8Array(capacity);
    }
    known.length = count;
    for (let i = 0; i < count; i++) {
      const hull = hulls[i];
      if (known[i] !== hull) this.prepared[i] = -1;
      known[i] = hull;
      this.versions[i] = hull.version;
      this.filed[i] = hull.enabled && hull.valid ? 1 : 0;
      if (this.filed[i] === 0) continue;
      hull.updateCoarseBounds();
      this.coarse.set(hull.coarseBounds, 4 * i);
    }
    this.grid.build(this.coarse, this.filed, count, EVERYWHERE);
  }
}
