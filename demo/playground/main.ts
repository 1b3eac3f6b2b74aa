import { writeScene } from 'penumbra-gl';
import { Editor } from './Editor';
import { acceptDroppedFiles, downloadText, pickImageFile, pickTextFile, storedScene, storeScene } from './files';
import { ImageTracer } from './ImageTracer';
import { Overlay } from './Overlay';
import { Panel } from './Panel';
import { Playground } from './Playground';
import { PRESETS } from './presets';
import { StatsOverlay } from './StatsOverlay';
import { installTestHook } from './testHook';
import { TilePainter } from './TilePainter';

/** Edits are kept for the next visit at most this often (the stress scene is a large file). */
const STORE_INTERVAL_MS = 1000;

const view = document.getElementById('view') as HTMLCanvasElement;
const gizmos = document.getElementById('gizmos') as HTMLCanvasElement;
const message = document.getElementById('message') as HTMLElement;
const gl = view.getContext('webgl2', { antialias: false, alpha: false });
if (!gl) throw new Error('playground: this browser has no WebGL2');

const playground = new Playground(gl);
const editor = new Editor(gizmos, playground, new TilePainter(playground));
const overlay = new Overlay(gizmos, playground);
const stats = new StatsOverlay(document.getElementById('stats') as HTMLElement);

function showError(text: string): void {
  message.textContent = text;
  message.hidden = false;
}
message.addEventListener('click', () => { message.hidden = true; });
const tracer = new ImageTracer(playground, showError);

/** Traces an image file into hulls centred on a canvas point (CSS pixels); resolves when done. */
function traceImage(file: File, x: number, y: number): Promise<void> {
  const [wx, wy] = playground.camera.screenToWorld(x, y, [0, 0]);
  return tracer.trace(file, wx, wy);
}
/** The canvas point at the centre of the view's free part (left of the panel). */
function viewCentre(): [number, number] {
  return playground.camera.worldToScreen(playground.camera.center[0], playground.camera.center[1], [0, 0]);
}

/**
 * Loads a scene file's text; on a bad file shows the error (naming the bad field) and keeps the
 * scene. The preset menu then shows `label` (the file's name) instead of the preset it replaced.
 */
function loadText(text: string, source: string, label = source): boolean {
  try {
    playground.load(text);
    message.hidden = true;
    panel.showPreset(label);
    return true;
  } catch (error) {
    showError(`Could not load ${source}: ${(error as Error).message}`);
    return false;
  }
}

function selectPreset(name: string): void {
  const preset = PRESETS[name];
  if (!preset) throw new Error(`playground: no preset named ${name}`);
  playground.load(preset());
  panel.showPreset(name);
}

const panel = new Panel(playground, editor, tracer, {
  selectPreset,
  save: () => {
    downloadText(writeScene(playground.document()), 'scene.penumbra.json');
    if (playground.hasTracedImages) showError('Saved. The file keeps the hulls traced from images, not the images drawn under them.');
  },
  load: () => pickTextFile((text, name) => loadText(text, name, `file: ${name}`)),
  pickImage: () => pickImageFile((file) => void traceImage(file, ...viewCentre())),
  showError,
});
acceptDroppedFiles(document.body, {
  text: (text, name) => loadText(text, name, `file: ${name}`),
  image: (file, clientX, clientY) => {
    const bounds = gizmos.getBoundingClientRect();
    void traceImage(file, clientX - bounds.left, clientY - bounds.top);
  },
});

// Keep the scene across reloads: edits mark it dirty, a timer writes it, leaving the page flushes it.
let unsaved = false;
playground.addEventListener('scene', () => { unsaved = true; });
function keepScene(): void {
  if (!unsaved) return;
  unsaved = false;
  storeScene(writeScene(playground.document()));
}
setInterval(keepScene, STORE_INTERVAL_MS);
window.addEventListener('pagehide', keepScene);

const stored = storedScene();
if (stored === null || !loadText(stored, 'the scene kept from the last visit', 'your last scene')) selectPreset(Object.keys(PRESETS)[0]);

/** Matches both canvases' drawing buffers to their CSS size × devicePixelRatio. */
function fitCanvases(): number {
  const dpr = window.devicePixelRatio || 1;
  const width = Math.max(1, Math.round(view.clientWidth * dpr));
  const height = Math.max(1, Math.round(view.clientHeight * dpr));
  playground.camera.width = view.clientWidth || 1;
  playground.camera.height = view.clientHeight || 1;
  if (view.width !== width || view.height !== height) {
    view.width = gizmos.width = width;
    view.height = gizmos.height = height;
    playground.renderer.resize(width, height);
  }
  return dpr;
}

let last = performance.now();
/** Draws one frame; `now` in milliseconds. */
function frame(now: number): void {
  const dt = Math.min(0.1, Math.max(0, (now - last) / 1000));
  last = now;
  const dpr = fitCanvases();
  editor.update(dt);
  playground.frame(dt);
  const painting = editor.painting
    ? { tileSize: editor.painter.tileSize, hover: editor.hover, erasing: editor.painter.erasing }
    : null;
  overlay.draw(dpr, editor.draft, editor.draftValid, painting);
  stats.frame(now, playground.renderer.stats);
}

function loop(now: number): void {
  frame(now);
  requestAnimationFrame(loop);
}
requestAnimationFrame(loop);

installTestHook({ playground, editor, tracer, gizmos, stats, loadText, selectPreset, frame: () => frame(performance.now()), message });
