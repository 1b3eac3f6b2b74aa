import { DirectionalLight, Hull, Spotlight, type Light } from 'penumbra-gl';
import { hullWorldPoint } from './hullShape';
import type { Playground } from './Playground';
import { COMPASS_RADIUS, compassCentre, forEachSun } from './sunCompass';

/** Outline of a hull the selected light passes through. */
const IGNORED_HULL_COLOR = '#ff9a3d';
/** Above this many hulls only the selected one is outlined, so the stress scene stays fast. */
const MAX_OUTLINED_HULLS = 400;
/** Radius in CSS pixels of a light's handle (also its pick radius). */
export const LIGHT_HANDLE_RADIUS = 9;
/** The tile grid is drawn only while its tiles are at least this many CSS pixels wide. */
const MIN_GRID_SPACING = 6;
/** The faint tile grid of tile mode. */
const GRID_COLOR = 'rgba(255, 255, 255, 0.12)';
/** Outline of the selected light or hull. */
const SELECTED_COLOR = '#ffd34d';

/** A light's linear colour as a CSS colour, channels above 1 shown as 1. */
function cssColor([r, g, b]: readonly number[]): string {
  return `rgb(${Math.min(255, r * 255)}, ${Math.min(255, g * 255)}, ${Math.min(255, b * 255)})`;
}

/** What tile mode shows: the grid of `tileSize` world units, the tile under the pointer, and whether a stroke erases. */
interface PaintGuide {
  tileSize: number;
  hover: readonly [number, number] | null;
  erasing: boolean;
}

/**
 * The editing gizmos, drawn unlit on a 2D canvas over the WebGL canvas: light handles, the suns'
 * compasses, outlines of the hulls no art draws (invalid hulls dashed red, as the renderer ignores
 * them; open hulls unclosed), the selection, the hulls the
 * selected light ignores (orange), the hull being drawn, and in tile mode the faint grid and the
 * tile under the pointer.
 */
export class Overlay {
  private readonly g: CanvasRenderingContext2D;
  private readonly point: [number, number] = [0, 0];
  private readonly view = new Float32Array(4);

  constructor(readonly canvas: HTMLCanvasElement, private readonly playground: Playground) {
    this.g = canvas.getContext('2d')!;
  }

  /**
   * Draws the gizmos; `draft` is the hull being drawn, in world points, and whether it is valid;
   * `paint` is tile mode's guide, null outside it.
   */
  draw(dpr: number, draft: readonly (readonly [number, number])[], draftValid: boolean, paint: PaintGuide | null = null): void {
    const { g, canvas, playground } = this;
    g.setTransform(1, 0, 0, 1, 0, 0);
    g.clearRect(0, 0, canvas.width, canvas.height);
    g.setTransform(dpr, 0, 0, dpr, 0, 0);
    if (paint) this.drawGrid(paint);
    const { hulls, lights } = playground.renderer;
    const selected = playground.selection;
    g.lineWidth = 1.5;
    // The showcase's art shows the level's hulls: an outline over it would read as a rim of light along every wall.
    const drawnByArt = (hull: Hull) => playground.showcaseActive && playground.showcase.draws(hull);
    for (const hull of hulls) {
      if (hull === selected || drawnByArt(hull) || hull.valid && hulls.length > MAX_OUTLINED_HULLS) continue;
      this.outlineHull(hull, hull.valid ? 'rgba(255, 255, 255, 0.25)' : '#ff4d4d');
    }
    if (selected instanceof Hull) this.outlineHull(selected, selected.valid ? SELECTED_COLOR : '#ff4d4d');
    else if (selected) for (const hull of selected.ignoredHulls) this.outlineHull(hull, IGNORED_HULL_COLOR);
    if (lights.length <= MAX_OUTLINED_HULLS) for (const light of lights) this.drawLight(light, light === selected);
    else if (selected && !(selected instanceof Hull)) this.drawLight(selected, true);
    // Few and fixed on the view: always drawn.
    forEachSun(lights, (sun, index) => this.drawCompass(sun, index, sun === selected));
    if (draft.length > 0) this.drawDraft(draft, draftValid);
  }

  /** The world-aligned grid lines across the view, and the tile under the pointer. */
  private drawGrid({ tileSize, hover, erasing }: PaintGuide): void {
    const { g, point } = this;
    const camera = this.playground.camera;
    const [x0, y0, x1, y1] = camera.visibleWorld(this.view);
    if (tileSize * camera.zoom >= MIN_GRID_SPACING) {
      g.strokeStyle = GRID_COLOR;
      g.lineWidth = 1;
      g.beginPath();
      for (let x = Math.ceil(x0 / tileSize) * tileSize; x <= x1; x += tileSize) {
        // Half-pixel offsets keep the 1-pixel lines crisp.
        const sx = Math.round(camera.worldToScreen(x, 0, point)[0]) + 0.5;
        g.moveTo(sx, 0);
        g.lineTo(sx, camera.height);
      }
      for (let y = Math.ceil(y0 / tileSize) * tileSize; y <= y1; y += tileSize) {
        const sy = Math.round(camera.worldToScreen(0, y, point)[1]) + 0.5;
        g.moveTo(0, sy);
        g.lineTo(camera.width, sy);
      }
      g.stroke();
    }
    if (hover) {
      const tx = Math.floor(hover[0] / tileSize) * tileSize, ty = Math.floor(hover[1] / tileSize) * tileSize;
      const [sx, sy] = camera.worldToScreen(tx, ty, point);
      g.strokeStyle = erasing ? '#ff4d4d' : '#6dff8a';
      g.lineWidth = 1.5;
      g.strokeRect(sx, sy, tileSize * camera.zoom, tileSize * camera.zoom);
    }
  }

