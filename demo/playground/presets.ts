import type { SceneDocument, SceneHull, SceneLight, SceneLightBase } from 'penumbra-gl';
import { PLAYGROUND_APP, writePlaygroundState } from './appState';
import { buildLevel } from './showcase/level';
import { seededRandom } from './textures';

type Point = [number, number];

function scene(ambient: [number, number, number], center: Point, zoom: number, hulls: SceneHull[], lights: SceneLight[]): SceneDocument {
  return {
    format: 'penumbra-scene', version: 3, ambient, camera: { center, zoom }, hulls, lights,
    look: { exposure: 1, toneMapping: 'none', dithering: 'none', lightmapBlur: 0 }, app: {},
  };
}

function hull(points: Point[], position: Point, rotation = 0): SceneHull {
  return { points, position, origin: [0, 0], rotation, scale: [1, 1], enabled: true, closed: true, layers: 1 };
}

/** A w × h box centred on its position. */
function box(x: number, y: number, w: number, h: number, rotation = 0): SceneHull {
  return hull([[-w / 2, -h / 2], [w / 2, -h / 2], [w / 2, h / 2], [-w / 2, h / 2]], [x, y], rotation);
}

/** A regular polygon of `sides` around its position. */
function pillar(x: number, y: number, radius: number, sides = 8): SceneHull {
  const points: Point[] = [];
  for (let i = 0; i < sides; i++) points.push([Math.cos((i / sides) * Math.PI * 2) * radius, Math.sin((i / sides) * Math.PI * 2) * radius]);
  return hull(points, [x, y]);
}

function light(position: Point, fields: Partial<SceneLightBase> = {}): SceneLightBase {
  return {
    position, range: 300, radius: 10, color: [1, 1, 1], intensity: 1, rotation: 0, origin: [0.5, 0.5],
    shadowType: 'illuminated', enabled: true, castsShadows: true, ignoredHulls: [],
    shadowLayers: 0xffffffff, shadowColor: [0, 0, 0], shadowStrength: 1, litLayers: 0xffffffff, falloff: 'linear', height: null, ...fields,
  };
}

/** The default level: a walled hall with pillars, crates, torches, a sweeping spotlight and a flickering brazier. */
function dungeon(): SceneDocument {
  const hulls = [
    // Concave: the north wall with two wings, and an L-shaped inner wall.
    hull([[0, 0], [1400, 0], [1400, 260], [1360, 260], [1360, 40], [40, 40], [40, 260], [0, 260]], [0, 0]),
    hull([[0, 0], [240, 0], [240, 40], [40, 40], [40, 220], [0, 220]], [880, 420]),
    pillar(380, 330, 34), pillar(380, 640, 34), pillar(1100, 330, 30, 6),
    box(620, 720, 70, 70, 0.3), box(700, 760, 50, 50, -0.2), box(1180, 720, 120, 40),
    hull([[0, -40], [30, 30], [-30, 30]], [200, 760], 0.4),
  ];
  const lights: SceneLight[] = [
    { kind: 'point', ...light([240, 470], { range: 420, radius: 14, color: [1, 0.72, 0.42], intensity: 1.2 }) },
    { kind: 'point', ...light([1250, 470], { range: 380, radius: 8, color: [0.45, 0.7, 1], intensity: 1.1 }) },
    { kind: 'spot', ...light([700, 90], { range: 650, radius: 6, color: [1, 0.95, 0.8], intensity: 1.4, rotation: Math.PI / 2 }), coneAngle: 0.9, coneDecay: 1.5 },
    { kind: 'textured', ...light([760, 520], { range: 260, radius: 18, color: [1, 0.55, 0.2], intensity: 1.6 }), cookie: 'flame', size: [520, 520] },
  ];
  return scene([0.08, 0.08, 0.12], [700, 420], 0.7, hulls, lights);
}

