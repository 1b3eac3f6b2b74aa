import { Point, type Container, type Polygon } from 'pixi.js';
import { Hull, type HullOptions } from '../../index';

const corner = new Point();

/**
 * A hull covering a display object's local bounds (e.g. a wall sprite), as the rectangle they
 * make in `space`: the container the lights and hulls live in (the layer's camera), or the
 * stage when omitted. Rotation and scale of the object are kept, so a rotated sprite gives a
 * rotated rectangle. The hull is a snapshot: call again, or move the hull, when the object moves.
 */
export function hullFromBounds(object: Container, space?: Container): Hull {
  const bounds = object.getLocalBounds();
  const xs = [bounds.minX, bounds.maxX, bounds.maxX, bounds.minX];
  const ys = [bounds.minY, bounds.minY, bounds.maxY, bounds.maxY];
  const points: [number, number][] = [];
  for (let i = 0; i < 4; i++) {
    corner.set(xs[i], ys[i]);
    object.toGlobal(corner, corner);
    if (space) space.toLocal(corner, undefined, corner);
    points.push([corner.x, corner.y]);
  }
  return new Hull(points);
}

/**
 * A hull from a Pixi `Polygon`, or from a flat `[x0, y0, x1, y1, …]` list, in either winding.
 * `options` place it in the world as for `new Hull`.
 */
export function hullFromPolygon(polygon: Polygon | readonly number[], options?: HullOptions): Hull {
  const flat: readonly number[] = Array.isArray(polygon) ? polygon as readonly number[] : (polygon as Polygon).points;
  const points: [number, number][] = [];
  for (let i = 0; i + 1 < flat.length; i += 2) points.push([flat[i], flat[i + 1]]);
  return new Hull(points, options);
}