  private outlineHull(hull: Hull, color: string): void {
    const { g, point } = this;
    const n = hull.points.length;
    if (n === 0) return;
    g.strokeStyle = color;
    g.setLineDash(hull.valid ? [] : [6, 4]);
    g.beginPath();
    for (let i = 0; i < n; i++) {
      hullWorldPoint(hull, i, point);
      this.playground.camera.worldToScreen(point[0], point[1], point);
      if (i === 0) g.moveTo(point[0], point[1]);
      else g.lineTo(point[0], point[1]);
    }
    if (hull.closed) g.closePath();
    g.stroke();
    g.setLineDash([]);
    if (!hull.valid) {
      g.fillStyle = '#ff4d4d';
      g.font = '12px system-ui, sans-serif';
      g.fillText('invalid hull', point[0] + 6, point[1] - 6);
    }
  }

  /** A light's handle at its position; none for a sun, which has no position (its compass stands for it). */
  private drawLight(light: Light, selected: boolean): void {
    if (light instanceof DirectionalLight) return;
    const { g, point } = this;
    const camera = this.playground.camera;
    camera.worldToScreen(light.position[0], light.position[1], point);
    const [x, y] = point;
    g.fillStyle = cssColor(light.color);
    g.strokeStyle = selected ? SELECTED_COLOR : 'rgba(0, 0, 0, 0.7)';
    g.lineWidth = selected ? 3 : 1.5;
    g.beginPath();
    g.arc(x, y, LIGHT_HANDLE_RADIUS, 0, Math.PI * 2);
    g.fill();
    g.stroke();
    if (light instanceof Spotlight || selected) {
      g.beginPath();
      g.moveTo(x, y);
      g.lineTo(x + Math.cos(light.rotation) * 30, y + Math.sin(light.rotation) * 30);
      g.stroke();
    }
    if (selected) {
      g.setLineDash([4, 6]);
      g.lineWidth = 1;
      g.beginPath();
      g.arc(x, y, light.range * camera.zoom, 0, Math.PI * 2);
      const radius = Math.max(1, light.radius * camera.zoom);
      g.moveTo(x + radius, y);
      g.arc(x, y, radius, 0, Math.PI * 2);
      g.stroke();
      g.setLineDash([]);
    }
  }

  /**
   * Sun `index`'s compass: a ring with the sun, in its colour, on the side its light comes from,
   * and an arrow across to the side it travels to, where shadows fall.
   */
  private drawCompass(sun: DirectionalLight, index: number, selected: boolean): void {
    const { g, point } = this;
    const [x, y] = compassCentre(index, this.playground.camera.height, point);
    const dx = Math.cos(sun.rotation) * COMPASS_RADIUS, dy = Math.sin(sun.rotation) * COMPASS_RADIUS;
    g.fillStyle = 'rgba(0, 0, 0, 0.55)';
    g.strokeStyle = selected ? SELECTED_COLOR : 'rgba(255, 255, 255, 0.7)';
    g.lineWidth = selected ? 3 : 1.5;
    g.beginPath();
    g.arc(x, y, COMPASS_RADIUS, 0, Math.PI * 2);
    g.fill();
    g.stroke();
    // The arrow, from the sun's side to the head at the rim.
    const headX = x + dx * 0.8, headY = y + dy * 0.8;
    g.strokeStyle = '#fff';
    g.lineWidth = 2;
    g.beginPath();
    g.moveTo(x - dx * 0.5, y - dy * 0.5);
    g.lineTo(headX, headY);
    g.moveTo(headX - dx * 0.35 - dy * 0.25, headY - dy * 0.35 + dx * 0.25);
    g.lineTo(headX, headY);
    g.lineTo(headX - dx * 0.35 + dy * 0.25, headY - dy * 0.35 - dx * 0.25);
    g.stroke();
    g.fillStyle = cssColor(sun.color);
    g.beginPath();
    g.arc(x - dx * 0.7, y - dy * 0.7, COMPASS_RADIUS * 0.22, 0, Math.PI * 2);
    g.fill();
  }

  private drawDraft(draft: readonly (readonly [number, number])[], valid: boolean): void {
    const { g, point } = this;
    g.strokeStyle = g.fillStyle = valid ? '#6dff8a' : '#ff4d4d';
    g.lineWidth = 2;
    g.beginPath();
    draft.forEach(([wx, wy], i) => {
      this.playground.camera.worldToScreen(wx, wy, point);
      if (i === 0) g.moveTo(point[0], point[1]);
      else g.lineTo(point[0], point[1]);
    });
    g.closePath();
    g.stroke();
    for (const [wx, wy] of draft) {
      this.playground.camera.worldToScreen(wx, wy, point);
      g.fillRect(point[0] - 3, point[1] - 3, 6, 6);
    }
  }
}