/** Three lights of growing source radius behind the same hulls: the penumbra widens with the radius. */
function penumbraLab(): SceneDocument {
  const hulls: SceneHull[] = [];
  const lights: SceneLight[] = [];
  [0, 12, 40].forEach((radius, i) => {
    const x = 250 + i * 450;
    hulls.push(box(x, 360, 60, 60), pillar(x + 70, 470, 22));
    lights.push({ kind: 'point', ...light([x, 220], { range: 420, radius, color: [1, 0.9, 0.75], shadowType: i === 2 ? 'solid' : 'illuminated' }) });
  });
  return scene([0.03, 0.03, 0.05], [700, 400], 0.85, hulls, lights);
}

/** A stage of coloured spotlights crossing between columns, and a lantern with a pierced cookie. */
function stage(): SceneDocument {
  const hulls = [pillar(450, 420, 30, 12), pillar(700, 330, 30, 12), pillar(950, 420, 30, 12), box(700, 600, 300, 24)];
  const colors: [number, number, number][] = [[1, 0.2, 0.2], [0.2, 1, 0.3], [0.3, 0.4, 1]];
  const lights: SceneLight[] = colors.map((color, i) => ({
    kind: 'spot', ...light([300 + i * 400, 120], { range: 700, radius: 8, color, intensity: 1.3, rotation: Math.PI / 2 + (1 - i) * 0.45 }),
    coneAngle: 0.7, coneDecay: 1,
  }));
  lights.push({ kind: 'textured', ...light([700, 760], { range: 380, radius: 6, color: [1, 0.85, 0.5] }), cookie: 'lantern', size: [600, 600] });
  lights.push({ kind: 'textured', ...light([1150, 700], { range: 300, radius: 4, color: [0.6, 0.7, 1], rotation: 0.3 }), cookie: 'window', size: [300, 260] });
  return scene([0.05, 0.05, 0.06], [700, 450], 0.8, hulls, lights);
}

/** Light and hull counts of the stress preset. */
const STRESS_LIGHTS = 300;
const STRESS_HULLS = 3000;

/** Hundreds of lights and thousands of hulls (mostly boxes and pillars, some L-shapes), from a fixed seed. */
function stress(): SceneDocument {
  const random = seededRandom(2024);
  const width = 6000, height = 4000;
  const hulls: SceneHull[] = [];
  for (let i = 0; i < STRESS_HULLS; i++) {
    const x = random() * width, y = random() * height, size = 12 + random() * 30;
    if (i % 10 === 0) hulls.push(hull([[0, 0], [size * 2, 0], [size * 2, size / 2], [size / 2, size / 2], [size / 2, size * 2], [0, size * 2]], [x, y], random() * 6.28));
    else if (i % 3 === 0) hulls.push(pillar(x, y, size / 2, 6));
    else hulls.push(box(x, y, size, size * (0.5 + random()), random() * 6.28));
  }
  const lights: SceneLight[] = [];
  for (let i = 0; i < STRESS_LIGHTS; i++) {
    const color: [number, number, number] = [0.5 + random() * 0.5, 0.5 + random() * 0.5, 0.5 + random() * 0.5];
    lights.push({ kind: 'point', ...light([random() * width, random() * height], { range: 150 + random() * 200, radius: 5 + random() * 20, color }) });
  }
  return scene([0.05, 0.05, 0.05], [width / 2, height / 2], 0.25, hulls, lights);
}

/** The preset drawn with the showcase's own art (normal-mapped level, flicker, day and night): the first view. */
const SHOWCASE_PRESET = 'Showcase';

/** The presets by name, in menu order; the first is the default level. */
export const PRESETS: Readonly<Record<string, () => SceneDocument>> = {
  // Drawn with the showcase's art, its objects taking the level's roles in order.
  [SHOWCASE_PRESET]: () => ({ ...buildLevel().document, app: { [PLAYGROUND_APP]: writePlaygroundState({ art: 'showcase', showcase: null }) } }),
  Dungeon: dungeon,
  'Penumbra lab': penumbraLab,
  Stage: stage,
  Stress: stress,
};
