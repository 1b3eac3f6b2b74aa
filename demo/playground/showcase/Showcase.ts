import type { mat4 } from 'gl-matrix';
import { DirectionalLight, Hull, type Light, type PenumbraRenderer } from 'penumbra-gl';
import type { ObjectCounts, ShowcaseState } from '../appState';
import { hullLocalToWorld, hullWorldPoint } from '../hullShape';
import { ATLAS_SIZE, CELLS, FLAME_FRAMES, flameCell, floorImage, grassImage, propsImage, wallFaceImage, wallImage, type Cell } from './art';
import { buildLevel, DAY, FLOOR_TOP, LEVEL_HEIGHT, LEVEL_WIDTH, NIGHT, type Decor, type HullRole, type LightRole } from './level';
import { SurfaceBatch, type SurfaceTextures } from './SurfaceBatch';
import { hash, noise } from './surfaceImage';

/** World units per repetition of the tiling textures. */
const FLOOR_REPEAT = 256, WALL_REPEAT = 96, GRASS_REPEAT = 192;
/** Width of the contact shadow along walls, in world units. */
const WALL_SHADE = 30;
/** How far a wall's south face reaches down the view (the 3/4 view's depth), world units; and its texture's repeat across. */
const FACE = 26, FACE_REPEAT = 96;
/** Stains scattered on the floor (shadow decals), which break up the floor texture's repeats: count, from a fixed seed. */
const STAINS = 26;
/** Embers around the brazier: count, and how far out they drift. */
const EMBERS = 14, EMBER_REACH = 34;

/** How strongly each kind of light flickers (0: steady) and how fast. */
const FLICKER: Partial<Record<LightRole['kind'], { depth: number; speed: number }>> = {
  torch: { depth: 0.22, speed: 9 },
  brazier: { depth: 0.15, speed: 6 },
  lantern: { depth: 0.06, speed: 12 },
  runes: { depth: 0.25, speed: 1.2 },
};

/**
 * The playground's showcase: a game-like level under normal-mapped lights. Its art follows the
 * objects it belongs to (props their hulls, flames and sconces their lights), so dragging a
 * barrel or a torch in the editor moves its picture with its light or shadow. Torches flicker
 * (intensity and source radius), and one `daylight` value blends night (ambient dusk, a cold
 * moon through the windows) into day (warm ambient, a high sun).
 */
export class Showcase {
  private readonly batch: SurfaceBatch;
  private readonly textures: Record<'floor' | 'wall' | 'face' | 'grass' | 'props', SurfaceTextures>;
  private readonly level = buildLevel();
  /** The level's objects: each hull's and light's index in the level's roles. */
  private readonly hullRoles = new Map<Hull, number>();
  private readonly lightRoles = new Map<Light, number>();
  /** Each flickering light's steady intensity and radius, and what the flicker last set (an edit in between becomes the new steady value). */
  private readonly steady = new Map<Light, { intensity: number; radius: number; shownIntensity: number; shownRadius: number; phase: number }>();
  private renderer: PenumbraRenderer | null = null;
  private _daylight = 0;
  private time = 0;
  private readonly point: [number, number] = [0, 0];
  private readonly corner: [number, number] = [0, 0];

  constructor(gl: WebGL2RenderingContext) {
    this.batch = new SurfaceBatch(gl);
    this.textures = {
      floor: this.batch.upload(floorImage(), true),
      wall: this.batch.upload(wallImage(), true),
      face: this.batch.upload(wallFaceImage(), true),
      grass: this.batch.upload(grassImage(), true),
      props: this.batch.upload(propsImage(), false),
    };
  }

  /** How many hull and light roles the level has. */
  get roleCounts(): ObjectCounts {
    return { hulls: this.level.hullRoles.length, lights: this.level.lightRoles.length };
  }

