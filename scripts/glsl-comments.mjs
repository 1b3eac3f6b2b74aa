/**
 * A Vite plugin for the library build: the shaders' `?raw` imports without their comments,
 * indentation and blank lines (GLSL gives whitespace no meaning but between tokens). GLSL has no
 * string literals, so everything from `//` to the end of a line is a comment; the sources use no
 * block comments (a `/*` fails the build rather than being kept). The shader text users' bundles
 * carry shrinks by more than half; the tests and the demos read the shaders as written, with the
 * same code.
 */
export function stripGlslComments() {
  return {
    name: 'penumbra:strip-glsl-comments',
    enforce: 'post',
    transform(code, id) {
      if (!/\.glsl\?raw$/.test(id)) return null;
      const match = /^export default ("(?:[^"\\]|\\.)*");?\s*$/s.exec(code);
      if (!match) throw new Error(`penumbra: unexpected ?raw module for ${id}`);
      const source = JSON.parse(match[1]);
      if (source.includes('/*')) throw new Error(`penumbra: block comment in ${id}: strip it by hand`);
      const stripped = source.split('\n').map((line) => line.replace(/\s*\/\/.*$/, '').trim()).filter((line) => line !== '').join('\n') + '\n';
      return { code: `export default ${JSON.stringify(stripped)};`, map: null };
    },
  };
}
