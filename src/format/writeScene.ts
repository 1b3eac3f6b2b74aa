import { readScene } from './readScene';
import { SCENE_SCHEMA_URL, type SceneDocument } from './SceneDocument';

/**
 * Writes a scene as JSON text (two-space indented) that {@link readScene} reads back to an equal
 * document, led by `"$schema"`: {@link SCENE_SCHEMA_URL}, so that editors validate and complete
 * the file. The document is checked first, so a file that would not load is never written.
 *
 * @throws {SceneFormatError} when `scene` has a bad field, naming its path.
 */
export function writeScene(scene: SceneDocument): string {
  return JSON.stringify({ $schema: SCENE_SCHEMA_URL, ...readScene(scene) }, null, 2);
}
