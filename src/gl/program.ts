/** A linked program and its uniform locations, looked up once at link time. */
export interface Program {
  readonly handle: WebGLProgram;
  readonly uniforms: Readonly<Record<string, WebGLUniformLocation>>;
}

/**
 * Compiles and links a program. Throws an `Error` naming the pass, the stage and the info log,
 * with the source lines around each reported error, when compiling or linking fails; then no GL
 * object of the attempt is left.
 */
export function createProgram(gl: WebGL2RenderingContext, passName: string, vertexSource: string, fragmentSource: string): Program {
  const vertex = compileShader(gl, passName, gl.VERTEX_SHADER, vertexSource);
  try {
    const fragment = compileShader(gl, passName, gl.FRAGMENT_SHADER, fragmentSource);
    try {
      return linkProgram(gl, passName, vertex, fragment);
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
 * Creates every program of `sources`, or none: when one fails, those already made are deleted
 * before the error goes on.
 */
export function createPrograms<K extends string>(gl: WebGL2RenderingContext, sources: Readonly<Record<K, ProgramSources>>): Record<K, Program> {
  const made: Partial<Record<K, Program>> = {};
  try {
    for (const key of Object.keys(sources) as K[]) {
      const [passName, vertexSource, fragmentSource] = sources[key];
      made[key] = createProgram(gl, passName, vertexSource, fragmentSource);
    }
  } catch (error) {
    deletePrograms(gl, Object.values(made) as Program[]);
    throw error;
  }
  return made as Record<K, Program>;
}

/** Deletes the programs' GL objects. */
export function deletePrograms(gl: WebGL2RenderingContext, programs: readonly Program[]): void {
  for (const program of programs) gl.deleteProgram(program.handle);
}

function linkProgram(gl: WebGL2RenderingContext, passName: string, vertex: WebGLShader, fragment: WebGLShader): Program {
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
  return { handle, uniforms: uniformLocations(gl, handle) };
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
export function excerptAroundErrors(source: string, log: string): string {
  const lines = source.split('\n');
  const wanted = new Set<number>();
  for (const match of log.matchAll(/ERROR:\s*\d+:(\d+)/g)) {
    const line = Number(match[1]);
    for (let i = line - 2; i <= line + 2; i++) if (i >= 1 && i <= lines.length) wanted.add(i);
  }
  const numbers = wanted.size > 0 ? [...wanted].sort((a, b) => a - b) : lines.map((_, i) => i + 1);
  return numbers.map((n) => `${String(n).padStart(4)}: ${lines[n - 1]}`).join('\n');
}

function uniformLocations(gl: WebGL2RenderingContext, program: WebGLProgram): Record<string, WebGLUniformLocation> {
  const uniforms: Record<string, WebGLUniformLocation> = {};
  const count = gl.getProgramParameter(program, gl.ACTIVE_UNIFORMS) as number;
  for (let i = 0; i < count; i++) {
    const info = gl.getActiveUniform(program, i);
    if (!info) continue;
    const name = info.name.replace(/\[0\]$/, '');
    const location = gl.getUniformLocation(program, info.name);
    if (location) uniforms[name] = location;
  }
  return uniforms;
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
