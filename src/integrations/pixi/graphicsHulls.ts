import {
  earcut, Graphics, type Circle, type Ellipse, type GraphicsContext, type Matrix, type Polygon, type Rectangle,
  type RoundedRectangle, type ShapePrimitive, type Triangle,
} from 'pixi.js';
import { Hull, type PenumbraRenderer } from '../../index';
import { Occluder } from './Occluder';

/** Options of {@link hullsFromGraphics} and of {@link PenumbraLayer.addOccluder} for a `Graphics`; every field has the default shown. */
export interface GraphicsHullsOptions {
  /**
   * Largest distance, in the Graphics' local units, between a curved outline (circle, ellipse, the
   * corners of a rounded rectangle) and the polygon that stands for it: the polygon's points lie
   * on the curve and its edges within this of it, inside. Must be > 0. Default `0.5`.
   */
  tolerance?: number;
}

/**
 * Hulls covering the filled shapes of a Pixi `Graphics` (or of a `GraphicsContext`), in its local
 * space: `rect`, `roundRect`, `circle`, `ellipse`, `poly`, `regularPoly`, `star`, and paths
 * (`moveTo`, `lineTo`, arcs and curves, as Pixi flattens them), each with the context transform it
 * was drawn with. Circles, ellipses and rounded corners become polygons within `tolerance` of the
 * curve. A shape with holes (`cut()`), or a path that crosses itself, is cut into simple pieces
 * that meet exactly along the cuts (hulls have no holes); one without is one hull. Strokes,
 * textures (`texture()`) and shapes of other types are left out: give those their own hulls.
 *
 * A snapshot: to keep hulls on a Graphics as it moves or is redrawn, use
 * {@link PenumbraLayer.addOccluder}. Reads the context's drawing instructions, which Pixi 8 marks
 * internal (tested with 8.22).
 *
 * ```ts
 * const crate = new Graphics().roundRect(0, 0, 40, 40, 6).fill(0x8a6a3a).circle(20, 20, 8).cut();
 * for (const hull of hullsFromGraphics(crate)) hull.position = [300, 200]; // or lighting.addOccluder(crate)
 * ```
 * @throws RangeError when `tolerance` is not a finite number > 0.
 */
export function hullsFromGraphics(graphics: Graphics | GraphicsContext, options: GraphicsHullsOptions = {}): Hull[] {
  const { tolerance = 0.5 } = options;
  if (typeof tolerance !== 'number' || !(tolerance > 0) || !Number.isFinite(tolerance)) {
    throw new RangeError(`hullsFromGraphics options.tolerance must be a finite number > 0, got ${String(tolerance)}`);
  }
  const context = graphics instanceof Graphics ? graphics.context : graphics;
  const hulls: Hull[] = [];
  for (const instruction of context.instructions) {
    if (instruction.action !== 'fill') continue;
    const { path, hole } = instruction.data;
    const primitives = path.shapePath.shapePrimitives;
    primitives.forEach((primitive, i) => {
      const outline = shapeOutline(primitive.shape, primitive.transform, tolerance);
      if (!outline) return;
      // Like Pixi's own triangulation: cut() holes belong to the fill's last shape.
      const holes = (i === primitives.length - 1 && hole ? hole.shapePath.shapePrimitives : primitive.holes) ?? [];
      const rings = holes.map((h) => shapeOutline(h.shape, h.transform, tolerance)).filter((ring) => ring !== null);
      if (rings.length === 0) {
        const hull = new Hull(pairs(outline));
        if (hull.valid) {
          hulls.push(hull);
          return;
        }
      }
      for (const piece of simplePieces(outline, rings)) hulls.push(new Hull(piece));
    });
  }
  return hulls;
}

/**
 * An {@link Occluder} for a `Graphics`: hulls covering its filled shapes (see
 * {@link hullsFromGraphics}), following it. Made by {@link PenumbraLayer.addOccluder}. When the
 * Graphics is redrawn (`clear()` and new shapes) or given another context, its hulls are read
 * again at the next render.
 */
export class GraphicsOccluder extends Occluder {
  declare readonly object: Graphics;
  private readonly options: GraphicsHullsOptions;
  private context: GraphicsContext | null = null;
  private dirty = true;
  private readonly onContextUpdate = (): void => {
    this.dirty = true;
  };

