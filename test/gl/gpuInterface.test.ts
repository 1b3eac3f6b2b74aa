import { afterEach, describe, expect, it } from 'vitest';
import type { ProgramInterface } from '../../src/gl/program';
import { textureUnits } from '../../src/frame/FrameResources';
import { DirectionalLight, Hull, PenumbraRenderer, PointLight, Spotlight, TexturedLight } from '../../src/index';
import { BLUR_INTERFACE } from '../../src/passes/BlurPass';
import { COMPOSITE_INTERFACE } from '../../src/passes/CompositePass';
import { DEBUG_INTERFACE } from '../../src/passes/DebugPass';
import { HULL_MASK_INTERFACE } from '../../src/passes/HullMaskPass';
import { LIGHT_INTERFACE } from '../../src/passes/LightPass';
import { createSurfaceQuad, SURFACE_INTERFACE, SurfacePass } from '../../src/passes/SurfacePass';
import { TEXTURE_UNITS, unitsSpanned } from '../../src/passes/textureUnits';
import { createContext, destroyContext } from './context';

// Every program the renderer and the engine surface pass link, in every build, against the tables
// its pass declares: each active uniform is in its pass's table with the declared GLSL type, and
// each sampler is on its table's unit, distinct within the program, below the units the renderer
// saves and restores. Names of a table that no program uses fail too.

const INTERFACES: Readonly<Record<string, ProgramInterface>> = {
  light: LIGHT_INTERFACE, composite: COMPOSITE_INTERFACE, blur: BLUR_INTERFACE, hullMask: HULL_MASK_INTERFACE,
  debug: DEBUG_INTERFACE, surface: SURFACE_INTERFACE,
};

/**
 * A program as linked through the recording context: the names its pass looked up (an array's
 * without its `[0]`), those it found a location for, and the unit each sampler was last set to.
 */
interface Linked {
  readonly names: Set<string>;
  readonly located: Set<string>;
  readonly units: Map<string, number>;
}

/**
 * A proxy of `gl` that records every program linked through it, the names looked up in each and the
 * units set on them (headless-gl answers some samplers' getUniform with null, so the units are
 * taken from the calls). It also keeps the draw buffers of framebuffers of several attachments,
 * which headless-gl rejects (stackgl/headless-gl pull request 336): a renderer with normals then
 * links all its programs, though it could not draw.
 */
function recordingContext(gl: WebGL2RenderingContext): { context: WebGL2RenderingContext; programs: Map<WebGLProgram, Linked> } {
  const programs = new Map<WebGLProgram, Linked>(), locations = new Map<WebGLUniformLocation, [Linked, string]>();
  const drawBuffers = new Map<WebGLFramebuffer | null, readonly number[]>();
  let framebuffer: WebGLFramebuffer | null = null;
  const overrides: Partial<Record<keyof WebGL2RenderingContext, unknown>> = {
    linkProgram: (program: WebGLProgram) => {
      gl.linkProgram(program);
      programs.set(program, { names: new Set(), located: new Set(), units: new Map() });
    },
    getUniformLocation: (program: WebGLProgram, name: string) => {
      const location = gl.getUniformLocation(program, name);
      const linked = programs.get(program)!, bare = name.replace(/\[0\]$/, '');
      linked.names.add(bare);
      if (location) {
        linked.located.add(bare);
        locations.set(location, [linked, bare]);
      }
      return location;
    },
    uniform1i: (location: WebGLUniformLocation | null, value: number) => {
      const found = location ? locations.get(location) : undefined;
      if (found) found[0].units.set(found[1], value);
      gl.uniform1i(location, value);
    },
    bindFramebuffer: (target: number, bound: WebGLFramebuffer | null) => {
      if (target !== gl.READ_FRAMEBUFFER) framebuffer = bound;
      gl.bindFramebuffer(target, bound);
    },
    drawBuffers: (buffers: number[]) => {
      drawBuffers.set(framebuffer, [...buffers]);
      gl.drawBuffers(buffers);
    },
    getParameter: (name: number) => {
      const buffers = drawBuffers.get(framebuffer);
      const i = name - gl.DRAW_BUFFER0;
      if (buffers && buffers.length > 1 && i >= 0 && i < 16) return buffers[i] ?? gl.NONE;
      return gl.getParameter(name);
    },
  };
  const context = new Proxy(gl, {
    get(target, key) {
      if (key in overrides) return overrides[key as keyof WebGL2RenderingContext];
      const value: unknown = Reflect.get(target, key);
      return typeof value === 'function' ? value.bind(target) : value;
    },
  });
  return { context, programs };
}

