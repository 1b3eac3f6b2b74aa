import type { FrameStats } from 'penumbra-gl';

/** How often the figures are refreshed, in milliseconds (often enough to read, rarely enough to be cheap). */
const REFRESH_MS = 500;

/** Figures the overlay shows, averaged over the last refresh period. */
export interface OverlayFigures {
  fps: number;
  /** Mean renderer CPU time per frame, in milliseconds. */
  cpuTime: number;
  lights: number;
  lightsDrawn: number;
  /** Lights whose shadow casters were filed anew in the last frame (the rest reused theirs). */
  lightsFiled: number;
  hulls: number;
  edges: number;
}

/** The stats overlay: fps, the renderer's CPU time per frame, lights (total, drawn, filed anew), hulls and edges. */
export class StatsOverlay {
  /** The figures last shown. */
  readonly figures: OverlayFigures = { fps: 0, cpuTime: 0, lights: 0, lightsDrawn: 0, lightsFiled: 0, hulls: 0, edges: 0 };
  private frames = 0;
  private cpuTotal = 0;
  private periodStart = performance.now();

  constructor(private readonly element: HTMLElement) {}

  /** Counts one frame with the renderer's stats of that frame. */
  frame(now: number, stats: FrameStats): void {
    this.frames++;
    this.cpuTotal += stats.cpuTime;
    const elapsed = now - this.periodStart;
    if (elapsed < REFRESH_MS) return;
    const f = this.figures;
    f.fps = (this.frames * 1000) / elapsed;
    f.cpuTime = this.cpuTotal / this.frames;
    f.lights = stats.lights;
    f.lightsDrawn = stats.lightsDrawn;
    f.lightsFiled = stats.lightsFiled;
    f.hulls = stats.hulls;
    f.edges = stats.edges;
    this.frames = 0;
    this.cpuTotal = 0;
    this.periodStart = now;
    this.element.textContent = `${f.fps.toFixed(1)} fps · renderer CPU ${f.cpuTime.toFixed(2)} ms/frame\n`
      + `lights ${f.lights} (drawn ${f.lightsDrawn}, filed ${f.lightsFiled}) · hulls ${f.hulls} · edges ${f.edges}`;
  }
}