  /** @internal */
  constructor(graphics: Graphics, renderer: PenumbraRenderer, options: GraphicsHullsOptions, onDestroyed: (occluder: Occluder) => void) {
    super(graphics, renderer, [], onDestroyed);
    this.options = { tolerance: options.tolerance };
    this.refresh();
  }

  /** @internal */
  override detach(): void {
    super.detach();
    this.context?.off('update', this.onContextUpdate);
    this.context = null;
  }

  protected override refresh(): void {
    const context = this.object.context;
    if (context !== this.context) {
      this.context?.off('update', this.onContextUpdate);
      context.on('update', this.onContextUpdate);
      this.context = context;
      this.dirty = true;
    }
    if (!this.dirty) return;
    this.dirty = false;
    this.setHulls(hullsFromGraphics(context, this.options));
  }
}

/** A shape's outline as flat coordinates in the Graphics' space, or `null` for a type it does not know. */
function shapeOutline(shape: ShapePrimitive, transform: Matrix | undefined, tolerance: number): number[] | null {
  let coords: number[];
  switch (shape.type) {
    case 'rectangle': {
      const { x, y, width, height } = shape as Rectangle;
      coords = [x, y, x + width, y, x + width, y + height, x, y + height];
      break;
    }
    case 'circle': {
      const { x, y, radius } = shape as Circle;
      coords = ellipse(x, y, radius, radius, tolerance);
      break;
    }
    case 'ellipse': {
      const { x, y, halfWidth, halfHeight } = shape as Ellipse;
      coords = ellipse(x, y, halfWidth, halfHeight, tolerance);
      break;
    }
    case 'roundedRectangle':
      coords = roundedRectangle(shape as RoundedRectangle, tolerance);
      break;
    case 'polygon':
      coords = Array.from((shape as Polygon).points);
      break;
    case 'triangle': {
      const { x, y, x2, y2, x3, y3 } = shape as Triangle;
      coords = [x, y, x2, y2, x3, y3];
      break;
    }
    default:
      return null;
  }
  if (transform && !transform.isIdentity()) {
    const { a, b, c, d, tx, ty } = transform;
    for (let i = 0; i < coords.length; i += 2) {
      const x = coords[i], y = coords[i + 1];
      coords[i] = a * x + c * y + tx;
      coords[i + 1] = b * x + d * y + ty;
    }
  }
  return withoutRepeats(coords);
}

/**
 * Segments for an arc of `radius` turning `angle` radians with every chord within `tolerance` of
 * the arc: a chord spanning δ lies r·(1 − cos(δ/2)) inside it at most.
 */
function arcSegments(radius: number, angle: number, tolerance: number): number {
  if (radius <= tolerance) return 1;
  const step = 2 * Math.acos(1 - tolerance / radius);
  return Math.max(1, Math.ceil(angle / step - 1e-9));
}

/**
 * Points on an axis-aligned ellipse. Its chords are within `tolerance` of it: they are those of
 * the circle of the larger radius squeezed along one axis, which brings no point farther apart.
 */
function ellipse(cx: number, cy: number, rx: number, ry: number, tolerance: number): number[] {
  const n = Math.max(3, arcSegments(Math.max(Math.abs(rx), Math.abs(ry)), 2 * Math.PI, tolerance));
  const coords: number[] = [];
  for (let i = 0; i < n; i++) {
    const angle = (2 * Math.PI * i) / n;
    coords.push(cx + rx * Math.cos(angle), cy + ry * Math.sin(angle));
  }
  return coords;
}

/** A rounded rectangle with its radius limited as Pixi draws it (half the shorter side at most). */
function roundedRectangle({ x, y, width, height, radius }: RoundedRectangle, tolerance: number): number[] {
  const r = Math.max(0, Math.min(radius, Math.min(Math.abs(width), Math.abs(height)) / 2));
  if (r === 0) return [x, y, x + width, y, x + width, y + height, x, y + height];
  const n = arcSegments(r, Math.PI / 2, tolerance);
  const corners = [[x + width - r, y + r], [x + width - r, y + height - r], [x + r, y + height - r], [x + r, y + r]];
  const coords: number[] = [];
  corners.forEach(([cx, cy], corner) => {
    // Clockwise on screen (y down): the top-right corner turns from −90° to 0°, and so on.
    const start = -Math.PI / 2 + (corner * Math.PI) / 2;
    for (let i = 0; i <= n; i++) {
      const angle = start + (i / n) * (Math.PI / 2);
      coords.push(cx + r * Math.cos(angle), cy + r * Math.sin(angle));
    }
  });
  return coords;
}

