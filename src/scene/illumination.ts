import { DiskVisibility } from '../geometry/diskVisibility';
import { HullGrid } from '../geometry/HullGrid';
import { isInsidePolygon } from '../geometry/polygon';
import type { Hull } from './Hull';
import { ShadowType, Spotlight, TexturedLight, type Light } from './lights';

/**
 * The value of a {@link TexturedLight}'s cookie (what the light pass reads from its texture's red
 * channel, 0..1) at texture coordinates (u, v) of the light's quad: (0, 0) is the quad's corner at
 * `−origin × size` from `position` before rotation (the texture's first texel as uploaded, which a
 * top-left world shows at the top left), (1, 1) the opposite corner. The GPU's texture cannot be
 * read without stalling it, so sample the CPU copy of the image you uploaded, with the same
 * filtering for the closest match.
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
   * exact soft shadow; 0 or 1 for a light of radius 0). Inside a hull it is 0 for a
   * {@link ShadowType.Solid} light and 1 for an {@link ShadowType.Illuminated} one; 1 for a light
   * with `castsShadows` off.
   */
  visibility: number;
  /**
   * How much of `color × intensity` the light would give the point without shadows: the distance
   * falloff, times the cone factor of a {@link Spotlight}, or the cookie of a {@link TexturedLight}.
   * Above 0 for every light listed.
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
   * range, outside a spotlight's cone, or with their centre inside a hull that shadows them.
   */
  lights: LightIllumination[];
}

/** Rec. 709 luminance weights (linear RGB). */
const LUMA_R = 0.2126, LUMA_G = 0.7152, LUMA_B = 0.0722;
/** The grid files every hull: queries may be anywhere in the world, on screen or not. */
const EVERYWHERE = [-Infinity, -Infinity, Infinity, Infinity] as const;

