/** Axis-aligned boxes as `[minX, minY, maxX, maxY]` in typed arrays, written in place. */

/** Sets `box` to the empty box (inside out), which {@link extendBox} grows. */
export function emptyBox(box: Float64Array): void {
  box[0] = box[1] = Infinity;
  box[2] = box[3] = -Infinity;
}

/** Grows `box` to hold `other`. */
export function extendBox(box: Float64Array, other: Float64Array): void {
  if (other[0] < box[0]) box[0] = other[0];
  if (other[1] < box[1]) box[1] = other[1];
  if (other[2] > box[2]) box[2] = other[2];
  if (other[3] > box[3]) box[3] = other[3];
}

/** Whether the boxes `a` (at `4 × at`) and `b` overlap, edges included. */
export function boxesOverlap(a: Float64Array, at: number, b: Float64Array): boolean {
  const k = 4 * at;
  return a[k] <= b[2] && a[k + 2] >= b[0] && a[k + 1] <= b[3] && a[k + 3] >= b[1];
}