/** The GLSL type of an active uniform that is not a sampler, as the tables write it (`vec2[3]` for an array). */
function glslType(gl: WebGL2RenderingContext, info: WebGLActiveInfo): string {
  const names = new Map<number, string>([
    [gl.FLOAT, 'float'], [gl.INT, 'int'], [gl.BOOL, 'bool'], [gl.FLOAT_VEC2, 'vec2'], [gl.FLOAT_VEC3, 'vec3'],
    [gl.FLOAT_VEC4, 'vec4'], [gl.FLOAT_MAT4, 'mat4'],
  ]);
  const name = names.get(info.type) ?? `GL type 0x${info.type.toString(16)}`;
  return info.size > 1 ? `${name}[${info.size}]` : name;
}

/** The interface whose names a program's pass looked up. */
function interfaceOf(linked: Linked): string | undefined {
  const names = [...linked.names].sort().join();
  return Object.keys(INTERFACES).find((key) => [...Object.keys(INTERFACES[key].uniforms), ...Object.keys(INTERFACES[key].samplers)].sort().join() === names);
}

/**
 * What is wrong with the programs of `programs` against their interfaces, each unit below `unitCount`;
 * adds the names each program uses to `used` (by interface).
 */
function problemsOf(gl: WebGL2RenderingContext, programs: Map<WebGLProgram, Linked>, unitCount: number, used: Map<string, Set<string>>): string[] {
  const problems: string[] = [];
  const samplerTypes = new Set<number>([gl.SAMPLER_2D, gl.INT_SAMPLER_2D, gl.UNSIGNED_INT_SAMPLER_2D]);
  for (const [program, linked] of programs) {
    const key = interfaceOf(linked);
    if (key === undefined) {
      problems.push(`a program looked up ${[...linked.names].join(', ')}: no pass's interface`);
      continue;
    }
    const { uniforms, samplers } = INTERFACES[key];
    const unitsTaken = new Map<number, string>();
    const count = gl.getProgramParameter(program, gl.ACTIVE_UNIFORMS) as number;
    for (let i = 0; i < count; i++) {
      const info = gl.getActiveUniform(program, i)!;
      const name = info.name.replace(/\[0\]$/, '');
      used.get(key)!.add(name);
      // (headless-gl finds no location for a few active uniforms by any name: u_quad in the tiled light programs, u_light in the directional ones.)
      const location = gl.getUniformLocation(program, info.name);
      if (location && !linked.located.has(name)) problems.push(`${key}: ${name} has a location, but its pass found none`);
      if (samplerTypes.has(info.type)) {
        const read: unknown = location ? gl.getUniform(program, location) : null;
        const unit = linked.units.get(name) ?? (typeof read === 'number' ? read : 0);
        if (!(name in samplers)) problems.push(`${key}: sampler ${name} is not in its table`);
        else if (unit !== samplers[name]) problems.push(`${key}: sampler ${name} on unit ${unit}, its table says ${samplers[name]}`);
        if (unitsTaken.has(unit)) problems.push(`${key}: samplers ${unitsTaken.get(unit)} and ${name} share unit ${unit}`);
        if (unit >= unitCount) problems.push(`${key}: sampler ${name} on unit ${unit}, beyond the ${unitCount} units saved`);
        unitsTaken.set(unit, name);
      } else if (!(name in uniforms)) {
        problems.push(`${key}: uniform ${name} is not in its table`);
      } else if (glslType(gl, info) !== uniforms[name].type) {
        problems.push(`${key}: uniform ${name} is a ${glslType(gl, info)}, its table says ${uniforms[name].type}`);
      }
    }
  }
  return problems;
}

/** Programs of each interface among `programs`. */
function countsOf(programs: Map<WebGLProgram, Linked>): Record<string, number> {
  const counts: Record<string, number> = {};
  for (const linked of programs.values()) {
    const key = interfaceOf(linked) ?? 'none';
    counts[key] = (counts[key] ?? 0) + 1;
  }
  return counts;
}

