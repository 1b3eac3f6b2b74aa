/**
 * The playground's art, generated at start-up so the repository ships no image files: tiles for
 * the floor, stone for hulls, sprites, and the light cookies of textured lights.
 */

/** A small deterministic random generator (mulberry32), so the art looks the same on every load. */
export function seededRandom(seed: number): () => number {
  let a = seed >>> 0;
  return () => {
    a = (a + 0x6d2b79f5) >>> 0;
    let t = a;
    t = Math.imul(t ^ (t >>> 15), t | 1);
    t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
}

function canvas2d(size: number): CanvasRenderingContext2D {
  const canvas = document.createElement('canvas');
  canvas.width = canvas.height = size;
  return canvas.getContext('2d')!;
}

/** Raw RGBA pixels, rows top-down as generated. */
interface RgbaPixels {
  width: number;
  height: number;
  pixels: Uint8Array;
}

/** Uploads a canvas (or raw RGBA pixels) as a mipmapped, repeating or clamped texture. */
export function createTexture(gl: WebGL2RenderingContext, source: TexImageSource | RgbaPixels, repeat: boolean): WebGLTexture {
  const texture = gl.createTexture();
  gl.bindTexture(gl.TEXTURE_2D, texture);
  if ('pixels' in source) {
    gl.pixelStorei(gl.UNPACK_ALIGNMENT, 4);
    gl.texImage2D(gl.TEXTURE_2D, 0, gl.RGBA8, source.width, source.height, 0, gl.RGBA, gl.UNSIGNED_BYTE, source.pixels);
  } else {
    gl.texImage2D(gl.TEXTURE_2D, 0, gl.RGBA, gl.RGBA, gl.UNSIGNED_BYTE, source);
  }
  gl.generateMipmap(gl.TEXTURE_2D);
  const wrap = repeat ? gl.REPEAT : gl.CLAMP_TO_EDGE;
  gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_WRAP_S, wrap);
  gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_WRAP_T, wrap);
  gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MIN_FILTER, gl.LINEAR_MIPMAP_LINEAR);
  gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MAG_FILTER, gl.LINEAR);
  gl.bindTexture(gl.TEXTURE_2D, null);
  return texture;
}

/** Compiles and links a program of the playground's art; throws naming `name` and the log when that fails. */
export function linkProgram(gl: WebGL2RenderingContext, name: string, vertexSource: string, fragmentSource: string): WebGLProgram {
  const program = gl.createProgram();
  for (const [type, source] of [[gl.VERTEX_SHADER, vertexSource], [gl.FRAGMENT_SHADER, fragmentSource]] as const) {
    const shader = gl.createShader(type)!;
    gl.shaderSource(shader, source);
    gl.compileShader(shader);
    if (!gl.getShaderParameter(shader, gl.COMPILE_STATUS)) throw new Error(`playground: ${name} shader: ${gl.getShaderInfoLog(shader)}`);
    gl.attachShader(program, shader);
    gl.deleteShader(shader);
  }
  gl.linkProgram(program);
  if (!gl.getProgramParameter(program, gl.LINK_STATUS)) throw new Error(`playground: ${name} program: ${gl.getProgramInfoLog(program)}`);
  return program;
}

/** Worn stone floor tiles, 4 × 4 per texture, with grout and speckle. */
export function drawFloorTiles(): HTMLCanvasElement {
  const size = 256, tile = size / 4;
  const g = canvas2d(size);
  const random = seededRandom(7);
  g.fillStyle = '#2b2622';
  g.fillRect(0, 0, size, size);
  for (let ty = 0; ty < 4; ty++) {
    for (let tx = 0; tx < 4; tx++) {
      const shade = 150 + Math.floor(random() * 40);
      g.fillStyle = `rgb(${shade}, ${shade - 12}, ${shade - 28})`;
      g.fillRect(tx * tile + 2, ty * tile + 2, tile - 4, tile - 4);
    }
  }
  for (let i = 0; i < 2500; i++) {
    g.fillStyle = `rgba(${random() < 0.5 ? '0,0,0' : '255,240,220'}, ${0.05 + random() * 0.1})`;
    g.fillRect(random() * size, random() * size, 1 + random() * 2, 1 + random() * 2);
  }
  return g.canvas;
}

/** Rough-hewn block tops for hulls (walls, pillars, crates seen from above). */
export function drawStone(): HTMLCanvasElement {
  const size = 128;
  const g = canvas2d(size);
  const random = seededRandom(11);
  g.fillStyle = '#5d5f66';
  g.fillRect(0, 0, size, size);
  for (let row = 0; row < 4; row++) {
    const offset = row % 2 === 0 ? 0 : 32;
    for (let col = -1; col < 2; col++) {
      const shade = 80 + Math.floor(random() * 30);
      g.fillStyle = `rgb(${shade}, ${shade + 2}, ${shade + 8})`;
      g.fillRect(offset + col * 64 + 2, row * 32 + 2, 60, 28);
    }
  }
  return g.canvas;
}

/** A top-down character: body, head and a lantern-yellow scarf; transparent around. */
export function drawWalker(): HTMLCanvasElement {
  const g = canvas2d(64);
  g.fillStyle = '#3f6fb5';
  g.beginPath();
  g.ellipse(32, 32, 22, 14, 0, 0, Math.PI * 2);
  g.fill();
  g.fillStyle = '#e0b04a';
  g.fillRect(24, 26, 16, 12);
  g.fillStyle = '#f1c9a5';
  g.beginPath();
  g.arc(40, 32, 9, 0, Math.PI * 2);
  g.fill();
  return g.canvas;
}

/** A wooden barrel seen from above. */
export function drawBarrel(): HTMLCanvasElement {
  const g = canvas2d(64);
  g.fillStyle = '#7a4a22';
  g.beginPath();
  g.arc(32, 32, 28, 0, Math.PI * 2);
  g.fill();
  g.strokeStyle = '#3a2a1a';
  g.lineWidth = 4;
  for (const r of [26, 16]) {
    g.beginPath();
    g.arc(32, 32, r, 0, Math.PI * 2);
    g.stroke();
  }
  return g.canvas;
}

/** A cookie whose red channel is `shape(u, v)` in 0..1 over a square of `size` pixels. */
export function drawCookie(size: number, shape: (u: number, v: number) => number): ImageData {
  const pixels = new ImageData(size, size);
  for (let y = 0; y < size; y++) {
    for (let x = 0; x < size; x++) {
      const value = Math.max(0, Math.min(1, shape((x + 0.5) / size, (y + 0.5) / size)));
      const i = (y * size + x) * 4;
      pixels.data[i] = pixels.data[i + 1] = pixels.data[i + 2] = Math.round(value * 255);
      pixels.data[i + 3] = 255;
    }
  }
  return pixels;
}

/** Moonlight through a four-pane window: bright panes, dark frame, soft overall falloff. */
export function windowCookie(u: number, v: number): number {
  const fu = (u * 2) % 1, fv = (v * 2) % 1;
  const frame = Math.min(fu, 1 - fu, fv, 1 - fv) < 0.08 ? 0.05 : 1;
  const edge = Math.min(u, 1 - u, v, 1 - v);
  return frame * Math.min(1, edge * 8);
}

/** A ring of light spots, as through a pierced lantern. */
export function lanternCookie(u: number, v: number): number {
  const dx = u - 0.5, dy = v - 0.5;
  const distance = Math.hypot(dx, dy) * 2;
  const holes = 0.5 + 0.5 * Math.cos(Math.atan2(dy, dx) * 12);
  return Math.max(0, 1 - distance) * (0.3 + 0.7 * holes * holes);
}
