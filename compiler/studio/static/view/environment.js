// The environment on the GPU, as the preview makes it (backends/preview/environment_pass.py):
// radiance (box-filtered mips), the GGX-prefiltered chain (level k <-> sqrt(alpha) = k / levels),
// the cosine-prefiltered irradiance and, per alpha, the environment prefiltered at exactly it.
// A named environment comes with them made by the preview itself (the server's
// `env/<name>` and `env/<name>@<alpha>`); a dropped one is prefiltered here with the preview's
// prefilter.frag (slow on a software rasteriser: seconds a texture).
import { environmentFromContainer, fetchBytes } from "./assets.js";
import { floatTexture, framebufferFor } from "./glutil.js";

export class EnvironmentTextures {
  // env: environmentFromContainer(...) or a dropped file's; `alphaUrl(alpha)`: where the server
  // has it prefiltered at alpha (null: prefilter here)
  constructor(gl, env, prefilterProgram, alphaUrl = null) {
    this.gl = gl;
    this.env = env;
    this.program = prefilterProgram;
    this.alphaUrl = alphaUrl;
    this.width = env.width;
    this.height = env.height;
    this.passes = env.passes;
    this.vao = gl.createVertexArray();
    const repeat = [true, false];
    this.radiance = floatTexture(gl, env.width, env.height, env.image, { mipmaps: true, repeat });
    this.prefiltered = floatTexture(gl, env.width, env.height, env.image, { mipmaps: true, repeat });
    const [iw, ih] = this.passes.irradiance_size;
    if (env.levels && env.levels.length) {
      gl.bindTexture(gl.TEXTURE_2D, this.prefiltered);
      env.levels.forEach((data, i) => {
        const level = i + 1;
        const size = [Math.max(env.width >> level, 4), Math.max(env.height >> level, 2)];
        gl.texSubImage2D(gl.TEXTURE_2D, level, 0, 0, size[0], size[1], gl.RGBA, gl.HALF_FLOAT, data);
      });
      this.irradiance = floatTexture(gl, iw, ih, env.irradiance, { repeat });
    } else {
      for (let level = 1; level <= this.passes.prefilter_levels; level++) {
        const size = [Math.max(env.width >> level, 4), Math.max(env.height >> level, 2)];
        const alpha = (level / this.passes.prefilter_levels) ** 2;
        this.prefilterInto(this.prefiltered, level, size, alpha, this.passes.prefilter_samples, false);
      }
      this.irradiance = floatTexture(gl, iw, ih, null, { repeat });
      this.prefilterInto(this.irradiance, 0, [iw, ih], 1.0, this.passes.irradiance_samples, true);
    }
    this.atAlpha = new Map();
  }

  // One pass of prefilter.frag at `alpha` into `level` of `texture`.
  prefilterInto(texture, level, size, alpha, samples, cosine) {
    const gl = this.gl;
    const fbo = framebufferFor(gl, texture, level);
    gl.viewport(0, 0, size[0], size[1]);
    gl.disable(gl.DEPTH_TEST);
    gl.disable(gl.CULL_FACE);
    gl.useProgram(this.program);
    gl.activeTexture(gl.TEXTURE0);
    gl.bindTexture(gl.TEXTURE_2D, this.radiance);
    gl.uniform1i(gl.getUniformLocation(this.program, "pv_env"), 0);
    gl.uniform1i(gl.getUniformLocation(this.program, "pv_samples"), samples);
    gl.uniform2f(gl.getUniformLocation(this.program, "pv_env_size"), this.width, this.height);
    gl.uniform1f(gl.getUniformLocation(this.program, "pv_alpha"), alpha);
    gl.uniform1i(gl.getUniformLocation(this.program, "pv_cosine"), cosine ? 1 : 0);
    gl.bindVertexArray(this.vao);
    gl.drawArrays(gl.TRIANGLES, 0, 3);
    gl.bindFramebuffer(gl.FRAMEBUFFER, null);
    gl.deleteFramebuffer(fbo);
  }

  // The environment prefiltered at exactly `alpha` (full resolution, one level), made once.
  async prefilteredAt(alpha) {
    const key = alpha.toFixed(6);
    if (!this.atAlpha.has(key)) this.atAlpha.set(key, this.makeAt(alpha, key));
    return this.atAlpha.get(key);
  }

  async makeAt(alpha, key) {
    const repeat = [true, false];
    if (this.alphaUrl) {
      const { image } = environmentFromContainer(await fetchBytes(this.alphaUrl(key)));
      return floatTexture(this.gl, this.width, this.height, image, { repeat });
    }
    const tex = floatTexture(this.gl, this.width, this.height, null, { repeat });
    this.prefilterInto(tex, 0, [this.width, this.height], alpha, this.passes.prefilter_samples, false);
    return tex;
  }

  async release() {
    const gl = this.gl;
    const made = await Promise.allSettled(this.atAlpha.values());
    for (const m of made) if (m.status === "fulfilled") gl.deleteTexture(m.value);
    for (const tex of [this.radiance, this.prefiltered, this.irradiance]) gl.deleteTexture(tex);
    gl.deleteVertexArray(this.vao);
    this.atAlpha.clear();
  }
}
