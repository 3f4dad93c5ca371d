// WebGL2 helpers of the studio's view: programs, float textures, render targets.
// Float data is uploaded as RGBA16F (filterable and renderable with EXT_color_buffer_float).

export function compileProgram(gl, vertex, fragment) {
  const stage = (type, source) => {
    const shader = gl.createShader(type);
    gl.shaderSource(shader, source);
    gl.compileShader(shader);
    if (!gl.getShaderParameter(shader, gl.COMPILE_STATUS)) {
      const log = gl.getShaderInfoLog(shader);
      gl.deleteShader(shader);
      throw new Error(`view: shader does not compile: ${log}`);
    }
    return shader;
  };
  const program = gl.createProgram();
  const vs = stage(gl.VERTEX_SHADER, vertex);
  const fs = stage(gl.FRAGMENT_SHADER, fragment);
  gl.attachShader(program, vs);
  gl.attachShader(program, fs);
  gl.linkProgram(program);
  gl.deleteShader(vs);
  gl.deleteShader(fs);
  if (!gl.getProgramParameter(program, gl.LINK_STATUS)) {
    throw new Error(`view: program does not link: ${gl.getProgramInfoLog(program)}`);
  }
  return program;
}

function mipLevels(width, height) {
  return Math.floor(Math.log2(Math.max(width, height))) + 1;
}

// A (width x height) RGBA16F texture from RGBA float32 (or float16 bits: Uint16Array) data,
// row 0 at v = 0; `mipmaps`: the whole chain (box filter), trilinear.
export function floatTexture(gl, width, height, data, { mipmaps = false, repeat = [false, false] } = {}) {
  const tex = gl.createTexture();
  gl.bindTexture(gl.TEXTURE_2D, tex);
  gl.texStorage2D(gl.TEXTURE_2D, mipmaps ? mipLevels(width, height) : 1, gl.RGBA16F, width, height);
  if (data) {
    const type = data instanceof Uint16Array ? gl.HALF_FLOAT : gl.FLOAT;
    gl.texSubImage2D(gl.TEXTURE_2D, 0, 0, 0, width, height, gl.RGBA, type, data);
    if (mipmaps) gl.generateMipmap(gl.TEXTURE_2D);
  }
  gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MIN_FILTER, mipmaps ? gl.LINEAR_MIPMAP_LINEAR : gl.LINEAR);
  gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MAG_FILTER, gl.LINEAR);
  gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_WRAP_S, repeat[0] ? gl.REPEAT : gl.CLAMP_TO_EDGE);
  gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_WRAP_T, repeat[1] ? gl.REPEAT : gl.CLAMP_TO_EDGE);
  return tex;
}

// A framebuffer drawing into `level` of `texture` (and a depth buffer when `depth`).
export function framebufferFor(gl, texture, level = 0, depth = null) {
  const fbo = gl.createFramebuffer();
  gl.bindFramebuffer(gl.FRAMEBUFFER, fbo);
  gl.framebufferTexture2D(gl.FRAMEBUFFER, gl.COLOR_ATTACHMENT0, gl.TEXTURE_2D, texture, level);
  if (depth) gl.framebufferRenderbuffer(gl.FRAMEBUFFER, gl.DEPTH_ATTACHMENT, gl.RENDERBUFFER, depth);
  const status = gl.checkFramebufferStatus(gl.FRAMEBUFFER);
  if (status !== gl.FRAMEBUFFER_COMPLETE) throw new Error(`view: framebuffer incomplete (${status})`);
  return fbo;
}

// The frame's targets: HDR colour (32-bit float) with depth, the quarter-size background and, for
// a frame drawn smaller than the canvas (`scaled`), the 8-bit image that is then stretched onto it.
export class Targets {
  constructor(gl, width, height, scaled = false) {
    this.gl = gl;
    this.width = width;
    this.height = height;
    // the object layer in 32-bit floats, read texel by texel (the preview's is half float: SwiftShader
    // converts each half-float texel it clears, writes and reads, 12 % of a 512² frame of red plastic)
    this.hdr = gl.createTexture();
    gl.bindTexture(gl.TEXTURE_2D, this.hdr);
    gl.texStorage2D(gl.TEXTURE_2D, 1, gl.RGBA32F, width, height);
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MIN_FILTER, gl.NEAREST);
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MAG_FILTER, gl.NEAREST);
    this.depth = gl.createRenderbuffer();
    gl.bindRenderbuffer(gl.RENDERBUFFER, this.depth);
    gl.renderbufferStorage(gl.RENDERBUFFER, gl.DEPTH_COMPONENT24, width, height);
    this.hdrFbo = framebufferFor(gl, this.hdr, 0, this.depth);
    this.backgroundWidth = Math.max(Math.floor(width / 4), 1); // targets.BACKGROUND_SCALE
    this.backgroundHeight = Math.max(Math.floor(height / 4), 1);
    this.background = floatTexture(gl, this.backgroundWidth, this.backgroundHeight, null);
    this.backgroundFbo = framebufferFor(gl, this.background);
    this.ldr = null;
    this.ldrFbo = null;
    if (scaled) [this.ldr, this.ldrFbo] = byteTarget(gl, width, height);
    // the background's view (MaterialView.keepBackground): what `background` was drawn for, and
    // the whole frame's background tone-mapped (8-bit, made when a second frame has the same view)
    this.backgroundView = null;
    this.toned = null;
    this.tonedFbo = null;
    this.tonedView = null;
  }

  // The 8-bit image of the tone-mapped background (made on first use).
  tonedTarget() {
    if (!this.toned) [this.toned, this.tonedFbo] = byteTarget(this.gl, this.width, this.height);
    return this.tonedFbo;
  }

  release() {
    const gl = this.gl;
    gl.deleteFramebuffer(this.hdrFbo);
    gl.deleteFramebuffer(this.backgroundFbo);
    gl.deleteTexture(this.hdr);
    gl.deleteTexture(this.background);
    gl.deleteRenderbuffer(this.depth);
    for (const [fbo, tex] of [[this.ldrFbo, this.ldr], [this.tonedFbo, this.toned]]) {
      if (!tex) continue;
      gl.deleteFramebuffer(fbo);
      gl.deleteTexture(tex);
    }
  }
}

// An RGBA8 texture (width x height) and the framebuffer drawing into it.
function byteTarget(gl, width, height) {
  const tex = gl.createTexture();
  gl.bindTexture(gl.TEXTURE_2D, tex);
  gl.texStorage2D(gl.TEXTURE_2D, 1, gl.RGBA8, width, height);
  return [tex, framebufferFor(gl, tex)];
}

const SETTERS = {
  float: (gl, at, v) => gl.uniform1f(at, v),
  int: (gl, at, v) => gl.uniform1i(at, v),
  vec2: (gl, at, v) => gl.uniform2fv(at, v),
  vec3: (gl, at, v) => gl.uniform3fv(at, v),
  vec4: (gl, at, v) => gl.uniform4fv(at, v),
  "float[]": (gl, at, v) => gl.uniform1fv(at, v),
  mat3: (gl, at, v) => gl.uniformMatrix3fv(at, true, v), // row-major, as numpy writes them
  mat4: (gl, at, v) => gl.uniformMatrix4fv(at, true, v),
};

// Set a uniform the program uses (others are skipped, as the preview's gl.set_uniform does).
export function setUniform(gl, program, name, type, value) {
  const at = gl.getUniformLocation(program, name);
  if (at === null) return;
  const set = SETTERS[type];
  if (!set) throw new Error(`view: uniform ${name} has an unknown type ${type}`);
  set(gl, at, Array.isArray(value) ? value.flat() : value);
}