describe('the GPU interface of every program', () => {
  let gl: WebGL2RenderingContext | null = null;
  afterEach(() => {
    if (gl) destroyContext(gl);
    gl = null;
  });

  it('links a kind of light\'s programs when the first light of the kind is added, and no other kind\'s', () => {
    gl = createContext(16, 16);
    const { context, programs } = recordingContext(gl);
    const renderer = new PenumbraRenderer(context);
    const lightPrograms = () => countsOf(programs).light ?? 0;
    expect(lightPrograms()).toBe(0);
    // A point light's: unshadowed, plain tiles, held, lean, listed, closed and general.
    renderer.addLight(new PointLight({ position: [4, 8], range: 12, radius: 1 }));
    expect(lightPrograms()).toBe(7);
    renderer.addLight(new PointLight({ position: [12, 8], range: 12, radius: 1 }));
    renderer.addHull(new Hull([[7, 6], [9, 6], [9, 10], [7, 10]]));
    renderer.renderLightmap();
    expect(lightPrograms()).toBe(7);
    // A directional light's: unshadowed, lean and general.
    renderer.addLight(new DirectionalLight({ intensity: 0.2 }));
    expect(lightPrograms()).toBe(10);
    renderer.renderLightmap();
    expect(lightPrograms()).toBe(10);
    renderer.dispose();
  });

  it('has every uniform in its pass\'s table and every sampler on its own unit from the texture-unit table', () => {
    gl = createContext(16, 16);
    const used = new Map(Object.keys(INTERFACES).map((key) => [key, new Set<string>()]));
    const cookie = gl.createTexture();
    gl.bindTexture(gl.TEXTURE_2D, cookie);
    gl.texImage2D(gl.TEXTURE_2D, 0, gl.RGBA8, 1, 1, 0, gl.RGBA, gl.UNSIGNED_BYTE, new Uint8Array([255, 255, 255, 255]));
    gl.bindTexture(gl.TEXTURE_2D, null);
    const problems: string[] = [];
    for (const normals of [false, true]) {
      for (const lightmapScale of [1, 0.5]) {
        const { context, programs } = recordingContext(gl);
        const renderer = new PenumbraRenderer(context, { normals, lightmapScale, lightmapBlur: 2 });
        // A kind of light's programs are linked when the first light of the kind is added; the blur
        // links its program on the first frame it runs (headless-gl cannot draw with normals).
        renderer.addLight(new PointLight({ position: [4, 8], range: 12, radius: 1 }));
        renderer.addLight(new Spotlight({ position: [12, 8], range: 12, radius: 1 }));
        renderer.addLight(new TexturedLight({ position: [8, 4], range: 12, texture: cookie }));
        renderer.addLight(new DirectionalLight({ intensity: 0.2 }));
        if (!normals) {
          renderer.addHull(new Hull([[7, 6], [9, 6], [9, 10], [7, 10]]));
          renderer.renderLightmap();
        }
        const edgeAware = lightmapScale < 1;
        const build = `normals ${normals}, edge-aware ${edgeAware}`;
        // Four light kinds, each unshadowed, lean and general, and but the directional one tiled plain, held, listed and closed.
        expect(countsOf(programs), build).toEqual({
          light: 4 * 3 + 3 * 4, composite: 1, debug: 2, ...(normals ? {} : { blur: 1 }), ...(edgeAware ? { hullMask: 1 } : {}),
        });
        problems.push(...problemsOf(gl, programs, textureUnits(normals, edgeAware), used).map((problem) => `${build}: ${problem}`));
        renderer.dispose();
      }
    }
    const { context, programs } = recordingContext(gl);
    const surfacePass = new SurfacePass(context);
    const texture = gl.createTexture();
    const quad = createSurfaceQuad();
    quad.color = quad.normals = texture;
    surfacePass.begin();
    surfacePass.add(quad);
    surfacePass.render(16, 16, 16, 16, false);
    expect(countsOf(programs)).toEqual({ surface: 1 });
    problems.push(...problemsOf(gl, programs, unitsSpanned([TEXTURE_UNITS.surface]), used).map((problem) => `surface pass: ${problem}`));
    surfacePass.dispose();
    gl.deleteTexture(texture);
    expect(problems).toEqual([]);
    // And no table names what no program has.
    for (const [key, { uniforms, samplers }] of Object.entries(INTERFACES)) {
      expect([...Object.keys(uniforms), ...Object.keys(samplers)].filter((name) => !used.get(key)!.has(name)), `${key}: unused names`).toEqual([]);
    }
  });
});
