/** The GLSL types of uniforms that are not samplers; an array as `type[length]`. */
type GlslValueType = 'float' | 'int' | 'bool' | 'vec2' | 'vec3' | 'vec4' | 'mat4';
type GlslType = GlslValueType | `${GlslValueType}[${number}]`;

/**
 * A uniform that is not a sampler, as a pass's table declares it: its GLSL type (what it holds is
 * the entry's doc comment, which stays out of the bundle).
 */
export interface UniformDeclaration {
  readonly type: GlslType;
}

/**
 * What a pass addresses in its programs: the uniforms it sets (its table, name to declaration) and
 * the texture unit of each sampler. A program need not use every name (builds differ).
 */
export interface ProgramInterface<Uniform extends string = string, Sampler extends string = string> {
  readonly uniforms: Readonly<Record<Uniform, UniformDeclaration>>;
  readonly samplers: Readonly<Record<Sampler, number>>;
}

/**
 * A linked program and the locations of its interface's names, looked up once at link time: null
 * for a name the program does not use (setting it does nothing).
 */
interface Program<Name extends string = never> {
  readonly handle: WebGLProgram;
  readonly uniforms: Readonly<Record<Name, WebGLUniformLocation | null>>;
}

/** The programs linked with an interface: their uniforms are its names. */
export type ProgramOf<I> = I extends ProgramInterface<infer Uniform, infer Sampler> ? Program<Uniform | Sampler> : never;

const NO_INTERFACE: ProgramInterface<never, never> = { uniforms: {}, samplers: {} };

/**
 * Compiles and links a program, looks up the locations of `programInterface`'s names and sets each
 * sampler to its unit (which leaves the program current when it has samplers). Throws an `Error`
 * naming the pass, the stage and the info log, with the source lines around each reported error,
 * when compiling or linking fails; then no GL object of the attempt is left.
 */
export function createProgram<Uniform extends string = never, Sampler extends string = never>(
  gl: WebGL2RenderingContext, passName: string, vertexSource: string, fragmentSource: string,
  // Left out, the names are `never`: the empty interface is theirs.
  programInterface = NO_INTERFACE as ProgramInterface<Uniform, Sampler>,
): Program<Uniform | Sampler> {
  const vertex = compileShader(gl, passName, gl.VERTEX_SHADER, vertexSource);
  try {
    const fragment = compileShader(gl, passName, gl.FRAGMENT_SHADER, fragmentSource);
    try {
      return linkProgram(gl, passName, vertex, fragment, programInterface);
    } finally {
      gl.deleteShader(fragment);
    }
  } finally {
    // Deleting an attached shader only flags it: it goes with its program.
    gl.deleteShader(vertex);
  }
}

/** A program's pass name (for messages), vertex source and fragment source. */
export type ProgramSources = readonly [passName: string, vertexSource: string, fragmentSource: string];

/**
 * Creates every program of `sources`, all with `programInterface` (see {@link createProgram}), or
 * none: when one fails, those already made are deleted before the error goes on.
 */
export function createPrograms<K extends string, Uniform extends string, Sampler extends string>(
  gl: WebGL2RenderingContext, sources: Readonly<Record<K, ProgramSources>>, programInterface: ProgramInterface<Uniform, Sampler>,
): Record<K, Program<Uniform | Sampler>> {
  const made: Partial<Record<K, Program<Uniform | Sampler>>> = {};
  try {
    for (const key of Object.keys(sources) as K[]) {
      const [passName, vertexSource, fragmentSource] = sources[key];
      made[key] = createProgram(gl, passName, vertexSource, fragmentSource, programInterface);
    }
  } catch (error) {
    deletePrograms(gl, Object.values(made) as Program[]);
    throw error;
  }
  return made as Record<K, Program<Uniform | Sampler>>;
}

/** Deletes the programs' GL objects. */
export function deletePrograms(gl: WebGL2RenderingContext, programs: readonly Program[]): void {
  for (const program of programs) gl.deleteProgram(program.handle);
}

