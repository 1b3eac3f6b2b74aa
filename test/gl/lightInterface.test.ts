import { afterEach, describe, expect, it } from 'vitest';
import { LIGHT_UNIFORMS } from '../../src/passes/lightLayout';
import { TEXTURE_UNITS } from '../../src/passes/textureUnits';
import { PenumbraRenderer } from '../../src/index';
import { createContext, destroyContext } from './context';

/** The programs a renderer links on `gl`, each with its fragment source, recorded through a proxy of the context. */
function recordPrograms(gl: WebGL2RenderingContext): { context: WebGL2RenderingContext; programs: Map<WebGLProgram, string> } {
  const sources = new Map<WebGLShader, string>(), fragments = new Map<WebGLProgram, string>(), programs = new Map<WebGLProgram, string>();
  const overrides: Partial<Record<keyof WebGL2RenderingContext, unknown>> = {
    shaderSource: (shader: WebGLShader, source: string) => {
      sources.set(shader, source);
      gl.shaderSource(shader, source);
    },
    attachShader: (program: WebGLProgram, shader: WebGLShader) => {
      if (sources.get(shader)?.includes('out vec4')) fragments.set(program, sources.get(shader)!);
      gl.attachShader(program, shader);
    },
    linkProgram: (program: WebGLProgram) => {
      gl.linkProgram(program);
      programs.set(program, fragments.get(program) ?? '');
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

const LIGHT_TEXTURE_UNITS = { ...TEXTURE_UNITS.light, ...TEXTURE_UNITS.lightWithNormals };

const SAMPLER_TYPES = (gl: WebGL2RenderingContext) => new Set<number>([gl.SAMPLER_2D, gl.INT_SAMPLER_2D, gl.UNSIGNED_INT_SAMPLER_2D]);

describe('the light pass\'s GPU interface', () => {
  let gl: WebGL2RenderingContext | null = null;
  afterEach(() => {
    if (gl) destroyContext(gl);
    gl = null;
  });

  it('gives every sampler its own unit, from 0 up', () => {
    const units = Object.values(LIGHT_TEXTURE_UNITS).sort((a, b) => a - b);
    expect(units).toEqual(units.map((_, i) => i));
  });

  // Without normals: headless-gl cannot draw into the three colour attachments normals need (the
  // surface's samplers and uniforms are in the tables all the same).
  it('sets every sampler of every light program to its unit in the table, and has every other uniform in the table', () => {
    gl = createContext(16, 16);
    const { context, programs } = recordPrograms(gl);
    const renderer = new PenumbraRenderer(context);
    const samplerTypes = SAMPLER_TYPES(gl);
    let lightPrograms = 0;
    const readBack = new Set<string>();
    for (const [program, fragment] of programs) {
      if (!fragment.includes('void writeLight(')) continue;
      lightPrograms++;
      const count = gl.getProgramParameter(program, gl.ACTIVE_UNIFORMS) as number;
      for (let i = 0; i < count; i++) {
        const info = gl.getActiveUniform(program, i)!;
        const name = info.name.replace(/\[0\]$/, '');
        if (samplerTypes.has(info.type)) {
          expect(Object.keys(LIGHT_TEXTURE_UNITS), `sampler ${name}`).toContain(name);
          // headless-gl answers some samplers' getUniform with null (its native call returns nothing);
          // every sampler is read back in some program.
          const unit: unknown = gl.getUniform(program, gl.getUniformLocation(program, info.name)!);
          if (unit === null) continue;
          expect(unit, `unit of ${name}`).toBe(LIGHT_TEXTURE_UNITS[name as keyof typeof LIGHT_TEXTURE_UNITS]);
          readBack.add(name);
        } else {
          expect(Object.keys(LIGHT_UNIFORMS), `uniform ${name}`).toContain(name);
        }
      }
    }
    // Four light kinds, each unshadowed, lean and general, and but the directional one tiled plain and held.
    expect(lightPrograms).toBeGreaterThanOrEqual(4 * 3 + 3 * 2);
    expect([...readBack].sort()).toEqual(['u_bins', 'u_cookie', 'u_entries', 'u_recordTags', 'u_records']);
    renderer.dispose();
  });
});