  /**
   * Takes the renderer's hulls and lights, just loaded, as the level's: by `saved`, the state a
   * saved scene kept ({@link state}), or else by their order (the level's own document, at night,
   * its clock running on).
   */
  attach(renderer: PenumbraRenderer, saved: ShowcaseState | null): void {
    this.renderer = renderer;
    this.hullRoles.clear();
    this.lightRoles.clear();
    this.steady.clear();
    const byOrder = (i: number, count: number) => (i < count ? i : null);
    renderer.hulls.forEach((hull, i) => {
      const role = saved ? saved.hullRoles[i] : byOrder(i, this.level.hullRoles.length);
      if (role !== null) this.hullRoles.set(hull, role);
    });
    renderer.lights.forEach((light, i) => {
      const role = saved ? saved.lightRoles[i] : byOrder(i, this.level.lightRoles.length);
      if (role === null) return;
      this.lightRoles.set(light, role);
      if (!FLICKER[this.level.lightRoles[role].kind]) return;
      // The lights hold the values shown when the scene was saved; the flicker scales the steady ones.
      const steady = saved?.flicker.find((entry) => entry.light === i) ?? light;
      this.steady.set(light, { intensity: steady.intensity, radius: steady.radius, shownIntensity: light.intensity, shownRadius: light.radius, phase: role * 7.3 });
    });
    // The colours the slider set are the scene's own: restoring its position changes none.
    this._daylight = saved?.daylight ?? 0;
    if (saved) this.time = saved.clock;
  }

  /** What a saved scene needs besides its lights and hulls to come back drawn the same ({@link attach}). */
  state(): ShowcaseState {
    const renderer = this.renderer;
    if (!renderer) throw new Error('showcase: not attached');
    return {
      daylight: this._daylight,
      clock: this.time,
      hullRoles: renderer.hulls.map((hull) => this.hullRoles.get(hull) ?? null),
      lightRoles: renderer.lights.map((light) => this.lightRoles.get(light) ?? null),
      flicker: renderer.lights.flatMap((light, i) => {
        const s = this.steady.get(light);
        // As step() has it: a value edited since the flicker set it is the new steady one.
        return s ? [{ light: i, intensity: light.intensity === s.shownIntensity ? s.intensity : light.intensity, radius: light.radius === s.shownRadius ? s.radius : light.radius }] : [];
      }),
    };
  }

  /** The level's role of a hull of the scene, or undefined for a hull the editor added. */
  private hullRole(hull: Hull): HullRole | undefined {
    const index = this.hullRoles.get(hull);
    return index === undefined ? undefined : this.level.hullRoles[index];
  }

  /** The level's role of a light of the scene, or undefined for a light the editor added. */
  private lightRole(light: Light): LightRole | undefined {
    const index = this.lightRoles.get(light);
    return index === undefined ? undefined : this.level.lightRoles[index];
  }

  /** Forgets the level's objects (another scene was loaded). */
  detach(): void {
    this.renderer = null;
    this.hullRoles.clear();
    this.lightRoles.clear();
    this.steady.clear();
  }

  /** Whether hull `hull` is drawn by the showcase's art (others are the generic stone). */
  draws(hull: Hull): boolean {
    return this.hullRoles.has(hull);
  }

  /** 0 at night, 1 at noon. */
  get daylight(): number {
    return this._daylight;
  }
  set daylight(value: number) {
    if (!(value >= 0 && value <= 1)) throw new RangeError(`showcase daylight: expected 0..1, got ${value}`);
    this._daylight = value;
    this.applyDaylight();
  }

  /** The sky light (sun or moon), while it is in the scene. */
  private sky(): DirectionalLight | null {
    for (const light of this.lightRoles.keys()) if (this.lightRole(light)?.kind === 'sky' && light instanceof DirectionalLight && this.renderer?.lights.includes(light)) return light;
    return null;
  }

  private applyDaylight(): void {
    const renderer = this.renderer;
    if (!renderer) return;
    const t = this._daylight;
    // The light of dawn comes quickly: ease the blend.
    const day = t * t * (3 - 2 * t);
    const mix = (a: readonly number[], b: readonly number[]) => a.map((value, i) => value + (b[i] - value) * day) as [number, number, number];
    renderer.ambientColor = mix(NIGHT.ambient, DAY.ambient);
    const sky = this.sky();
    if (sky) {
      sky.color = mix(NIGHT.sky, DAY.sky);
      sky.intensity = NIGHT.skyIntensity + (DAY.skyIntensity - NIGHT.skyIntensity) * day;
      sky.elevation = NIGHT.elevation + (DAY.elevation - NIGHT.elevation) * day;
    }
  }

  /** Advances the flicker by `dt` seconds. */
  step(dt: number): void {
    this.time += dt;
    const t = this.time;
    for (const [light, s] of this.steady) {
      const role = this.lightRole(light)!;
      const { depth, speed } = FLICKER[role.kind]!;
      // An edit made since the last step becomes the steady value.
      if (light.intensity !== s.shownIntensity) s.intensity = light.intensity;
      if (light.radius !== s.shownRadius) s.radius = light.radius;
      const wobble = flicker(t * speed + s.phase);
      light.intensity = s.shownIntensity = s.intensity * (1 - depth + depth * 2 * wobble);
      light.radius = s.shownRadius = s.radius * (0.85 + 0.3 * wobble);
    }
  }

