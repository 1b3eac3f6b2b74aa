import Phaser from 'phaser';
import type { Hull } from '../../index';

/**
 * Where hulls made for a Phaser object go: {@link PenumbraPlugin} (its hulls follow the plugin's
 * current renderer, also after `configure()`), or a `PenumbraRenderer` of your own.
 */
export interface HullTarget {
  /** Starts drawing the hull's shadows. */
  addHull(hull: Hull): unknown;
  /** Stops drawing the hull's shadows. */
  removeHull(hull: Hull): unknown;
}

/** A game object's world placement: translation, rotation, scale (no skew). */
export interface Placement {
  x: number;
  y: number;
  rotation: number;
  scaleX: number;
  scaleY: number;
}

/** A game object with a transform: a sprite, an image, a tilemap layer. */
export type Placed = Phaser.GameObjects.GameObject & Phaser.GameObjects.Components.Transform;

let world: Phaser.GameObjects.Components.TransformMatrix | null = null;
let scratch: Phaser.GameObjects.Components.TransformMatrix | null = null;

/**
 * Reads where `object` is drawn into `out`, without allocating: its own fields, or, inside a
 * Container, its world matrix split into translation, rotation and scale (a container that
 * scales unevenly and rotates a child would skew it, which a hull cannot: the skew is dropped).
 * `withRotation: false` leaves the object's own rotation out (a tilemap layer does not draw it).
 */
export function readPlacement(object: Placed, withRotation: boolean, out: Placement): Placement {
  const rotation = withRotation ? object.rotation : 0;
  const container = object.parentContainer;
  if (!container) {
    out.x = object.x;
    out.y = object.y;
    out.rotation = rotation;
    out.scaleX = object.scaleX;
    out.scaleY = object.scaleY;
    return out;
  }
  world ??= new Phaser.GameObjects.Components.TransformMatrix();
  scratch ??= new Phaser.GameObjects.Components.TransformMatrix();
  const p = container.getWorldTransformMatrix(world, scratch);
  // The object's own matrix L = T(x, y) · R(rotation) · S(scaleX, scaleY), then m = P · L.
  const cos = Math.cos(rotation), sin = Math.sin(rotation);
  const la = cos * object.scaleX, lb = sin * object.scaleX, lc = -sin * object.scaleY, ld = cos * object.scaleY;
  const a = p.a * la + p.c * lb, b = p.b * la + p.d * lb;
  const c = p.a * lc + p.c * ld, d = p.b * lc + p.d * ld;
  out.x = p.a * object.x + p.c * object.y + p.tx;
  out.y = p.b * object.x + p.d * object.y + p.ty;
  // m = T · R(θ) · S(sx, sy): (a, b) is the x axis, sx its length; sy is signed (det / sx).
  const sx = Math.hypot(a, b);
  if (sx === 0) {
    out.rotation = Math.atan2(-c, d);
    out.scaleX = 0;
    out.scaleY = Math.hypot(c, d);
  } else {
    out.rotation = Math.atan2(b, a);
    out.scaleX = sx;
    out.scaleY = (a * d - b * c) / sx;
  }
  return out;
}

/** A value for an error message, cut to ~80 characters. */
export function describe(value: unknown): string {
  let text: string;
  if (typeof value === 'string') text = JSON.stringify(value);
  else if (typeof value === 'function') text = 'a function';
  else if (typeof value === 'object' && value !== null) text = value.constructor?.name ? `a ${value.constructor.name}` : 'an object';
  else text = String(value);
  return text.length > 80 ? `${text.slice(0, 77)}…` : text;
}
