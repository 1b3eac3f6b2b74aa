import { extendBox } from '../geometry/boxes';
import type { HullGrid } from '../geometry/HullGrid';
import type { Hull } from '../scene/Hull';
import type { DirectionalLight } from '../scene/DirectionalLight';
import { shadows } from './casters';
import type { LightDraw } from './lightPlacement';
import { DISTANCE_BUCKETS, type DirectionalStrips, type ShadowBins } from './ShadowBins';
import { BIN_COUNT } from './shadowLayout';
import type { ShadowGeometry } from './ShadowGeometry';

/**
 * Files a directional light's hulls into its strips over the view (see
 * `ShadowBins.addDirectionalHull`), every frame: the strips follow the view. Every hull goes in
 * the first list of its strips, moving or still.
 */
export class DirectionalFiling {
  /** The box the light's search covers: the view swept upstream. */
  private readonly upstreamBox = new Float64Array(4);
  /** The box of the hulls both grids filed. */
  private readonly hullsExtent = new Float64Array(4);

  /**
   * Files the hulls whose shadow can reach the view into the strips of `draw`'s light (its filing's
   * still span): those the grids find upstream of the view, in its layers and not ignored; counts
   * them in its filing. `movingGrid` is null when no hull moves.
   */
  file(draw: LightDraw, hulls: readonly Hull[], geometry: ShadowGeometry, bins: ShadowBins, grid: HullGrid, movingGrid: HullGrid | null): void {
    const light = draw.light as DirectionalLight, filing = draw.filing;
    filing.stillCount = 0;
    if (!light.castsShadows) return;
    const box = writeUpstreamBox(draw, this.upstreamBox), extent = this.hullsExtent;
    extent.set(grid.extent);
    if (movingGrid) extendBox(extent, movingGrid.extent);
    writeStrips(draw, light, extent, draw.strips);
    bins.beginDirectional(draw.strips);
    addHulls(draw, hulls, geometry, bins, grid, box);
    if (movingGrid) addHulls(draw, hulls, geometry, bins, movingGrid, box);
    bins.endLight(geometry, filing.stillSpan);
  }

  /** The box the hulls of `draw`'s directional light are searched in (see {@link writeUpstreamBox}). */
  searchBox(draw: LightDraw): Float64Array {
    return writeUpstreamBox(draw, this.upstreamBox);
  }
}

/** Adds the hulls `grid` finds in `box` whose shadow can reach the view to the directional light's candidates, counting them in its filing. */
function addHulls(draw: LightDraw, hulls: readonly Hull[], geometry: ShadowGeometry, bins: ShadowBins, grid: HullGrid, box: Float64Array): void {
  const light = draw.light, count = grid.search(box);
  for (let i = 0; i < count; i++) {
    const index = grid.found[i];
    if (!shadows(light, hulls, geometry, index)) continue;
    geometry.prepare(index);
    if (bins.addDirectionalHull(geometry, index)) draw.filing.stillCount++;
  }
}

/**
 * The box a directional light's hulls are searched in: the view's bounds, swept without end against
 * the travel and across it (a far hull's penumbra widens without end), bounded only on the side the
 * light travels to in each axis along which it moves.
 */
function writeUpstreamBox(draw: LightDraw, box: Float64Array): Float64Array {
  const b = draw.bounds, rotation = draw.light.rotation;
  const travelX = Math.cos(rotation), travelY = Math.sin(rotation);
  box[0] = travelX < 0 ? b[0] : -Infinity;
  box[1] = travelY < 0 ? b[1] : -Infinity;
  box[2] = travelX > 0 ? b[2] : Infinity;
  box[3] = travelY > 0 ? b[3] : Infinity;
  return box;
}

/**
 * Sets a directional light's strips over the view quad of `draw`, with the first distance bucket
 * at the least coordinate along the travel of the view and of `hulls`, the box of the hulls searched
 * (a hull's circle may reach a little further: it goes in the first bucket). Doubles go through
 * objects, not arguments (see Hot-path rules in docs/architecture.md).
 */
function writeStrips(draw: LightDraw, light: DirectionalLight, hulls: Float64Array, strips: DirectionalStrips): void {
  const travelX = Math.cos(light.rotation), travelY = Math.sin(light.rotation), q = draw.quad;
  strips.travelX = travelX;
  strips.travelY = travelY;
  strips.tangent = Math.tan(light.angularSize / 2);
  let perpMin = Infinity, perpMax = -Infinity, alongMin = Infinity, alongMax = -Infinity;
  for (let corner = 0; corner < 4; corner++) {
    const x = q[0] + (corner & 1 ? q[2] : 0) + (corner & 2 ? q[4] : 0), y = q[1] + (corner & 1 ? q[3] : 0) + (corner & 2 ? q[5] : 0);
    const along = x * travelX + y * travelY, across = y * travelX - x * travelY;
    perpMin = Math.min(perpMin, across);
    perpMax = Math.max(perpMax, across);
    alongMin = Math.min(alongMin, along);
    alongMax = Math.max(alongMax, along);
  }
  strips.perpBase = perpMin;
  strips.width = Math.max(perpMax - perpMin, 1e-9) / BIN_COUNT;
  strips.alongEnd = alongMax;
  // HullGrid.leastAlong written out (see Hot-path rules in docs/architecture.md).
  const hullsFrom = hulls[0] > hulls[2] ? Infinity
    : (travelX < 0 ? hulls[2] : hulls[0]) * travelX + (travelY < 0 ? hulls[3] : hulls[1]) * travelY;
  strips.alongBase = Math.min(alongMin, hullsFrom);
  strips.bucketWidth = Math.max(alongMax - strips.alongBase, 1e-9) / DISTANCE_BUCKETS;
}
