/**
 * What the playground keeps in a scene file besides the scene: its entry in the file's `app`
 * object (docs/scene-format.md), so that a saved scene loads back drawn the same way.
 */
import { SceneFormatError, type JsonValue, type SceneAppData } from 'penumbra-gl';

/** The playground's key in a scene file's `app` object. */
export const PLAYGROUND_APP = 'penumbra-gl/playground';
/** The version of the playground's entry this page writes and reads. */
const STATE_VERSION = 1;

/** A flickering light's steady values (the flicker scales them), by its index in the file's `lights`. */
interface SteadyLight {
  light: number;
  intensity: number;
  radius: number;
}

/** The showcase level's state beyond its lights and hulls. */
export interface ShowcaseState {
  /** The daylight slider, 0 (night) to 1 (noon); the colours it set are the file's own. */
  daylight: number;
  /** The flicker's clock, seconds. */
  clock: number;
  /** For each hull of the file, the index of its role in the level (which picture draws it), or null for a hull the editor added. */
  hullRoles: (number | null)[];
  /** For each light of the file, the index of its role in the level (sconce, brazier…), or null. */
  lightRoles: (number | null)[];
  /** Steady values of the lights that flicker. */
  flicker: SteadyLight[];
}

/** The playground's entry: which art draws the scene, and the showcase's state when it is the showcase. */
type PlaygroundState = { art: 'generic' } | { art: 'showcase'; showcase: ShowcaseState | null };

/** The playground's entry of a file's application data as JSON. */
export function writePlaygroundState(state: PlaygroundState): JsonValue {
  if (state.art === 'generic') return { version: STATE_VERSION, art: 'generic' };
  const showcase = state.showcase;
  return {
    version: STATE_VERSION,
    art: 'showcase',
    showcase: showcase && {
      daylight: showcase.daylight, clock: showcase.clock, hullRoles: showcase.hullRoles, lightRoles: showcase.lightRoles,
      flicker: showcase.flicker.map(({ light, intensity, radius }) => ({ light, intensity, radius })),
    },
  };
}

/** How many objects a file has, or a level has roles for. */
export interface ObjectCounts {
  hulls: number;
  lights: number;
}

/**
 * The playground's entry of a file's application data; a file without one is drawn with the
 * generic art. `file`: how many hulls and lights the file has; `level`: how many roles the
 * showcase level has.
 *
 * @throws {SceneFormatError} naming the bad field, e.g. `app.penumbra-gl/playground.showcase.daylight`.
 */
export function readPlaygroundState(app: SceneAppData, file: ObjectCounts, level: ObjectCounts): PlaygroundState {
  const entry = app[PLAYGROUND_APP];
  if (entry === undefined) return { art: 'generic' };
  const path = `app.${PLAYGROUND_APP}`;
  const fields = object(entry, path);
  if (fields.version !== STATE_VERSION) throw new SceneFormatError(`${path}.version`, `expected ${STATE_VERSION} (the version this playground writes), got ${JSON.stringify(fields.version)}`);
  if (fields.art === 'generic') return { art: 'generic' };
  if (fields.art !== 'showcase') throw new SceneFormatError(`${path}.art`, `expected "showcase" or "generic", got ${JSON.stringify(fields.art)}`);
  if (fields.showcase === undefined || fields.showcase === null) return { art: 'showcase', showcase: null };
  return { art: 'showcase', showcase: readShowcase(fields.showcase, `${path}.showcase`, file, level) };
}

function readShowcase(value: JsonValue, path: string, file: ObjectCounts, level: ObjectCounts): ShowcaseState {
  const fields = object(value, path);
  const flicker = array(fields.flicker, `${path}.flicker`).map((item, i) => {
    const itemPath = `${path}.flicker[${i}]`;
    const steady = object(item, itemPath);
    return {
      light: index(steady.light, `${itemPath}.light`, file.lights),
      intensity: number(steady.intensity, `${itemPath}.intensity`, 0),
      radius: number(steady.radius, `${itemPath}.radius`, 0),
    };
  });
  return {
    daylight: number(fields.daylight, `${path}.daylight`, 0, 1),
    clock: number(fields.clock, `${path}.clock`, 0),
    hullRoles: roles(fields.hullRoles, `${path}.hullRoles`, file.hulls, level.hulls),
    lightRoles: roles(fields.lightRoles, `${path}.lightRoles`, file.lights, level.lights),
    flicker,
  };
}

function object(value: JsonValue | undefined, path: string): { [key: string]: JsonValue } {
  if (typeof value !== 'object' || value === null || Array.isArray(value)) throw new SceneFormatError(path, `expected an object, got ${JSON.stringify(value)}`);
  return value;
}

function array(value: JsonValue | undefined, path: string): JsonValue[] {
  if (!Array.isArray(value)) throw new SceneFormatError(path, `expected an array, got ${JSON.stringify(value)}`);
  return value;
}

function number(value: JsonValue | undefined, path: string, min: number, max = Infinity): number {
  if (typeof value !== 'number' || value < min || value > max) {
    throw new SceneFormatError(path, `expected a number from ${min}${max === Infinity ? '' : ` to ${max}`}, got ${JSON.stringify(value)}`);
  }
  return value;
}

function index(value: JsonValue | undefined, path: string, count: number): number {
  if (typeof value !== 'number' || !Number.isInteger(value) || value < 0 || value >= count) {
    throw new SceneFormatError(path, `expected an index from 0 to ${count - 1}, got ${JSON.stringify(value)}`);
  }
  return value;
}

/** One entry per object of the file (`count`): the index of one of the level's `roles`, or null. */
function roles(value: JsonValue | undefined, path: string, count: number, roleCount: number): (number | null)[] {
  const items = array(value, path);
  if (items.length !== count) throw new SceneFormatError(path, `expected ${count} entries (one per object of the file), got ${items.length}`);
  return items.map((item, i) => (item === null ? null : index(item, `${path}[${i}]`, roleCount)));
}
