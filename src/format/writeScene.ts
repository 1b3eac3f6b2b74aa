import { readScene } from './readScene';
import type { SceneDocument } from './SceneDocument';

/**
 * Writes a scene as JSON text (two-space indented) that {@link readScene} reads back to an equal
 * document. The document is checked first, so a file that would not load is never written.
 *
 * @throws {SceneFormatError} when `scene` has a bad field, naming its path.
 */
export function writeScene(scene: SceneDocument): string {
  return JSON.stringify(readScene(scene), null, 2);
}
