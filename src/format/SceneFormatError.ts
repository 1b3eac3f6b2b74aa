/**
 * A scene file that does not follow the format. `path` names the bad field the way you would
 * reach it in the JSON (`hulls[3].points[1]`, or `(root)` for the whole document); the message
 * is `path: problem`.
 */
export class SceneFormatError extends Error {
  /**
   * @param path - The bad field, e.g. `hulls[3].points[1]`, or `(root)`.
   * @param problem - What is wrong with it, showing the value (cut to about 80 characters).
   */
  constructor(readonly path: string, readonly problem: string) {
    super(`${path}: ${problem}`);
    this.name = 'SceneFormatError';
  }
}
