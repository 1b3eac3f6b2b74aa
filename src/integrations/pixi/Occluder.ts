import type { Container } from 'pixi.js';
import type { Hull, PenumbraRenderer } from '../../index';

/**
 * Where the hulls go, read once per frame by the layer: the camera (whose local space is the
 * lights' world), the inverse of the camera's transform to the stage, and the stage the layer is
 * drawn in. @internal
 */
export interface OccluderSpace {
  /** The layer's camera, or `null` for stage pixels. */
  camera: Container | null;
  /** The topmost ancestor of the layer (the stage it is drawn in), or the layer itself. */
  root: Container | null;
  /** Stage → camera space, `[a, b, c, d, tx, ty]`; valid when `camera` is set. */
  readonly fromRoot: Float64Array;
}

/** What one walk up the parent chain found; reused, so that a frame allocates nothing. */
const walk = { found: false, visible: true, root: null as Container | null };
const WALKED = new Float64Array(6);
const RELATIVE = new Float64Array(6);
const PLACED = new Float64Array(6);
/** Columns closer to perpendicular than this (relative to the matrix's size) count as no skew. */
const SKEW_EPSILON = 1e-9;

/**
 * Hulls that follow a Pixi display object: made by {@link PenumbraLayer.follow} (your hulls) or
 * {@link PenumbraLayer.addOccluder} (a sprite's alpha, a Graphics' shapes), kept in
 * {@link PenumbraLayer.occluders} and updated by the layer each time it renders.
 *
 * Each hull's points are in the object's local space, placed within it by the hull's own
 * `position`, `origin`, `rotation` and `scale` as they were when it started following (so hulls
 * made for a sprite at the origin, e.g. `hullsFromAlpha(image)` with the sprite's anchor, follow
 * it as they are). From then on the occluder owns those fields: each frame it composes the
 * object's transform relative to the layer's camera (position, rotation, scale, a negative scale
 * mirroring, pivot, and every parent's up to the camera) with that placement and writes the
 * result into the hulls, but only when it changed: a still object, also under a moving camera,
 * costs a few multiplications a frame and no allocation, and its hulls keep their version (the
 * renderer rebuilds nothing). A move allocates only the frozen pairs the hulls' setters make.
 *
 * **Skew.** A hull has no skew of its own. While the composed transform is skewed (the object's or
 * a parent's `skew`, or a non-uniform scale under a rotated parent), the occluder writes the
 * transformed points into the hull instead (exact, but each change re-triangulates the hull and
 * allocates), and goes back to moving the original points once the skew is gone.
 *
 * **Visibility.** Its hulls cast shadows while {@link Occluder.enabled} is true, the object and
 * every parent up to the camera are `visible`, and the object is in the stage the layer is drawn
 * in (under the camera, or with the camera elsewhere in the same stage). Removed from the stage
 * (`removeChild`) its hulls are disabled, and enabled again once it is added back. When the object
 * is destroyed the occluder is removed from the layer and its hulls from the renderer.
 */
export class Occluder {
  /** The display object the hulls follow. */
  readonly object: Container;
  /** Whether the hulls may cast shadows; see the visibility rules above. Default `true`. */
  enabled = true;

  /** The renderer the hulls are in. */
  protected readonly renderer: PenumbraRenderer;
  private _hulls: Hull[] = [];
  /** Each hull's points as it was given them, in its own local space. */
  private given: ReadonlyArray<ReadonlyArray<readonly [number, number]>> = [];
  /** Each hull's placement within the object: `[a, b, c, d, tx, ty]` per hull. */
  private bases: Float64Array = new Float64Array(0);
  /** Whether each hull now holds transformed points (a skewed transform) rather than its given ones. */
  private baked: boolean[] = [];
  /** The object → camera transform the hulls were last placed with. */
  private readonly last = new Float64Array(6);
  /** Whether the hulls must be placed again whatever the transform. */
  private stale = true;
  private shown = true;
  private readonly onDestroyed: () => void;

  /**
   * Made by the layer ({@link PenumbraLayer.follow}); `onDestroyed` removes the occluder from it.
   * @internal
   */
  constructor(object: Container, renderer: PenumbraRenderer, hulls: readonly Hull[], onDestroyed: (occluder: Occluder) => void) {
    this.object = object;
    this.renderer = renderer;
    this.onDestroyed = () => onDestroyed(this);
    object.on('destroyed', this.onDestroyed);
    this.setHulls(hulls);
  }