  /** The flicker of light `light` now, 0..1 (0.5 when it does not flicker). */
  private flickerOf(light: Light): number {
    const s = this.steady.get(light);
    return s ? flicker(this.time * FLICKER[this.lightRole(light)!.kind]!.speed + s.phase) : 0.5;
  }

  /**
   * Draws the level into the renderer's scene target: courtyard, floor, rug and runes, contact
   * shadows, walls, props, then flames and embers. `view` is the visible world rectangle.
   */
  draw(viewProjection: mat4, view: Float32Array, hulls: readonly Hull[], lights: readonly Light[]): void {
    const batch = this.batch;
    batch.begin(viewProjection);
    const [x0, y0, x1, y1] = view;
    // Grass around the level (not under it: SwiftShader pays for every layer), the floor inside.
    const fx0 = Math.max(x0, 0), fy0 = Math.max(y0, FLOOR_TOP), fx1 = Math.min(x1, LEVEL_WIDTH), fy1 = Math.min(y1, LEVEL_HEIGHT);
    this.tiled(x0, y0, x1, Math.min(y1, fy0), GRASS_REPEAT);
    this.tiled(x0, Math.max(y0, fy1), x1, y1, GRASS_REPEAT);
    this.tiled(x0, fy0, Math.min(x1, fx0), fy1, GRASS_REPEAT);
    this.tiled(Math.max(x0, fx1), fy0, x1, fy1, GRASS_REPEAT);
    batch.flush(this.textures.grass);
    this.tiled(fx0, fy0, fx1, fy1, FLOOR_REPEAT);
    batch.flush(this.textures.floor);

    this.stains();
    for (const decor of this.level.decor) if (decor.kind === 'rug') this.decor(decor);
    for (const light of lights) if (this.lightRole(light)?.kind === 'runes') this.sprite(CELLS.runes, light.position[0], light.position[1], 0, 1, 0.6 + 0.4 * this.flickerOf(light));
    for (const hull of hulls) {
      const role = this.hullRole(hull);
      if (role === 'wall' && hull.enabled) this.wallShade(hull);
      else if (role && role !== 'bar' && hull.enabled) this.blob(hull, role);
    }
    batch.flush(this.textures.props);

    for (const hull of hulls) if (this.hullRole(hull) === 'wall' && hull.enabled) this.wallFaces(hull);
    batch.flush(this.textures.face);
    for (const hull of hulls) if (this.hullRole(hull) === 'wall' && hull.enabled) this.wall(hull);
    batch.flush(this.textures.wall);

    for (const hull of hulls) {
      const role = this.hullRole(hull);
      if (role && role !== 'wall' && hull.enabled) this.prop(hull, role);
    }
    for (const decor of this.level.decor) if (decor.kind !== 'rug') this.decor(decor);
    for (const light of lights) {
      const role = this.lightRole(light);
      if (!role) continue;
      const [x, y] = light.position;
      if (role.kind === 'brazier') this.sprite(CELLS.brazier, x, y, 0);
      else if (role.kind === 'lantern') this.sprite(CELLS.lantern, x, y, 0);
      else if (role.kind === 'torch') {
        // The sconce's bracket reaches back to the wall.
        this.sprite(CELLS.sconce, x + Math.cos(role.facing) * 4, y + Math.sin(role.facing) * 4, role.facing + Math.PI / 2, 1.5);
      }
    }
    for (const light of lights) {
      const role = this.lightRole(light);
      if (role?.kind === 'brazier') this.embers(light);
    }
    for (const light of lights) {
      const role = this.lightRole(light);
      if (role?.kind === 'torch' || role?.kind === 'brazier') this.flame(light, role.kind === 'brazier' ? 1.9 : 1);
    }
    batch.flush(this.textures.props);
    batch.end();
  }

  dispose(): void {
    this.batch.dispose();
  }

