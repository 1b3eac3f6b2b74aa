import { Hull } from '../scene/Hull';
import { DirectionalLight } from '../scene/DirectionalLight';
import { Light } from '../scene/Light';
import { PointLight } from '../scene/PointLight';
import { Spotlight } from '../scene/Spotlight';
import { TexturedLight } from '../scene/TexturedLight';
import { describeValue } from '../util/validate';
import { DEFAULT_LOOK, SCENE_FORMAT, SCENE_FORMAT_VERSION, type SceneAppData, type SceneCamera, type SceneDocument, type SceneLight, type SceneLook } from './SceneDocument';
import { SceneFormatError } from './SceneFormatError';

/** Lights and hulls built from a {@link SceneDocument}, ready for `renderer.addLight` / `addHull`. */
export interface SceneObjects {
  /** The hulls, in the file's order (lights' `ignoredHulls` refer to them by index there). */
  hulls: Hull[];
  /** The lights, in the file's order. */
  lights: Light[];
}

/** Finds the light cookie texture of a name, or returns null when the name is unknown. */
export type CookieResolver = (name: string) => WebGLTexture | null;

/**
 * Builds the lights and hulls a scene document describes. Textured lights get their texture from
 * `resolveCookie`. Nothing is added to a renderer: on an error nothing has changed anywhere.
 *
 * @throws {SceneFormatError} `lights[i].cookie` when `resolveCookie` does not know a cookie name.
 */
export function createSceneObjects(scene: SceneDocument, resolveCookie: CookieResolver): SceneObjects {
  const hulls = scene.hulls.map(({ points, ...options }) => new Hull(points, options));
  const lights = scene.lights.map((light, i) => createLight(light, i, hulls, resolveCookie));
  return { hulls, lights };
}

/** The light a document's entry describes: its fields are the light's options, less `kind` (and a textured light's `cookie`). */
function createLight(light: SceneLight, index: number, hulls: readonly Hull[], resolveCookie: CookieResolver): Light {
  const ignoredHulls = light.ignoredHulls.map((i) => hulls[i]);
  switch (light.kind) {
    case 'point': {
      const { kind, ...options } = light;
      return new PointLight({ ...options, ignoredHulls });
    }
    case 'spot': {
      const { kind, ...options } = light;
      return new Spotlight({ ...options, ignoredHulls });
    }
    case 'textured': {
      const { kind, cookie, size, ...options } = light;
      const texture = resolveCookie(cookie);
      if (!texture) throw new SceneFormatError(`lights[${index}].cookie`, `unknown cookie ${describeValue(cookie)}`);
      return new TexturedLight({ ...options, ignoredHulls, texture, size: size ?? undefined });
    }
    case 'directional': {
      const { kind, ...options } = light;
      return new DirectionalLight({ ...options, ignoredHulls });
    }
  }
}

/** What {@link describeScene} needs besides the lights and hulls. */
export interface SceneDescriptionInput extends SceneObjects {
  /** The ambient colour to store, e.g. `renderer.ambientColor`. */
  ambient: readonly [number, number, number];
  /** Where the view is, for the editor that opens the file. */
  camera: SceneCamera;
  /** The cookie name of a textured light's texture. */
  cookieName: (texture: WebGLTexture) => string;
  /** The look to store, e.g. the renderer itself (its `exposure`, `toneMapping`, `dithering`, `lightmapBlur`). Default: the renderer's defaults. */
  look?: Readonly<SceneLook>;
  /** Application data to store, by application name (see {@link SceneDocument.app}); copied when written. Default: none. */
  app?: Readonly<SceneAppData>;
}

/**
 * Describes lights and hulls (e.g. `renderer.lights` and `renderer.hulls`) as a scene document,
 * ready for {@link writeScene}. Ignored hulls that are not in `hulls` are left out.
 */
export function describeScene(input: SceneDescriptionInput): SceneDocument {
  const hullIndex = new Map(input.hulls.map((hull, i) => [hull, i]));
  return {
    format: SCENE_FORMAT,
    version: SCENE_FORMAT_VERSION,
    ambient: [...input.ambient],
    camera: { center: [...input.camera.center], zoom: input.camera.zoom },
    hulls: input.hulls.map((hull) => ({
      points: hull.points.map(([x, y]) => [x, y]),
      position: [...hull.position],
      origin: [...hull.origin],
      rotation: hull.rotation,
      scale: [...hull.scale],
      enabled: hull.enabled,
      closed: hull.closed,
      layers: hull.layers,
    })),
    lights: input.lights.map((light) => describeLight(light, hullIndex, input.cookieName)),
    look: describeLook(input.look ?? DEFAULT_LOOK),
    app: { ...input.app },
  };
}

function describeLook({ exposure, toneMapping, dithering, lightmapBlur }: Readonly<SceneLook>): SceneLook {
  return { exposure, toneMapping, dithering, lightmapBlur };
}

function describeLight(light: Light, hullIndex: ReadonlyMap<Hull, number>, cookieName: (texture: WebGLTexture) => string): SceneLight {
  const shared = {
    color: [...light.color] as [number, number, number],
    intensity: light.intensity,
    rotation: light.rotation,
    shadowType: light.shadowType,
    enabled: light.enabled,
    castsShadows: light.castsShadows,
    ignoredHulls: [...light.ignoredHulls].flatMap((hull) => hullIndex.get(hull) ?? []),
    shadowLayers: light.shadowLayers,
    shadowColor: [...light.shadowColor] as [number, number, number],
    shadowStrength: light.shadowStrength,
    litLayers: light.litLayers,
  };
  // Its inherited position, range, radius and origin mean nothing: a file does not keep them.
  if (light instanceof DirectionalLight) return { kind: 'directional', ...shared, angularSize: light.angularSize, elevation: light.elevation };
  const base = {
    ...shared,
    position: [...light.position] as [number, number],
    range: light.range,
    radius: light.radius,
    origin: [...light.origin] as [number, number],
    falloff: light.falloff,
    height: light.givenHeight,
  };
  if (light instanceof Spotlight) return { kind: 'spot', ...base, coneAngle: light.coneAngle, coneDecay: light.coneDecay };
  if (light instanceof TexturedLight) {
    const size = light.givenSize;
    return { kind: 'textured', ...base, cookie: cookieName(light.texture), size: size && [size[0], size[1]] };
  }
  return { kind: 'point', ...base };
}
