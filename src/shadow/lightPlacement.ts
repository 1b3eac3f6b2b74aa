import { mat4, type ReadonlyMat4 } from 'gl-matrix';
import { DirectionalLight } from '../scene/DirectionalLight';
import type { Light } from '../scene/Light';
import type { LightFiling } from './filings';
import { DirectionalStrips } from './ShadowBins';
import { LISTED_RECORDS, TILE_CLASS_COUNT } from './shadowLayout';

/**
 * What the passes need to draw one light, as the shadow cache leaves it: its quad, the hulls that shadow
 * it, its row of shadow bins and how they were filed, and its tiles of each class.
 */
export class LightDraw {
  light!: Light;
  /** `[cornerX, cornerY, axisXx, axisXy, axisYx, axisYy]`, see `Light.writeQuad`. */
  readonly quad = new Float32Array(6);
  /** `[minX, minY, maxX, maxY]` of the quad and the light centre, in world units. */
  readonly bounds = new Float64Array(4);
  /** Distance from the light's position beyond which it adds nothing (`Light.reach`). */
  reach = 0;
  /** Number of hulls in range that shadow this light (in both its lists). */
  hullCount = 0;
  /** The light's row in the shadow cache's `bins` and its `tiles`, when `hullCount > 0`. */
  binRow = 0;
  /**
   * How a light with a centre was filed, when `hullCount > 0` (the shader's `u_binning`): the bins'
   * origin, the disk radius they were filed for, and their distance buckets' width.
   */
  readonly binning = new Float32Array(4);
  /**
   * A shadowed point light's tile grid, when `hullCount > 0` (the light pass's `u_tiles`): its
   * corner (least x and y) and a tile's width and height.
   */
  readonly tileFrame = new Float32Array(4);
  /** A shadowed point light's tiles of each class (indexed by TILE_CLASSES), when `hullCount > 0`. */
  readonly tileCounts = new Int32Array(TILE_CLASS_COUNT);
  /**
   * Whether a shadowed point light's general tiles may take the closed program, when `hullCount > 0`:
   * its records reaching into its filed disk are one record or one convex hull's fan, and it is not
   * Occluded (`LightTiles.closedFormSuffices`).
   */
  closedForm = false;
  /** A shadowed point light's listed records, when it has listed tiles (`TileRecordLists`; the light pass's `u_listedRecords`). */
  readonly listedRecords = new Int32Array(LISTED_RECORDS);
  /** Per class of its tiles, where its rectangles' indices start in the shadow cache's `tiles.rectangles` and how many (`LightTiles.writeLists`), when `hullCount > 0`. */
  readonly tileLists = new Int32Array(2 * TILE_CLASS_COUNT);
  /** A directional light's strips over the view (its bins). */
  readonly strips = new DirectionalStrips();
  /** The light's filing, kept from frame to frame: the shadow cache's own. */
  filing!: LightFiling;
}

/**
 * Places each frame's lights: the enabled, visible ones whose quad reaches into the target, each
 * with its quad (a directional light's is the view's) and bounds.
 */
export class LightPlacement {
  private readonly inverseViewProjection = mat4.create();

  /** Puts the placed lights in the first of `draws` (grown as needed); returns how many. */
  place(draws: LightDraw[], lights: readonly Light[], viewProjection: ReadonlyMat4, targetWidth: number, targetHeight: number): number {
    let placed = 0;
    for (let i = 0; i < lights.length; i++) {
      const light = lights[i];
      if (!light.enabled || light.intensity === 0 || light.range === 0) continue;
      if (draws.length === placed) draws.push(new LightDraw());
      const draw = draws[placed];
      draw.light = light;
      draw.reach = light.reach();
      if (light instanceof DirectionalLight) this.writeViewQuad(viewProjection, draw.quad);
      else light.writeQuad(draw.quad);
      writeBounds(draw);
      if (reachesTarget(draw.bounds, viewProjection, targetWidth, targetHeight)) placed++;
    }
    return placed;
  }

  /** Writes the view rectangle's world quad: clip space's corner (−1, −1) and its two edges, through the inverse view-projection. */
  private writeViewQuad(viewProjection: ReadonlyMat4, quad: Float32Array): void {
    const inverse = mat4.invert(this.inverseViewProjection, viewProjection) ?? mat4.identity(this.inverseViewProjection);
    // The views are affine in x and y (w = 1): the world point of clip (x, y) is m·(x, y, 0, 1).
    const m = inverse;
    quad[0] = -m[0] - m[4] + m[12];
    quad[1] = -m[1] - m[5] + m[13];
    quad[2] = 2 * m[0];
    quad[3] = 2 * m[1];
    quad[4] = 2 * m[4];
    quad[5] = 2 * m[5];
  }
}

/** The bounds of the light's quad and, but for a directional light (which has none), its centre. */
function writeBounds(draw: LightDraw): void {
  const q = draw.quad, light = draw.light;
  const directional = light instanceof DirectionalLight;
  // A quad corner stands in for a directional light's centre: it changes nothing.
  const lx = directional ? q[0] : light.position[0], ly = directional ? q[1] : light.position[1];
  const b = draw.bounds;
  b[0] = Math.min(lx, q[0], q[0] + q[2], q[0] + q[4], q[0] + q[2] + q[4]);
  b[1] = Math.min(ly, q[1], q[1] + q[3], q[1] + q[5], q[1] + q[3] + q[5]);
  b[2] = Math.max(lx, q[0], q[0] + q[2], q[0] + q[4], q[0] + q[2] + q[4]);
  b[3] = Math.max(ly, q[1], q[1] + q[3], q[1] + q[5], q[1] + q[3] + q[5]);
}

/**
 * Whether the world-space box `bounds = [minX, minY, maxX, maxY]` under `viewProjection` covers
 * some pixel of a `targetWidth × targetHeight` target, its projection rounded outward to whole
 * pixels (a box that reaches into a pixel at all counts).
 */
function reachesTarget(bounds: ArrayLike<number>, viewProjection: ReadonlyMat4, targetWidth: number, targetHeight: number): boolean {
  let minX = Infinity, minY = Infinity, maxX = -Infinity, maxY = -Infinity;
  const m = viewProjection;
  for (let corner = 0; corner < 4; corner++) {
    const x = bounds[corner & 1 ? 2 : 0];
    const y = bounds[corner & 2 ? 3 : 1];
    const w = m[3] * x + m[7] * y + m[15];
    const sx = ((m[0] * x + m[4] * y + m[12]) / w * 0.5 + 0.5) * targetWidth;
    const sy = ((m[1] * x + m[5] * y + m[13]) / w * 0.5 + 0.5) * targetHeight;
    if (sx < minX) minX = sx;
    if (sx > maxX) maxX = sx;
    if (sy < minY) minY = sy;
    if (sy > maxY) maxY = sy;
  }
  return Math.min(targetWidth, Math.ceil(maxX)) > Math.max(0, Math.floor(minX))
    && Math.min(targetHeight, Math.ceil(maxY)) > Math.max(0, Math.floor(minY));
}
