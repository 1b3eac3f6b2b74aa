import { Hull, Spotlight, type Light } from 'penumbra-gl';
import { hullWorldPoint } from './hullShape';
import type { Playground } from './Playground';

/** Outline of a hull the selected light passes through. */
const IGNORED_HULL_COLOR = '#ff9a3d';
/** Above this many hulls only the selected one is outlined, so the stress scene stays fast. */
const MAX_OUTLINED_HULLS = 400;
/** Radius in CSS pixels of a light's handle (also its pick radius). */
export const LIGHT_HANDLE_RADIUS = 9;

/**
 * The editing gizmos, drawn unlit on a 2D canvas over the WebGL canvas: light handles, hull
 * outlines (invalid hulls dashed red, as the renderer ignores them), the selection, the hulls the
 * selected light ignores (orange), and the hull being drawn.
 */
export class Overlay {
  private readonly g: CanvasRenderingContext2D;
  private readonly point: [number, number] = [0, 0];

  constructor(readonly canvas: HTMLCanvasElement, private readonly playground: Playground) {
    this.g = canvas.getContext('2d')!;
  }

  /** Draws the gizmos; `draft` is the hull being drawn, in world points, and whether it is valid. */
  draw(dpr: number, draft: readonly (readonly [number, number])[], draftValid: boolean): void {
    const { g, canvas, playground } = this;
    g.setTransform(1, 0, 0, 1, 0, 0);
    g.clearRect(0, 0, canvas.width, canvas.height);
    g.setTransform(dpr, 0, 0, dpr, 0, 0);
    const { hulls, lights } = playground.renderer;
    const selected = playground.selection;
    g.lineWidth = 1.5;
    for (const hull of hulls) {
      if (hull === selected || hull.valid && hulls.length > MAX_OUTLINED_HULLS) continue;
      this.outlineHull(hull, hull.valid ? 'rgba(255, 255, 255, 0.25)' : '#ff4d4d');
    }
    if (selected instanceof Hull) this.outlineHull(selected, selected.valid ? '#ffd34d' : '#ff4d4d');
    else if (selected) for (const hull of selected.ignoredHulls) this.outlineHull(hull, IGNORED_HULL_COLOR);
    if (lights.length <= MAX_OUTLINED_HULLS) for (const light of lights) this.drawLight(light, light === selected);
    else if (selected && !(selected instanceof Hull)) this.drawLight(selected, true);
    if (draft.length > 0) this.drawDraft(draft, draftValid);
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
    g.closePath();
    g.stroke();
    g.setLineDash([]);
    if (!hull.valid) {
      g.fillStyle = '#ff4d4d';
      g.font = '12px system-ui, sans-serif';
      g.fillText('invalid hull', point[0] + 6, point[1] - 6);
    }
  }

  private drawLight(light: Light, selected: boolean): void {
    const { g, point } = this;
    const camera = this.playground.camera;
    camera.worldToScreen(light.position[0], light.position[1], point);
    const [x, y] = point;
    const [r, gr, b] = light.color;
    g.fillStyle = `rgb(${Math.min(255, r * 255)}, ${Math.min(255, gr * 255)}, ${Math.min(255, b * 255)})`;
    g.strokeStyle = selected ? '#ffd34d' : 'rgba(0, 0, 0, 0.7)';
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
