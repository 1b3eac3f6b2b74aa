// What test/browser/pixiOccluders.test.ts checks in the page beside pixels: a Graphics' hulls
// against Pixi's own idea of its shapes, and the occluders' life cycle. Not part of the example.
import { Container, Graphics, Point, type Application } from 'pixi.js';
import type { Hull, PenumbraLayer } from 'penumbra-gl/pixi';

/** A transform for the checked Graphics (inside a turned, scaled parent in the world). */
export interface Placement {
  x: number;
  y: number;
  rotation: number;
  scaleX: number;
  scaleY: number;
  skewX?: number;
}

/** One placement's result, in the camera's (world container's) space. */
export interface GraphicsReport {
  /** Each enabled hull's outline, `[x0, y0, x1, y1, …]`. */
  hulls: number[][];
  /** Samples of the Graphics' local bounds: camera-space x, y, and 1 where Pixi's `containsPoint` is true. */
  samples: number[];
  /** Local → camera-space linear map `[a, b, c, d]`: how far a local unit may stretch. */
  linear: [number, number, number, number];
}

/** The occluder of a Graphics through its life: each field true when it held. */
interface LifecycleReport {
  addedToRenderer: boolean;
  disabledWhenRemoved: boolean;
  enabledWhenAddedBack: boolean;
  replacedWhenRedrawn: boolean;
  goneWhenDestroyed: boolean;
}

/** `window.penumbraPixiOccluders`. */
interface OccluderCheckHook {
  /** Draws the checked shapes, places them with each placement in turn and reports the hulls and samples. */
  graphics(placements: Placement[], tolerance: number): GraphicsReport[];
  /** Adds, removes, re-adds, redraws and destroys a Graphics occluder. */
  lifecycle(): LifecycleReport;
  /** Whether the still prop's hulls keep their very placement objects while the camera pans from `from` to `to`. */
  stillWhilePanning(from: [number, number], to: [number, number]): boolean;
  /** After a render: every occluder's enabled hulls, `[x0, y0, x1, y1, …]` each, in the camera's space. */
  occluderOutlines(): number[][];
}

declare global {
  interface Window {
    penumbraPixiOccluders?: OccluderCheckHook;
  }
}

/** The checked shapes: each kind the Graphics hulls read, a hole, and a shape drawn under a context transform. */
function drawShapes(g: Graphics): Graphics {
  return g
    .rect(0, 0, 60, 40).fill(0x6a8caf).circle(30, 20, 10).cut()
    .roundRect(70, 0, 50, 40, 12).fill(0x6a8caf)
    .circle(25, 75, 22).fill(0x6a8caf)
    .ellipse(90, 75, 28, 14).fill(0x6a8caf)
    .poly([130, 0, 170, 20, 150, 30, 170, 60, 130, 50]).fill(0x6a8caf)
    .star(150, 90, 5, 20, 9).fill(0x6a8caf)
    .translateTransform(210, 40).rotateTransform(0.5).rect(-15, -10, 30, 20).fill(0x6a8caf).resetTransform();
}

function outline(hull: Hull): number[] {
  const [px, py] = hull.position, [ox, oy] = hull.origin, [sx, sy] = hull.scale;
  const cos = Math.cos(hull.rotation), sin = Math.sin(hull.rotation);
  return hull.points.flatMap(([x, y]) => {
    const lx = (x - ox) * sx, ly = (y - oy) * sy;
    return [px + lx * cos - ly * sin, py + lx * sin + ly * cos];
  });
}

export function exposeOccluderCheck(app: Application, world: Container, lighting: PenumbraLayer, setPlayer: (x: number, y: number) => void): void {
  const toCamera = (object: Container, x: number, y: number) => world.toLocal(object.toGlobal(new Point(x, y)));
  const inRenderer = (hull: Hull) => lighting.penumbra.hulls.includes(hull);

  window.penumbraPixiOccluders = {
    graphics(placements, tolerance) {
      const holder = world.addChild(new Container({ position: { x: 40, y: 460 }, rotation: 0.1, scale: 0.9, pivot: { x: 5, y: 5 } }));
      const graphics = holder.addChild(drawShapes(new Graphics()));
      const occluder = lighting.addOccluder(graphics, { tolerance });
      const reports = placements.map(({ x, y, rotation, scaleX, scaleY, skewX = 0 }) => {
        graphics.position.set(x, y);
        graphics.rotation = rotation;
        graphics.scale.set(scaleX, scaleY);
        graphics.skew.set(skewX, 0);
        app.render();
        const samples: number[] = [];
        for (let ly = -5; ly <= 115; ly += 1.7) {
          for (let lx = -5; lx <= 235; lx += 1.7) {
            const point = toCamera(graphics, lx, ly);
            samples.push(point.x, point.y, graphics.containsPoint(new Point(lx, ly)) ? 1 : 0);
          }
        }
        const origin = toCamera(graphics, 0, 0), ex = toCamera(graphics, 1, 0), ey = toCamera(graphics, 0, 1);
        return {
          hulls: occluder.hulls.filter((hull) => hull.enabled && inRenderer(hull)).map(outline),
          samples,
          linear: [ex.x - origin.x, ex.y - origin.y, ey.x - origin.x, ey.y - origin.y] as [number, number, number, number],
        };
      });
      holder.destroy({ children: true });
      return reports;
    },

    lifecycle() {
      const graphics = world.addChild(new Graphics().rect(0, 0, 30, 30).fill(0x6a8caf));
      graphics.position.set(60, 560);
      const occluder = lighting.addOccluder(graphics);
      const first = occluder.hulls;
      app.render();
      const addedToRenderer = lighting.occluders.includes(occluder) && first.length > 0 && first.every((hull) => inRenderer(hull) && hull.enabled);
      world.removeChild(graphics);
      app.render();
      const disabledWhenRemoved = first.every((hull) => !hull.enabled);
      world.addChild(graphics);
      app.render();
      const enabledWhenAddedBack = first.every((hull) => hull.enabled);
      graphics.clear().circle(15, 15, 15).fill(0x6a8caf);
      app.render();
      const second = occluder.hulls;
      const replacedWhenRedrawn = second !== first && second.length > 0 && second.every(inRenderer) && !first.some(inRenderer)
        && second[0].points.length > 4;
      graphics.destroy();
      app.render();
      const goneWhenDestroyed = !lighting.occluders.includes(occluder) && !second.some(inRenderer);
      return { addedToRenderer, disabledWhenRemoved, enabledWhenAddedBack, replacedWhenRedrawn, goneWhenDestroyed };
    },

    occluderOutlines() {
      app.render();
      return lighting.occluders.flatMap((occluder) => occluder.hulls.filter((hull) => hull.enabled && inRenderer(hull)).map(outline));
    },

    stillWhilePanning(from, to) {
      setPlayer(from[0], from[1]);
      app.render();
      const hulls = lighting.occluders.flatMap((occluder) => occluder.hulls);
      const before = hulls.map((hull) => [hull.position, hull.scale, hull.points, hull.rotation] as const);
      setPlayer(to[0], to[1]);
      app.render();
      app.render();
      return hulls.length > 0 && hulls.every((hull, i) => {
        const [position, scale, points, rotation] = before[i];
        return hull.position === position && hull.scale === scale && hull.points === points && hull.rotation === rotation;
      });
    },
  };
}
