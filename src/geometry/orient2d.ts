/**
 * The orientation predicate with the right sign for any doubles: adaptive exact arithmetic after
 * Shewchuk ("Adaptive Precision Floating-Point Arithmetic and Fast Robust Geometric Predicates",
 * 1997). A floating-point determinant is returned as it is when its error bound proves its sign
 * (almost every call); otherwise the determinant of the rounded coordinate differences is
 * computed exactly, and, if those differences were themselves rounded and that result is still
 * too close to call, the determinant of the coordinates as given, exactly.
 *
 * Accuracy limit: exact as long as no product of two coordinates (or of two coordinate
 * differences) overflows or underflows, which holds for any coordinate between about 1e-140 and
 * 1e150 in magnitude, and for 0.
 */

const EPSILON = 2 ** -53;
/** 2^27 + 1: splits a double into two halves of 26 bits whose products are exact. */
const SPLITTER = 134217729;
/** Bound on the error of the plain floating-point determinant, relative to the sum of its two products' magnitudes. */
const ERROR_BOUND_A = (3 + 16 * EPSILON) * EPSILON;
/** Bound on the error of the estimate of the exact determinant of the rounded differences. */
const ERROR_BOUND_B = (2 + 12 * EPSILON) * EPSILON;

/** Scratch expansions, reused: the predicate allocates nothing. */
const differenceTerms = new Float64Array(4);
const exactTerms = new Float64Array(12);

/**
 * Twice the signed area of the triangle a, b, c, with its sign exact: positive when the points
 * turn counter-clockwise in a y-up frame (c left of the line from a to b), negative when they turn
 * clockwise, 0 exactly when they are collinear. Its magnitude is approximate.
 */
export function orient2d(ax: number, ay: number, bx: number, by: number, cx: number, cy: number): number {
  const left = (ax - cx) * (by - cy), right = (ay - cy) * (bx - cx);
  const determinant = left - right;
  const magnitude = Math.abs(left + right);
  if (Math.abs(determinant) >= ERROR_BOUND_A * magnitude) return determinant;
  return orient2dAdaptive(ax, ay, bx, by, cx, cy, magnitude);
}

/** The sign of {@link orient2d} as −1, 0 or 1. */
export function orientationSign(ax: number, ay: number, bx: number, by: number, cx: number, cy: number): number {
  return Math.sign(orient2d(ax, ay, bx, by, cx, cy));
}

function orient2dAdaptive(ax: number, ay: number, bx: number, by: number, cx: number, cy: number, magnitude: number): number {
  const acx = ax - cx, bcx = bx - cx, acy = ay - cy, bcy = by - cy;
  // The exact determinant of the rounded differences, acx·bcy − acy·bcx, as a 4-term expansion.
  let count = 0;
  count = growExpansion(differenceTerms, count, acx * bcy);
  count = growExpansion(differenceTerms, count, productTail(acx, bcy, acx * bcy));
  count = growExpansion(differenceTerms, count, -(acy * bcx));
  count = growExpansion(differenceTerms, count, -productTail(acy, bcx, acy * bcx));
  const estimate = expansionEstimate(differenceTerms, count);
  const differencesExact = differenceTail(ax, cx, acx) === 0 && differenceTail(bx, cx, bcx) === 0
    && differenceTail(ay, cy, acy) === 0 && differenceTail(by, cy, bcy) === 0;
  if (differencesExact) return expansionSign(differenceTerms, count) * Math.max(Math.abs(estimate), Number.MIN_VALUE);
  if (Math.abs(estimate) >= ERROR_BOUND_B * magnitude) return estimate;
  return exactOrientation(ax, ay, bx, by, cx, cy);
}

/**
 * The determinant of the coordinates as given, exactly: expanded into its six products
 * (bx·cy − bx·ay − ax·cy − by·cx + by·ax + ay·cx), each an exact two-term expansion, summed
 * without rounding. Returns its sign with the magnitude of its largest term.
 */
function exactOrientation(ax: number, ay: number, bx: number, by: number, cx: number, cy: number): number {
  let count = 0;
  count = addProduct(count, bx, cy);
  count = addProduct(count, -bx, ay);
  count = addProduct(count, -ax, cy);
  count = addProduct(count, -by, cx);
  count = addProduct(count, by, ax);
  count = addProduct(count, ay, cx);
  return expansionSign(exactTerms, count) * Math.max(Math.abs(expansionEstimate(exactTerms, count)), Number.MIN_VALUE);
}

function addProduct(count: number, a: number, b: number): number {
  const product = a * b;
  count = growExpansion(exactTerms, count, product);
  return growExpansion(exactTerms, count, productTail(a, b, product));
}

/** The rounding error of `product = a · b`: a · b = product + tail exactly (Dekker's split). */
function productTail(a: number, b: number, product: number): number {
  let c = SPLITTER * a;
  const aHigh = c - (c - a), aLow = a - aHigh;
  c = SPLITTER * b;
  const bHigh = c - (c - b), bLow = b - bHigh;
  return aLow * bLow - (product - aHigh * bHigh - aLow * bHigh - aHigh * bLow);
}

/** The rounding error of `difference = a − b`: a − b = difference + tail exactly. */
function differenceTail(a: number, b: number, difference: number): number {
  const bVirtual = a - difference, aVirtual = difference + bVirtual;
  return (a - aVirtual) + (bVirtual - b);
}

/**
 * Adds `value` to the nonoverlapping expansion `terms[0 … count − 1]` (smallest magnitude first),
 * exactly, dropping zero terms (Shewchuk's Grow-Expansion with zero elimination); returns the new
 * count.
 */
function growExpansion(terms: Float64Array, count: number, value: number): number {
  let carry = value, out = 0;
  for (let i = 0; i < count; i++) {
    const sum = carry + terms[i];
    const virtual = sum - carry;
    const tail = (carry - (sum - virtual)) + (terms[i] - virtual);
    if (tail !== 0) terms[out++] = tail;
    carry = sum;
  }
  if (carry !== 0) terms[out++] = carry;
  return out;
}

function expansionEstimate(terms: Float64Array, count: number): number {
  let sum = 0;
  for (let i = 0; i < count; i++) sum += terms[i];
  return sum;
}

/** The sign of a nonoverlapping expansion: that of its largest (last) term. */
function expansionSign(terms: Float64Array, count: number): number {
  return count === 0 ? 0 : Math.sign(terms[count - 1]);
}
