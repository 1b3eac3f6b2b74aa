/**
 * Outlines of labelled grid regions, traced along cell edges. Pure; see `gridRegions.ts` for the
 * labels.
 */

// Directions in cell units (y down): east, south, west, north. With the region on the left (the
// side (-dy, dx)), the outline has positive signed area; turning left is the next direction. LEFT_X/Y: the cell ahead and to the left of a
// vertex, relative to it; RIGHT_X/Y: ahead and to the right.
const DX = [1, 0, -1, 0], DY = [0, 1, 0, -1];
const LEFT_X = [0, -1, -1, 0], LEFT_Y = [0, 0, -1, -1];
const RIGHT_X = [0, 0, -1, -1], RIGHT_Y = [-1, 0, 0, -1];

/**
 * The outline of each region of `labels` (`labels[y * width + x]` = region index in `0..count-1`,
 * or −1), traced along cell edges, as flat `[x0, y0, x1, y1, …]` in cell units (cell (x, y) spans
 * x..x+1, y..y+1), with positive signed area (the library's counter-clockwise) and no collinear or
 * repeated points: a corner of the outline is a point, nothing else.
 *
 * Each region must be a disk, as {@link holeFreeRegions} makes them: 4-connected, without holes,
 * and without two of its cells meeting only at a corner. Its outline is then a simple polygon;
 * two regions may share edges and points. A region that is not a disk gets the outline of the
 * part reached from its first cell (a wrong shape, not an endless loop).
 *
 * O(cells + outline length): one scan finds each region's first cell (its top-left), and the trace
 * from there walks the outline once, keeping the region on its left.
 */
export function traceOutlines(labels: Int32Array, width: number, height: number, count: number): number[][] {
  const outlines = new Array<number[]>(count);
  const traced = new Uint8Array(count);
  for (let i = 0; i < width * height; i++) {
    const label = labels[i];
    if (label < 0 || traced[label]) continue;
    traced[label] = 1;
    outlines[label] = traceOne(labels, width, height, label, i % width, (i / width) | 0);
  }
  for (let label = 0; label < count; label++) if (!traced[label]) outlines[label] = [];
  return outlines;
}

/**
 * Walks the outline of region `label` from the top-left corner of its first cell (x0, y0), heading
 * east with the region on the left: at each vertex it turns left where the cell ahead-left is not
 * the region's, right where the cell ahead-right is, and goes on otherwise.
 */
function traceOne(labels: Int32Array, width: number, height: number, label: number, x0: number, y0: number): number[] {
  const inRegion = (x: number, y: number) => x >= 0 && y >= 0 && x < width && y < height && labels[y * width + x] === label;
  const points = [x0, y0];
  let x = x0 + 1, y = y0, dir = 0;
  // The walk is a permutation of the grid's directed edges, so it is back at the start within that many steps.
  for (let steps = 4 * (width + 1) * (height + 1); steps > 0; steps--) {
    if (x === x0 && y === y0) return points;
    let turn = dir;
    if (!inRegion(x + LEFT_X[dir], y + LEFT_Y[dir])) turn = (dir + 1) & 3;
    else if (inRegion(x + RIGHT_X[dir], y + RIGHT_Y[dir])) turn = (dir + 3) & 3;
    if (turn !== dir) {
      points.push(x, y);
      dir = turn;
    }
    x += DX[dir];
    y += DY[dir];
  }
  throw new Error(`traceOutlines: the outline of region ${label} does not close`);
}