  /** The hulls, in the layer's renderer; a new array when they are replaced (a sprite's new texture, a redrawn Graphics). */
  get hulls(): readonly Hull[] {
    return this._hulls;
  }

  /**
   * Places the hulls for the object's current transform, if it changed since the last call. The
   * layer calls it for every occluder each time it renders. @internal
   */
  update(space: OccluderSpace): void {
    this.refresh();
    const shown = placeInSpace(this.object, space, RELATIVE) && this.enabled;
    if (shown !== this.shown) {
      this.shown = shown;
      for (let i = 0; i < this._hulls.length; i++) this._hulls[i].enabled = shown;
    }
    if (!shown) return;
    const m = RELATIVE, last = this.last;
    if (!this.stale && m[0] === last[0] && m[1] === last[1] && m[2] === last[2] && m[3] === last[3] && m[4] === last[4] && m[5] === last[5]) return;
    this.stale = false;
    last.set(m);
    for (let i = 0; i < this._hulls.length; i++) {
      multiply(PLACED, m, this.bases, 6 * i);
      this.place(i, PLACED);
    }
  }

  /**
   * Removes the hulls from the renderer and stops listening to the object. The layer calls it
   * from {@link PenumbraLayer.removeOccluder}. @internal
   */
  detach(): void {
    this.object.off('destroyed', this.onDestroyed);
    for (const hull of this._hulls) this.renderer.removeHull(hull);
  }

  /** Called first each time the layer places the hulls: subclasses check their source (texture, shapes) here. */
  protected refresh(): void {}

  /**
   * Replaces the hulls (removing the old ones from the renderer, adding the new ones), each placed
   * within the object by its own fields, or by `bases` (`[a, b, c, d, tx, ty]` per hull) when given.
   */
  protected setHulls(hulls: readonly Hull[], bases?: Float64Array): void {
    for (const hull of this._hulls) this.renderer.removeHull(hull);
    this._hulls = [...hulls];
    this.given = hulls.map((hull) => hull.points);
    this.baked = hulls.map(() => false);
    this.bases = bases ?? new Float64Array(6 * hulls.length);
    if (!bases) hulls.forEach((hull, i) => placementOf(hull, this.bases, 6 * i));
    for (const hull of this._hulls) {
      hull.enabled = this.shown;
      this.renderer.addHull(hull);
    }
    this.stale = true;
  }

  /** Changes each hull's placement within the object (`[a, b, c, d, tx, ty]` per hull), e.g. for a new anchor. */
  protected setBases(bases: Float64Array): void {
    this.bases = bases;
    this.stale = true;
  }

  /** Writes transform `m` (hull points → camera space) into hull `i`. */
  private place(i: number, m: Float64Array): void {
    const hull = this._hulls[i];
    const a = m[0], b = m[1], c = m[2], d = m[3];
    if (Math.abs(a * c + b * d) > SKEW_EPSILON * (a * a + b * b + c * c + d * d)) {
      // Skewed: no rotation and scale give it, so the points themselves are transformed.
      hull.points = this.given[i].map(([x, y]) => [a * x + c * y, b * x + d * y] as [number, number]);
      this.baked[i] = true;
      setPlacement(hull, 0, 1, 1, m[4], m[5]);
      return;
    }
    if (this.baked[i]) {
      hull.points = this.given[i];
      this.baked[i] = false;
    }
    // m = R(θ) · diag(sx, sy) with perpendicular columns; a negative sy is a mirror.
    let sx = Math.hypot(a, b), sy: number, rotation: number;
    if (sx > 0) {
      rotation = Math.atan2(b, a);
      sy = (a * d - b * c) / sx;
    } else {
      sy = Math.hypot(c, d);
      rotation = sy > 0 ? Math.atan2(-c, d) : 0;
      sx = 0;
    }
    setPlacement(hull, rotation, sx, sy, m[4], m[5]);
  }
}

/** Sets a hull's fields to these values with origin `[0, 0]`, touching only those that differ. */
function setPlacement(hull: Hull, rotation: number, sx: number, sy: number, x: number, y: number): void {
  const origin = hull.origin;
  if (origin[0] !== 0 || origin[1] !== 0) hull.origin = ZERO;
  if (hull.rotation !== rotation) hull.rotation = rotation;
  const scale = hull.scale;
  if (scale[0] !== sx || scale[1] !== sy) hull.scale = [sx, sy];
  const position = hull.position;
  if (position[0] !== x || position[1] !== y) hull.setPosition(x, y);
}