/** Drops points equal to the one before them, and a last point equal to the first. */
function withoutRepeats(coords: number[]): number[] {
  const out: number[] = [];
  for (let i = 0; i < coords.length; i += 2) {
    const n = out.length;
    if (n >= 2 && out[n - 2] === coords[i] && out[n - 1] === coords[i + 1]) continue;
    out.push(coords[i], coords[i + 1]);
  }
  while (out.length >= 4 && out[0] === out[out.length - 2] && out[1] === out[out.length - 1]) out.length -= 2;
  return out;
}

function pairs(coords: readonly number[]): [number, number][] {
  const points: [number, number][] = [];
  for (let i = 0; i < coords.length; i += 2) points.push([coords[i], coords[i + 1]]);
  return points;
}

/**
 * Simple polygons covering an outline minus its holes (or a self-crossing outline, filled as Pixi
 * fills it): earcut's triangles, then merged greedily across shared edges as long as a piece's
 * outline never visits a point twice, so a ring around a hole ends as a few pieces that meet
 * exactly along the cuts.
 */
function simplePieces(outline: readonly number[], holes: readonly (readonly number[])[]): [number, number][][] {
  const coords = [...outline];
  const holeStarts: number[] = [];
  for (const ring of holes) {
    holeStarts.push(coords.length / 2);
    coords.push(...ring);
  }
  const triangles = earcut(coords, holeStarts, 2);
  const pieces: (number[] | null)[] = [];
  for (let i = 0; i < triangles.length; i += 3) {
    const [p, q, r] = [triangles[i], triangles[i + 1], triangles[i + 2]];
    const area = (coords[2 * q] - coords[2 * p]) * (coords[2 * r + 1] - coords[2 * p + 1])
      - (coords[2 * r] - coords[2 * p]) * (coords[2 * q + 1] - coords[2 * p + 1]);
    if (area === 0) continue;
    pieces.push(area > 0 ? [p, q, r] : [p, r, q]);
  }
  // owner.get(u * n + v): the piece whose outline runs u → v.
  const n = coords.length / 2;
  const owner = new Map<number, number>();
  const own = (piece: number[], id: number) => piece.forEach((u, k) => owner.set(u * n + piece[(k + 1) % piece.length], id));
  pieces.forEach((piece, id) => own(piece!, id));
  for (let id = 0; id < pieces.length; id++) {
    let merged = true;
    while (merged) {
      merged = false;
      const piece = pieces[id];
      if (!piece) break;
      for (let k = 0; k < piece.length && !merged; k++) {
        const u = piece[k], v = piece[(k + 1) % piece.length];
        const other = owner.get(v * n + u);
        if (other === undefined || other === id || !pieces[other]) continue;
        const joined = join(piece, k, pieces[other], u);
        if (!joined) continue;
        pieces[id] = joined;
        pieces[other] = null;
        own(joined, id);
        merged = true;
      }
    }
  }
  return pieces.filter((piece) => piece !== null).map((piece) => piece.map((i) => [coords[2 * i], coords[2 * i + 1]] as [number, number]));
}

/**
 * `a` (with edge `a[k] → a[k + 1]`) and `b` (which runs that edge backwards) as one outline
 * without the edge, or `null` when the result would visit a point twice.
 */
function join(a: readonly number[], k: number, b: readonly number[], u: number): number[] | null {
  const out: number[] = [];
  for (let i = 1; i <= a.length; i++) out.push(a[(k + i) % a.length]); // v … u
  const start = b.indexOf(u);
  for (let i = 1; i < b.length - 1; i++) out.push(b[(start + i) % b.length]); // after u, up to before v
  return new Set(out).size === out.length ? out : null;
}