function linkProgram<Uniform extends string, Sampler extends string>(
  gl: WebGL2RenderingContext, passName: string, vertex: WebGLShader, fragment: WebGLShader, programInterface: ProgramInterface<Uniform, Sampler>,
): Program<Uniform | Sampler> {
  const handle = gl.createProgram();
  if (!handle) throw new Error(`penumbra: ${passName}: could not create a program (is the context lost?)`);
  gl.attachShader(handle, vertex);
  gl.attachShader(handle, fragment);
  gl.linkProgram(handle);
  if (!gl.getProgramParameter(handle, gl.LINK_STATUS)) {
    const log = gl.getProgramInfoLog(handle) ?? '';
    gl.deleteProgram(handle);
    throw new Error(`penumbra: ${passName}: program failed to link:\n${log}`);
  }
  return { handle, uniforms: interfaceLocations(gl, handle, programInterface) };
}

function compileShader(gl: WebGL2RenderingContext, passName: string, type: number, source: string): WebGLShader {
  const shader = gl.createShader(type);
  if (!shader) throw new Error(`penumbra: ${passName}: could not create a shader (is the context lost?)`);
  gl.shaderSource(shader, source);
  gl.compileShader(shader);
  if (!gl.getShaderParameter(shader, gl.COMPILE_STATUS)) {
    const log = gl.getShaderInfoLog(shader) ?? '';
    gl.deleteShader(shader);
    const stage = type === gl.VERTEX_SHADER ? 'vertex' : 'fragment';
    throw new Error(`penumbra: ${passName}: ${stage} shader failed to compile:\n${log}\n${excerptAroundErrors(source, log)}`);
  }
  return shader;
}

/** The numbered source lines around every `ERROR: 0:<line>` in a compiler log. */
function excerptAroundErrors(source: string, log: string): string {
  const lines = source.split('\n');
  const wanted = new Set<number>();
  for (const match of log.matchAll(/ERROR:\s*\d+:(\d+)/g)) {
    const line = Number(match[1]);
    for (let i = line - 2; i <= line + 2; i++) if (i >= 1 && i <= lines.length) wanted.add(i);
  }
  const numbers = wanted.size > 0 ? [...wanted].sort((a, b) => a - b) : lines.map((_, i) => i + 1);
  return numbers.map((n) => `${String(n).padStart(4)}: ${lines[n - 1]}`).join('\n');
}

/**
 * The locations of the interface's names in `program`, its samplers set to their units. An array is
 * located by its element 0 (`name[0]`; headless-gl finds no location for the bare name).
 */
function interfaceLocations<Uniform extends string, Sampler extends string>(
  gl: WebGL2RenderingContext, program: WebGLProgram, programInterface: ProgramInterface<Uniform, Sampler>,
): Record<Uniform | Sampler, WebGLUniformLocation | null> {
  const locations = {} as Record<Uniform | Sampler, WebGLUniformLocation | null>;
  for (const [name, declaration] of Object.entries(programInterface.uniforms) as [Uniform, UniformDeclaration][]) {
    locations[name] = gl.getUniformLocation(program, declaration.type.endsWith(']') ? `${name}[0]` : name);
  }
  const samplers = Object.entries(programInterface.samplers) as [Sampler, number][];
  if (samplers.length > 0) gl.useProgram(program);
  for (const [name, unit] of samplers) {
    const location = gl.getUniformLocation(program, name);
    locations[name] = location;
    if (location) gl.uniform1i(location, unit);
  }
  return locations;
}

/** `source` with a `#define name value` line for each entry, after its `#version` line. */
export function withDefines(source: string, defines: Readonly<Record<string, string | number>>): string {
  const entries = Object.entries(defines);
  if (entries.length === 0) return source;
  const lines = entries.map(([name, value]) => `#define ${name} ${value}`.trimEnd()).join('\n');
  const versionEnd = source.startsWith('#version') ? source.indexOf('\n') + 1 : 0;
  return `${source.slice(0, versionEnd)}${lines}\n${source.slice(versionEnd)}`;
}

/** Replaces `#include "name"` lines with the named chunk. */
export function resolveIncludes(source: string, chunks: Readonly<Record<string, string>>): string {
  return source.replace(/^#include\s+"([\w-]+)"\s*$/gm, (_, name: string) => {
    const chunk = chunks[name];
    if (chunk === undefined) throw new Error(`penumbra: unknown shader chunk "${name}"`);
    return chunk;
  });
}