const ZERO = Object.freeze([0, 0] as const);

/** A hull's own placement as a matrix at `out[offset…]`: points → position + R · S · (p − origin). */
function placementOf(hull: Hull, out: Float64Array, offset: number): void {
  const cos = Math.cos(hull.rotation), sin = Math.sin(hull.rotation);
  const [sx, sy] = hull.scale;
  const [ox, oy] = hull.origin;
  const [px, py] = hull.position;
  const a = cos * sx, b = sin * sx, c = -sin * sy, d = cos * sy;
  out[offset] = a;
  out[offset + 1] = b;
  out[offset + 2] = c;
  out[offset + 3] = d;
  out[offset + 4] = px - (a * ox + c * oy);
  out[offset + 5] = py - (b * ox + d * oy);
}

/** `out = m · n[offset…]` (n applied first), matrices as `[a, b, c, d, tx, ty]`. */
function multiply(out: Float64Array, m: Float64Array, n: Float64Array, offset: number): void {
  const na = n[offset], nb = n[offset + 1], nc = n[offset + 2], nd = n[offset + 3], ntx = n[offset + 4], nty = n[offset + 5];
  const ma = m[0], mb = m[1], mc = m[2], md = m[3];
  out[0] = ma * na + mc * nb;
  out[1] = mb * na + md * nb;
  out[2] = ma * nc + mc * nd;
  out[3] = mb * nc + md * nd;
  out[4] = ma * ntx + mc * nty + m[4];
  out[5] = mb * ntx + md * nty + m[5];
}

/**
 * Writes into `out` the transform from `object`'s local space to that of `stop` (excluded), or to
 * the stage above its topmost ancestor when `stop` is not one of its ancestors, from each node's
 * own local transform (never from world transforms that Pixi may not have updated yet), and
 * records in {@link walk} whether it met `stop`, whether every node on the way was visible, and
 * the topmost node.
 */
function walkUp(object: Container, stop: Container | null, out: Float64Array): void {
  out[0] = 1; out[1] = 0; out[2] = 0; out[3] = 1; out[4] = 0; out[5] = 0;
  walk.found = false;
  walk.visible = true;
  let node: Container | null = object;
  let top = object;
  while (node) {
    if (node === stop) {
      walk.found = true;
      break;
    }
    if (!node.visible) walk.visible = false;
    node.updateLocalTransform();
    const t = node.localTransform;
    const a = out[0], b = out[1], c = out[2], d = out[3], tx = out[4], ty = out[5];
    out[0] = t.a * a + t.c * b;
    out[1] = t.b * a + t.d * b;
    out[2] = t.a * c + t.c * d;
    out[3] = t.b * c + t.d * d;
    out[4] = t.a * tx + t.c * ty + t.tx;
    out[5] = t.b * tx + t.d * ty + t.ty;
    top = node;
    node = node.parent;
  }
  walk.root = top;
}

/**
 * Writes into `out` the transform from `object`'s local space to the camera's (or to the stage
 * without a camera), `[a, b, c, d, tx, ty]`, and returns whether the object is shown: it and every
 * parent up to the camera are visible, and it is in the stage the layer is drawn in. @internal
 */
export function placeInSpace(object: Container, space: OccluderSpace, out: Float64Array): boolean {
  walkUp(object, space.camera, out);
  if (!walk.found && space.camera) {
    // The camera is not an ancestor: through the stage, then into the camera's space.
    WALKED.set(out);
    multiply(out, space.fromRoot, WALKED, 0);
  }
  return walk.visible && (walk.found || walk.root === space.root);
}

/**
 * Fills `space` for this frame: the layer's stage and, with a camera, stage → camera. @internal
 */
export function prepareSpace(space: OccluderSpace, layer: Container, camera: Container | null): void {
  let top = layer;
  while (top.parent) top = top.parent;
  space.root = top;
  space.camera = camera;
  if (!camera) return;
  walkUp(camera, null, WALKED);
  const a = WALKED[0], b = WALKED[1], c = WALKED[2], d = WALKED[3], tx = WALKED[4], ty = WALKED[5];
  const det = a * d - b * c;
  const m = space.fromRoot;
  m[0] = d / det;
  m[1] = -b / det;
  m[2] = -c / det;
  m[3] = a / det;
  m[4] = (c * ty - d * tx) / det;
  m[5] = (b * tx - a * ty) / det;
}