/**
 * The CPU side of `PenumbraRenderer.illuminationAt` and `isLit`: the renderer's light model at one
 * world point, from the lights and hulls themselves (no GPU read-back). Per light: the falloff, the
 * cone or cookie, and the exact visible fraction of its disk ({@link DiskVisibility}) past the hulls
 * that shadow it, found through a {@link HullGrid} of the hulls' bounds, so a query looks only at
 * the hulls between the point and each light's disk. The rules follow the renderer's frame: a
 * light is skipped when disabled, of intensity or range 0, or when its centre is inside a closed
 * hull that shadows it; a hull shadows a light when it is enabled, valid, shares a layer with the
 * light's `shadowLayers`, is not one of its `ignoredHulls`, and overlaps the light's bounds.
 *
 * The grid is rebuilt when a hull changed (its `version`) or the list did: every query compares
 * each hull's version, O(hulls) reads. Nothing is allocated per query but the result, and not that
 * when one is passed in to be reused.
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
  private readonly quad = new Float32Array(6);
  private readonly lightBounds = new Float64Array(4);
  private readonly point = new Float64Array(2);
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
    const result = out ?? { color: [0, 0, 0], luminance: 0, lights: [] };
    this.sync(hulls);
    let red = includeAmbient ? ambient[0] : 0, green = includeAmbient ? ambient[1] : 0, blue = includeAmbient ? ambient[2] : 0;
    let listed = 0;
    for (let i = 0; i < lights.length; i++) {
      const light = lights[i];
      const strength = this.strengthOf(light, x, y, cookie);
      if (!(strength > 0)) continue;
      const visibility = this.visibilityOf(light, hulls, x, y);
      if (visibility < 0) continue;
      const color = light.color, shadowColor = light.shadowColor, shadowStrength = light.shadowStrength;
      const scale = light.intensity * strength, hidden = 1 - visibility;
      const r = color[0] * scale * (visibility + hidden * (1 - shadowStrength * (1 - shadowColor[0])));
      const g = color[1] * scale * (visibility + hidden * (1 - shadowStrength * (1 - shadowColor[1])));
      const b = color[2] * scale * (visibility + hidden * (1 - shadowStrength * (1 - shadowColor[2])));
      red += r;
      green += g;
      blue += b;
      if (!perLight) continue;
      let entry = result.lights[listed];
      if (entry === undefined) result.lights.push((entry = { light, color: [0, 0, 0], luminance: 0, visibility: 0, strength: 0 }));
      entry.light = light;
      entry.color[0] = r;
      entry.color[1] = g;
      entry.color[2] = b;
      entry.luminance = LUMA_R * r + LUMA_G * g + LUMA_B * b;
      entry.visibility = visibility;
      entry.strength = strength;
      listed++;
    }
    result.lights.length = listed;
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
  isLit(lights: readonly Light[], hulls: readonly Hull[], x: number, y: number, threshold: number, cookie: CookieSampler | null): boolean {
    this.sync(hulls);
    if (this.strengths.length < lights.length) {
      const capacity = Math.ceil(lights.length * 1.5);
      this.strengths = new Float64Array(capacity);
      this.lows = new Float64Array(capacity);
      this.highs = new Float64Array(capacity);
    }
    const strengths = this.strengths, lows = this.lows, highs = this.highs;
    let low = 0, high = 0;
    for (let i = 0; i < lights.length; i++) {
      const light = lights[i];
      const strength = this.strengthOf(light, x, y, cookie);
      strengths[i] = strength;
      lows[i] = highs[i] = 0;
      if (!(strength > 0)) continue;
      const color = light.color;
      const full = (LUMA_R * color[0] + LUMA_G * color[1] + LUMA_B * color[2]) * light.intensity * strength;
      highs[i] = full;
      // A light that casts shadows may have its centre inside a hull: then it adds nothing.
      lows[i] = light.castsShadows ? 0 : full;
      low += lows[i];
      high += full;
    }
    if (low > threshold) return true;
    if (high <= threshold) return false;
    for (let i = 0; i < lights.length; i++) {
      if (lows[i] === highs[i]) continue;
      const light = lights[i];
      const visibility = this.visibilityOf(light, hulls, x, y);
      let exact = 0;
      if (visibility >= 0) {
        const color = light.color, shadowColor = light.shadowColor, shadowStrength = light.shadowStrength, hidden = 1 - visibility;
        exact = (LUMA_R * color[0] * (visibility + hidden * (1 - shadowStrength * (1 - shadowColor[0])))
          + LUMA_G * color[1] * (visibility + hidden * (1 - shadowStrength * (1 - shadowColor[1])))
          + LUMA_B * color[2] * (visibility + hidden * (1 - shadowStrength * (1 - shadowColor[2])))) * light.intensity * strengths[i];
      }
      low += exact - lows[i];
      high += exact - highs[i];
      if (low > threshold) return true;
      if (high <= threshold) return false;
    }
    return low > threshold;
  }

  /**
   * What the light gives (x, y) before shadows, as a multiplier on colour × intensity: the linear
   * falloff (times the cone of a spotlight, as shaders/light-spot.frag.glsl), or the cookie over a
   * textured light's quad. 0 for a light the renderer skips.
   */
  private strengthOf(light: Light, x: number, y: number, cookie: CookieSampler | null): number {
    if (!light.enabled || light.intensity === 0 || light.range === 0) return 0;
    if (light instanceof TexturedLight) {
      // The quad as the renderer draws it (float32): x = corner + u · axisX + v · axisY.
      const q = this.quad;
      light.writeQuad(q);
      const determinant = q[2] * q[5] - q[3] * q[4];
      if (determinant === 0) return 0;
      const rx = x - q[0], ry = y - q[1];
      const u = (rx * q[5] - ry * q[4]) / determinant, v = (q[2] * ry - q[3] * rx) / determinant;
      if (!(u >= 0 && u <= 1 && v >= 0 && v <= 1)) return 0;
      const value = cookie ? cookie(light, u, v) : 1;
      return value > 0 ? value : 0;
    }
    const dx = x - light.position[0], dy = y - light.position[1];
    const distance = Math.sqrt(dx * dx + dy * dy);
    const falloff = 1 - distance / light.range;
    if (!(falloff > 0)) return 0;
    if (!(light instanceof Spotlight)) return falloff;
    const along = distance > 0 ? (dx * Math.cos(light.rotation) + dy * Math.sin(light.rotation)) / distance : 1;
    const angle = Math.acos(along < -1 ? -1 : along > 1 ? 1 : along);
    const inside = 1 - angle / Math.max(light.coneAngle / 2, 1e-6);
    if (!(inside > 0)) return 0;
    return light.coneDecay === 0 ? falloff : falloff * Math.pow(inside, light.coneDecay);
  }

  /**
   * The fraction of the light's disk visible from (x, y) past the hulls that shadow it (1 or 0
   * inside one, by the light's shadow type), or −1 when the light's centre is inside one of them
   * (the renderer then leaves the light out).
   */
  private visibilityOf(light: Light, hulls: readonly Hull[], x: number, y: number): number {
    if (!light.castsShadows) return 1;
    const lx = light.position[0], ly = light.position[1];
    const bounds = this.lightBounds;
    this.writeLightBounds(light);
    const visibility = this.visibility;
    visibility.begin(x, y, lx, ly, light.radius);
    const point = this.point;
    point[0] = x;
    point[1] = y;
    const grid = this.grid;
    const found = grid.search(visibility.bounds);
    const layers = light.shadowLayers, ignored = light.ignoredHulls;
    let holdsPoint = false;
    for (let i = 0; i < found; i++) {
      const hull = hulls[grid.found[i]];
      if ((hull.layers & layers) === 0 || (ignored.size > 0 && ignored.has(hull))) continue;
      hull.updateWorld();
      const b = hull.worldBounds;
      // The renderer gives a light only the hulls that overlap its bounds.
      if (b[0] > bounds[2] || b[2] < bounds[0] || b[1] > bounds[3] || b[3] < bounds[1]) continue;
      if (hull.closed) {
        if (b[0] <= lx && lx <= b[2] && b[1] <= ly && ly <= b[3] && isInsidePolygon(hull.worldPoints, light.position)) return -1;
        if (!holdsPoint && b[0] <= x && x <= b[2] && b[1] <= y && y <= b[3] && isInsidePolygon(hull.worldPoints, point)) holdsPoint = true;
      }
      if (!holdsPoint) visibility.addOutline(hull.worldPoints, hull.pointCount, hull.closed);
    }
    if (holdsPoint) return light.shadowType === ShadowType.Illuminated ? 1 : 0;
    return visibility.fraction();
  }

  /** The light's bounds as the renderer's frame plan has them: its quad and its centre. */
  private writeLightBounds(light: Light): void {
    const q = this.quad, b = this.lightBounds;
    light.writeQuad(q);
    const lx = light.position[0], ly = light.position[1];
    b[0] = Math.min(lx, q[0], q[0] + q[2], q[0] + q[4], q[0] + q[2] + q[4]);
    b[1] = Math.min(ly, q[1], q[1] + q[3], q[1] + q[5], q[1] + q[3] + q[5]);
    b[2] = Math.max(lx, q[0], q[0] + q[2], q[0] + q[4], q[0] + q[2] + q[4]);
    b[3] = Math.max(ly, q[1], q[1] + q[3], q[1] + q[5], q[1] + q[3] + q[5]);
  }

  /** Rebuilds the grid when the hull list or a hull changed since it was built. */
  private sync(hulls: readonly Hull[]): void {
    const count = hulls.length, known = this.known, versions = this.versions;
    let same = count === known.length;
    for (let i = 0; same && i < count; i++) same = hulls[i] === known[i] && hulls[i].version === versions[i];
    if (same) return;
    if (this.filed.length < count) {
      const capacity = Math.ceil(count * 1.5);
      this.versions = new Float64Array(capacity);
      this.coarse = new Float64Array(4 * capacity);
      this.filed = new Uint8Array(capacity);
    }
    known.length = count;
    for (let i = 0; i < count; i++) {
      const hull = hulls[i];
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