  /** The rectangle (x0, y0)–(x1, y1) with a tiling texture repeating every `repeat` world units, fixed to the world. */
  private tiled(x0: number, y0: number, x1: number, y1: number, repeat: number): void {
    if (x1 <= x0 || y1 <= y0) return;
    this.batch.quad(x0, y0, x1 - x0, 0, 0, y1 - y0, x0 / repeat, y0 / repeat, (x1 - x0) / repeat, (y1 - y0) / repeat, 1, 0);
  }

  /**
   * An atlas cell centred on (x, y), turned by `rotation`, at `scale` world units per pixel
   * (1: the cell's own size), with `opacity`; `decal`: a shadow.
   */
  private sprite(cell: Cell, x: number, y: number, rotation: number, scale = 1, opacity = 1, decal = false): void {
    const cos = Math.cos(rotation), sin = Math.sin(rotation);
    const w = cell.w * scale, h = cell.h * scale;
    const ax = cos * w, ay = sin * w, bx = -sin * h, by = cos * h;
    this.batch.quad(x - (ax + bx) / 2, y - (ay + by) / 2, ax, ay, bx, by,
      cell.x / ATLAS_SIZE, cell.y / ATLAS_SIZE, cell.w / ATLAS_SIZE, cell.h / ATLAS_SIZE, cos, sin, opacity, decal);
  }

  /** A wall hull's top: its four corners with the wall texture fixed to the world (adjacent walls line up). */
  private wall(hull: Hull): void {
    if (hull.points.length !== 4) return;
    const p0 = hullWorldPoint(hull, 0, [0, 0]), p1 = hullWorldPoint(hull, 1, [0, 0]), p3 = hullWorldPoint(hull, 3, [0, 0]);
    const cos = Math.cos(hull.rotation), sin = Math.sin(hull.rotation);
    this.batch.quad(p0[0], p0[1], p1[0] - p0[0], p1[1] - p0[1], p3[0] - p0[0], p3[1] - p0[1],
      p0[0] / WALL_REPEAT, p0[1] / WALL_REPEAT, (p1[0] - p0[0]) / WALL_REPEAT, (p3[1] - p0[1]) / WALL_REPEAT, cos, sin);
  }

  /**
   * Calls `side` with each side of a hull (world points a → b) and its outward unit normal.
   * Allocates nothing: the points are scratch arrays, valid during the call.
   */
  private eachSide(hull: Hull, side: (ax: number, ay: number, bx: number, by: number, nx: number, ny: number) => void): void {
    const n = hull.points.length;
    let cx = 0, cy = 0;
    for (let i = 0; i < n; i++) {
      const [x, y] = hullWorldPoint(hull, i, this.point);
      cx += x / n;
      cy += y / n;
    }
    for (let i = 0; i < n; i++) {
      const [ax, ay] = hullWorldPoint(hull, i, this.point);
      const [bx, by] = hullWorldPoint(hull, (i + 1) % n, this.corner);
      const length = Math.hypot(bx - ax, by - ay);
      if (length === 0) continue;
      let nx = -(by - ay) / length, ny = (bx - ax) / length;
      if (nx * ((ax + bx) / 2 - cx) + ny * ((ay + by) / 2 - cy) < 0) {
        nx = -nx;
        ny = -ny;
      }
      side(ax, ay, bx, by, nx, ny);
    }
  }

  /** Whether a side with outward normal (nx, ny) shows its face: it faces down the view. */
  private static facesViewer(ny: number): boolean {
    return ny > 0.7;
  }

  /** A soft shadow on the floor along each side of a wall hull, darkest against the wall (below the face of a side that shows one). */
  private wallShade(hull: Hull): void {
    const { x: u, y: v, w, h } = CELLS.edge;
    this.eachSide(hull, (ax, ay, bx, by, nx, ny) => {
      const offset = Showcase.facesViewer(ny) ? FACE : 0;
      this.batch.quad(ax + nx * offset, ay + ny * offset, bx - ax, by - ay, nx * WALL_SHADE, ny * WALL_SHADE,
        (u + 2) / ATLAS_SIZE, v / ATLAS_SIZE, (w - 4) / ATLAS_SIZE, h / ATLAS_SIZE, 1, 0, 1, true);
    });
  }

  /**
   * The brick face below each side of a wall that faces down the view, {@link FACE} deep: drawn
   * on the floor outside the hull, so only lights in front of the wall reach it, and its normals
   * lean towards them.
   */
  private wallFaces(hull: Hull): void {
    this.eachSide(hull, (ax, ay, bx, by, nx, ny) => {
      if (!Showcase.facesViewer(ny)) return;
      // Along the side left to right, so the texture reads the right way up.
      const [x0, y0, x1, y1] = ax <= bx ? [ax, ay, bx, by] : [bx, by, ax, ay];
      const cos = (x1 - x0) / Math.hypot(x1 - x0, y1 - y0), sin = (y1 - y0) / Math.hypot(x1 - x0, y1 - y0);
      this.batch.quad(x0, y0, x1 - x0, y1 - y0, nx * FACE, ny * FACE, x0 / FACE_REPEAT, 0, (x1 - x0) / FACE_REPEAT, 1, cos, sin);
    });
  }

  /** A round contact shadow under a prop. */
  private blob(hull: Hull, role: HullRole): void {
    const [x, y] = hullLocalToWorld(hull, 0, 0, this.point);
    const size = role === 'table' ? 3.6 : role === 'pillar' ? 1.6 : 1.35;
    const cell = CELLS.blob;
    this.sprite(cell, x + 3, y + 5, hull.rotation, size * (role === 'table' ? 0.6 : 1), 0.9, true);
    if (role === 'table') this.sprite(cell, x + 3, y + 5, hull.rotation + Math.PI / 2, 2.2, 0.9, true);
  }

  /** A prop's picture over its hull: centred on the hull's local origin, turned with it. */
  private prop(hull: Hull, role: Exclude<HullRole, 'wall'>): void {
    const [x, y] = hullLocalToWorld(hull, 0, 0, this.point);
    switch (role) {
      case 'crate': this.sprite(CELLS.crate, x, y, hull.rotation, 60 / 64); break;
      case 'barrel': this.sprite(CELLS.barrel, x, y, hull.rotation, 60 / 64); break;
      case 'pillar': this.sprite(CELLS.pillar, x, y, hull.rotation, 1); break;
      case 'table': this.sprite(CELLS.table, x, y, hull.rotation + Math.PI / 2, 1); break;
      case 'bar': this.sprite(CELLS.bar, x, y, hull.rotation, 0.5); break;
    }
  }

  private decor(decor: Decor): void {
    this.sprite(decor.kind === 'rug' ? CELLS.rug : CELLS.books, decor.x, decor.y, decor.rotation, 1);
  }

  /** Faint dark stains of several sizes over the floor, the same on every frame. */
  private stains(): void {
    for (let i = 0; i < STAINS; i++) {
      const x = 80 + hash(i, 1, 211) * (LEVEL_WIDTH - 160), y = FLOOR_TOP + 80 + hash(i, 2, 211) * (LEVEL_HEIGHT - FLOOR_TOP - 160);
      this.sprite(CELLS.blob, x, y, hash(i, 3, 211) * 6.28, 1.5 + hash(i, 4, 211) * 3, 0.18 + hash(i, 5, 211) * 0.2, true);
    }
  }

  /** A flame over a light, growing and shrinking with its flicker, its frame cycling. */
  private flame(light: Light, size: number): void {
    const wobble = this.flickerOf(light);
    const frame = Math.floor(this.time * 10 + light.position[0]) % FLAME_FRAMES;
    const cell = flameCell(frame);
    const scale = size * (0.8 + 0.35 * wobble) * 0.75;
    // Its base at the light, the tip up the screen.
    this.sprite(cell, light.position[0], light.position[1] - (cell.h * scale) / 2 + 6 * size, 0, scale, light.enabled ? 1 : 0);
  }

  /** Embers rising and fading around the brazier's light. */
  private embers(light: Light): void {
    const [cx, cy] = light.position;
    for (let i = 0; i < EMBERS; i++) {
      const life = (this.time * (0.25 + (i % 5) * 0.06) + i * 0.37) % 1;
      const angle = i * 2.4 + noise(i, this.time * 0.5, 64, 7) * 1.5;
      const reach = 22 + life * EMBER_REACH;
      this.sprite(CELLS.ember, cx + Math.cos(angle) * reach, cy + Math.sin(angle) * reach - life * 20, 0, 0.5 + 0.4 * (1 - life), (1 - life) * 0.9);
    }
  }
}

/** A flicker signal in 0..1 from a few incommensurate sines, for time `t` in the light's own units. */
function flicker(t: number): number {
  return 0.5 + 0.25 * Math.sin(t) * Math.sin(t * 0.37 + 1) + 0.15 * Math.sin(t * 2.73 + 2) + 0.1 * Math.sin(t * 5.1);
}
