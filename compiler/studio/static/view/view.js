// The studio's live material view: cnlmc's own GLSL ES 3.00 (the GLSL backend's library in the
// preview's `splitsum` shader, from cnlmc.studio.view_payload) drawn in WebGL2 the way
// `cnlmc preview` draws it: object pass into a half-float target, the blurred environment
// behind it at quarter size, then edge filter, exposure, ACES and sRGB (tonemap.frag).
//
//   const view = new MaterialView(canvas, { dataUrl: "/view-data", filesUrl: "/files" });
//   await view.show([payload]);            // "or" variants: several payloads side by side
//   canvas.addEventListener("frame", (e) => console.log(e.detail.ms));
import { decodeFloats, environmentFromContainer, fetchBytes, fetchText, meshFromContainer } from "./assets.js";
import { Orbit, invert } from "./camera.js";
import { EnvironmentTextures } from "./environment.js";
import { Targets, compileProgram, floatTexture, setUniform } from "./glutil.js";
import { meshFromFile, environmentFromFile } from "./loaders.js";
import { afterPaint } from "./trace.js";

const IDENTITY3 = [1, 0, 0, 0, 1, 0, 0, 0, 1];
const IDENTITY4 = [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1];
const ATTRIBUTES = [["in_position", 3, 0], ["in_normal", 3, 12], ["in_tangent", 3, 24], ["in_uv", 2, 36]];
const STRIDE = 44;
const tableKey = (table) => table.key ?? table.data; // the server's digest, or the data itself
// The quick frame (see show): our choices. Its draw should take at most QUICK_BUDGET_MS (of the
// 150 ms from a keystroke to the picture, the rest is the socket, the server, the page and the
// wait for the screen); never below MIN_QUICK_SCALE of the canvas (128² of 512²: the material
// still reads, its highlight and edge softer — looked at for plastic, oak and glass).
const QUICK_BUDGET_MS = 40;
const MIN_QUICK_SCALE = 0.25;
// A full frame that takes at most FULL_BUDGET_MS is drawn at once, without a quick frame first (of
// the 150 ms from a keystroke to the picture, 30-60 ms are the editor, the socket, the server and
// the wait for the screen): the quick frame and its trip to the screen would only delay it, by
// 40-50 ms on SwiftShader (docs/studio_view.md, "Latency"). Our choice.
const FULL_BUDGET_MS = 90;
// show()'s full frame is drawn in bands of rows of about BAND_MS each (at most MAX_BANDS, as many
// when its cost is not known yet), the page's tasks run between them: a key typed meanwhile waits
// for one band, not the whole frame. Our choice; each band costs a read-back and the mesh again
// (4 bands: +20-75 % of a 512² frame on SwiftShader), so a frame that fits one band is one band.
const BAND_MS = 60;
const MAX_BANDS = 4;

const RECT_PAD = 2; // render.py Renderer.RECT_PAD: the edge filter reads a pixel's neighbours

// The pixel rectangle [x, y, w, h] (window coordinates) holding the box [lo, hi] seen through the
// row-major `viewProjection` drawn into `cell`, padded and clipped to the cell; the whole cell
// when a corner is at or behind the camera (targets.screen_rect).
export function screenRect(lo, hi, viewProjection, cell, pad = RECT_PAD) {
  const m = viewProjection;
  let [x0, y0, x1, y1] = [Infinity, Infinity, -Infinity, -Infinity];
  for (const x of [lo[0], hi[0]]) {
    for (const y of [lo[1], hi[1]]) {
      for (const z of [lo[2], hi[2]]) {
        const w = m[12] * x + m[13] * y + m[14] * z + m[15];
        if (!(w > 1e-9)) return cell;
        const px = cell[0] + ((m[0] * x + m[1] * y + m[2] * z + m[3]) / w * 0.5 + 0.5) * cell[2];
        const py = cell[1] + ((m[4] * x + m[5] * y + m[6] * z + m[7]) / w * 0.5 + 0.5) * cell[3];
        [x0, y0, x1, y1] = [Math.min(x0, px), Math.min(y0, py), Math.max(x1, px), Math.max(y1, py)];
      }
    }
  }
  const left = Math.max(Math.floor(x0) - pad, cell[0]), bottom = Math.max(Math.floor(y0) - pad, cell[1]);
  const right = Math.min(Math.ceil(x1) + pad, cell[0] + cell[2]), top = Math.min(Math.ceil(y1) + pad, cell[1] + cell[3]);
  return [left, bottom, Math.max(right - left, 0), Math.max(top - bottom, 0)];
}

// `cell` outside `rect` as up to four non-empty rectangles: below, above, left, right (strips_around).
function stripsAround(rect, cell) {
  const [x, y, w, h] = rect;
  const [cx, cy, cw, ch] = cell;
  const strips = [[cx, cy, cw, y - cy], [cx, y + h, cw, cy + ch - y - h], [cx, y, x - cx, h], [x + w, y, cx + cw - x - w, h]];
  return strips.filter((s) => s[2] > 0 && s[3] > 0);
}

// `rect` cut to rows [rows[0], rows[1]) (an empty rectangle when they miss it).
function inRows(rect, rows) {
  const bottom = Math.max(rect[1], rows[0]), top = Math.min(rect[1] + rect[3], rows[1]);
  return [rect[0], bottom, rect[2], Math.max(top - bottom, 0)];
}

// The scale of the quick frame for a frame that costs `msPerPixel` (null: not measured yet) on
// `pixels`: 1 (no quick frame) when the full frame fits `fullBudgetMs` (or the quick budget), else
// the size whose frame fits `budgetMs`, between MIN_QUICK_SCALE and `largest`.
export function quickScaleFor(msPerPixel, pixels, largest, budgetMs = QUICK_BUDGET_MS, fullBudgetMs = FULL_BUDGET_MS) {
  if (!largest || largest >= 1) return 1;
  if (msPerPixel === null || msPerPixel === undefined) return largest;
  const full = msPerPixel * pixels;
  if (full <= Math.max(budgetMs, fullBudgetMs)) return 1;
  return Math.min(largest, Math.max(MIN_QUICK_SCALE, Math.sqrt(budgetMs / full)));
}

// The number of bands of show()'s full frame for a frame that costs `msPerPixel` (null: not
// measured yet) on `pixels`: about `bandMs` each, between 1 and MAX_BANDS.
export function bandsFor(msPerPixel, pixels, bandMs = BAND_MS) {
  if (msPerPixel === null || msPerPixel === undefined) return MAX_BANDS;
  return Math.min(MAX_BANDS, Math.max(1, Math.ceil((msPerPixel * pixels) / bandMs)));
}
const KEPT_MAPS = 24; // our choice: 8 materials' worth of maps (512² half-float RGBA + mips: 2.7 MB each)
const KEPT_TABLES = 64; // our choice: split-sum tables (96 x 1 or 8 texels) of 32 recent looks

export class MaterialView {
  // quickScale: show() first draws the new material at most at this fraction of the canvas size
  // (stretched onto it), smaller when its frames have been slower (quickScaleFor), then the full
  // frame; null: the full frame only. (A software rasteriser shades 4x fewer pixels at 0.5.)
  // trace: a Trace (trace.js) that show() marks its stages in, for the edit number it is given.
  constructor(canvas, { dataUrl = "/view-data", filesUrl = "/files", quickScale = 0.5, trace = null } = {}) {
    this.canvas = canvas;
    this.dataUrl = dataUrl.replace(/\/$/, "");
    this.filesUrl = filesUrl.replace(/\/$/, "");
    const gl = canvas.getContext("webgl2", { antialias: false, alpha: false, preserveDrawingBuffer: true });
    if (!gl) throw new Error("view: this browser has no WebGL2");
    if (!gl.getExtension("EXT_color_buffer_float")) throw new Error("view: WebGL2 without EXT_color_buffer_float");
    this.gl = gl;
    this.exposure = 1;
    this.quickScale = quickScale;
    this.costs = new Map(); // the shown programs' keys -> ms per pixel of their latest frame
    this.trace = trace;
    this.sized = new Map(); // "w x h" -> Targets
    this.orbit = new Orbit();
    this.orbit.attach(canvas, () => this.requestDraw());
    this.programs = new Map(); // shader key (or source) -> program (one per shader, kept while the view lives)
    this.maps = new Map(); // file -> texture
    this.tables = new Map(); // table key (or data) -> texture: a look seen before is not uploaded again
    this.entries = []; // what is shown: per variant {payload, program, textures}
    this.meshName = "sphere";
    this.envName = "studio";
    this.pending = null;
    this.ready = this.init();
  }

  async init() {
    const shader = (name) => fetchText(`${this.dataUrl}/shader/${name}`);
    const [vertex, prefilter, background, tonemap] = await Promise.all(
      ["fullscreen.vert", "prefilter.frag", "background.frag", "tonemap.frag"].map(shader));
    const gl = this.gl;
    this.prefilterProgram = compileProgram(gl, vertex, prefilter);
    this.backgroundProgram = compileProgram(gl, vertex, background);
    this.tonemapProgram = compileProgram(gl, vertex, tonemap);
    // outside the object's rectangle the background alone (tonemap.frag's PV_BACKGROUND_ONLY)
    const [version, rest] = [tonemap.slice(0, tonemap.indexOf("\n") + 1), tonemap.slice(tonemap.indexOf("\n") + 1)];
    this.backgroundOnlyProgram = compileProgram(gl, vertex, `${version}#define PV_BACKGROUND_ONLY\n${rest}`);
    this.emptyVao = gl.createVertexArray();
    await Promise.all([this.loadMesh("sphere"), this.loadEnvironment("studio")]);
  }

  // -- what is drawn
  // Show these payloads; resolves with the frame time, or null when a later show() overtook it
  // (edits arrive faster than their textures: the newest wins, an older one never replaces it).
  // `edit`: the number its stages are marked with in the trace.
  async show(payloads, { edit = null } = {}) {
    const mark = (stage, more = {}) => this.trace && this.trace.mark(stage, edit, more);
    const ticket = (this.shows = (this.shows || 0) + 1);
    await this.ready;
    const list = Array.isArray(payloads) ? payloads : [payloads];
    const entries = [];
    for (const payload of list) entries.push(await this.entry(payload));
    await this.resolvePrefiltered(entries);
    while (entries.some((e) => e.env !== this.environment)) await this.resolvePrefiltered(entries); // changed meanwhile
    if (ticket !== this.shows) {
      return null;
    }
    this.entries = entries;
    this.pruneTextures();
    mark("setup");
    const pixels = this.canvas.width * this.canvas.height;
    const cost = this.costs.get(this.shownKey());
    const quick = quickScaleFor(cost, pixels, this.quickScale);
    if (quick < 1) {
      mark("quick-drawn", { scale: quick, ms: this.draw(quick) });
      await new Promise((resolve) => afterPaint(resolve)); // shown first
      mark("quick-shown");
      if (ticket !== this.shows) return null;
    }
    const bands = bandsFor(cost, pixels);
    const ms = await this.drawInBands(ticket, bands);
    if (ms === null) return null;
    mark("drawn", { scale: 1, ms, bands });
    afterPaint(() => mark("shown"));
    return ms;
  }

  // Map and table textures beyond the most recently used KEPT_MAPS / KEPT_TABLES go (a long
  // session of edits would pile them up; undo and edits back and forth find the recent ones).
  pruneTextures() {
    const maps = new Set(this.entries.flatMap((e) => Object.values(e.payload.maps).map((m) => m.file)));
    const tables = new Set(this.entries.flatMap((e) => Object.values(e.payload.tables).map(tableKey)));
    this.prune(this.maps, maps, KEPT_MAPS);
    this.prune(this.tables, tables, KEPT_TABLES);
  }

  prune(textures, used, kept) {
    let spare = textures.size - kept;
    for (const [key, tex] of textures) { // oldest first (a texture handed out is re-inserted)
      if (spare <= 0) break;
      if (used.has(key)) continue;
      this.gl.deleteTexture(tex);
      textures.delete(key);
      spare -= 1;
    }
  }

  // What the shown frame's cost depends on: its programs.
  shownKey() {
    return this.entries.map((e) => e.programKey).join("\u0001");
  }

  async entry(payload) {
    const [program, programKey] = this.program(payload);
    const tables = {};
    for (const [name, t] of Object.entries(payload.tables)) tables[name] = this.tableTexture(t);
    const maps = {};
    for (const [name, m] of Object.entries(payload.maps)) maps[name] = await this.mapTexture(m);
    return { payload, program, programKey, tables, maps };
  }

  tableTexture(table) {
    const key = tableKey(table);
    let tex = this.tables.get(key);
    if (!tex) tex = floatTexture(this.gl, table.width, table.height, decodeFloats(table.data));
    this.tables.delete(key);
    this.tables.set(key, tex); // the most recently used last
    return tex;
  }

  // Each entry's environment textures prefiltered at exactly its alphas (in the current environment).
  async resolvePrefiltered(entries) {
    const env = this.environment;
    for (const entry of entries) {
      entry.env = env;
      entry.prefiltered = {};
      for (const [name, alpha] of Object.entries(entry.payload.prefilter)) {
        entry.prefiltered[name] = await env.prefilteredAt(alpha);
      }
    }
  }

  // The payload's program and its key: made once per shader (its key from the server, or its source).
  program(payload) {
    const key = payload.shader ?? `${payload.vertex}\u0000${payload.fragment}`;
    if (!this.programs.has(key)) this.programs.set(key, compileProgram(this.gl, payload.vertex, payload.fragment));
    return [this.programs.get(key), key];
  }

  async mapTexture(map) {
    let tex = this.maps.get(map.file);
    if (!tex) {
      const bits = new Uint16Array(await fetchBytes(`${this.filesUrl}/${encodeURIComponent(map.file)}`));
      tex = floatTexture(this.gl, map.width, map.height, bits, { mipmaps: true, repeat: [true, true] });
    }
    this.maps.delete(map.file);
    this.maps.set(map.file, tex); // the most recently used last
    return tex;
  }

  async setMesh(nameOrArrayBuffer) {
    await this.ready;
    if (typeof nameOrArrayBuffer === "string") await this.loadMesh(nameOrArrayBuffer);
    else this.useMesh(meshFromFile(nameOrArrayBuffer));
    return this.draw();
  }

  async loadMesh(name) {
    this.useMesh(meshFromContainer(await fetchBytes(`${this.dataUrl}/mesh/${encodeURIComponent(name)}`)));
    this.meshName = name;
  }

  useMesh(mesh) {
    const gl = this.gl;
    if (this.mesh) {
      gl.deleteBuffer(this.mesh.vbo);
      gl.deleteBuffer(this.mesh.ibo);
      for (const vao of this.mesh.vaos.values()) gl.deleteVertexArray(vao);
    }
    const vbo = gl.createBuffer();
    gl.bindBuffer(gl.ARRAY_BUFFER, vbo);
    gl.bufferData(gl.ARRAY_BUFFER, mesh.vertices, gl.STATIC_DRAW);
    const ibo = gl.createBuffer();
    gl.bindBuffer(gl.ELEMENT_ARRAY_BUFFER, ibo);
    gl.bufferData(gl.ELEMENT_ARRAY_BUFFER, mesh.indices, gl.STATIC_DRAW);
    this.mesh = { ...mesh, vbo, ibo, count: mesh.indices.length, vaos: new Map() };
  }

  vertexArray(program) {
    const gl = this.gl;
    if (!this.mesh.vaos.has(program)) {
      const vao = gl.createVertexArray();
      gl.bindVertexArray(vao);
      gl.bindBuffer(gl.ARRAY_BUFFER, this.mesh.vbo);
      for (const [name, size, offset] of ATTRIBUTES) {
        const at = gl.getAttribLocation(program, name);
        if (at < 0) continue;
        gl.enableVertexAttribArray(at);
        gl.vertexAttribPointer(at, size, gl.FLOAT, false, STRIDE, offset);
      }
      gl.bindBuffer(gl.ELEMENT_ARRAY_BUFFER, this.mesh.ibo);
      gl.bindVertexArray(null);
      this.mesh.vaos.set(program, vao);
    }
    return this.mesh.vaos.get(program);
  }

  async setEnvironment(nameOrFile) {
    await this.ready;
    if (typeof nameOrFile === "string") await this.loadEnvironment(nameOrFile);
    else this.useEnvironment(await environmentFromFile(nameOrFile, this.environment.env), null);
    await this.resolvePrefiltered(this.entries);
    return this.draw();
  }

  async loadEnvironment(name) {
    const url = `${this.dataUrl}/env/${encodeURIComponent(name)}`;
    this.useEnvironment(environmentFromContainer(await fetchBytes(url)), (alpha) => `${url}@${alpha}`);
    this.envName = name;
  }

  useEnvironment(env, alphaUrl) {
    if (this.environment) this.environment.release();
    this.environment = new EnvironmentTextures(this.gl, env, this.prefilterProgram, alphaUrl);
  }

  setExposure(ev) {
    this.exposure = 2 ** Number(ev);
    this.requestDraw();
  }

  // -- a frame
  requestDraw() {
    if (this.pending) return;
    this.pending = requestAnimationFrame(() => {
      this.pending = null;
      this.draw();
    });
  }

  // The targets of a frame this size, made once: one set for the canvas's size, one for the latest
  // quick frame's (a quick frame of another size, or a resized canvas, replaces its kind's: each
  // quick size made its own and kept it while the view lived).
  targetsFor(width, height) {
    const scaled = width !== this.canvas.width || height !== this.canvas.height;
    const key = `${width}x${height}${scaled ? " scaled" : ""}`;
    if (!this.sized.has(key)) {
      for (const [k, t] of this.sized) {
        if (Boolean(t.ldr) !== scaled) continue;
        t.release();
        this.sized.delete(k);
      }
      this.sized.set(key, new Targets(this.gl, width, height, scaled));
    }
    return this.sized.get(key);
  }

  // Draw a frame (at `scale` of the canvas size, stretched onto it when < 1); returns its time in ms
  // and dispatches the "frame" event {ms, scale}.
  draw(scale = 1) {
    return this.frameSteps(scale, 1).next().value;
  }

  // show()'s full frame, in `bands` bands with the page's tasks between them: a key typed
  // meanwhile waits for a band, not the whole frame, and a newer show() stops it. Its time in ms,
  // or null when a newer show() came; a whole frame drawn meanwhile (an orbit) counts as it.
  async drawInBands(ticket, bands = MAX_BANDS) {
    const steps = this.frameSteps(1, bands);
    let step = steps.next(); // the first band: the frame's number is taken there
    const frame = this.frameNumber;
    while (!step.done) {
      await new Promise((resolve) => setTimeout(resolve, 0));
      if (ticket !== this.shows) return null;
      if (this.frameNumber !== frame) return this.lastFrameMs;
      step = steps.next();
    }
    return step.value;
  }

  // A frame as `bands` steps (a generator: it yields between bands, returns the frame's ms): the
  // clear and the background first, then per band of rows the objects and the tone map (up to the
  // band's last row but one: the edge filter reads the next row, drawn with the next band).
  *frameSteps(scale, bands) {
    const frame = (this.frameNumber = (this.frameNumber || 0) + 1);
    let start = performance.now(), ms = 0;
    const gl = this.gl;
    const width = Math.max(1, Math.round(this.canvas.width * scale));
    const height = Math.max(1, Math.round(this.canvas.height * scale));
    const t = (this.targets = this.targetsFor(width, height));
    gl.bindFramebuffer(gl.FRAMEBUFFER, t.hdrFbo);
    gl.viewport(0, 0, width, height);
    gl.clearColor(0, 0, 0, 0);
    gl.clearDepth(1);
    gl.clear(gl.COLOR_BUFFER_BIT | gl.DEPTH_BUFFER_BIT);
    const cells = Math.max(this.entries.length, 1);
    const cameras = [];
    for (let i = 0; i < cells; i++) {
      const x0 = Math.round((i * width) / cells), x1 = Math.round(((i + 1) * width) / cells);
      const cell = [x0, 0, x1 - x0, height];
      cameras.push([cell, this.orbit.camera(this.mesh.lo, this.mesh.hi, cell[2] / cell[3])]);
    }
    const entries = this.entries;
    const kept = this.keepBackground(t, cameras);
    const rects = cameras.map(([cell, camera], i) => [cell, entries[i] ? this.objectRect(cell, camera) : null]);
    let toned = 0;
    for (let band = 0; band < bands; band++) {
      const last = band === bands - 1;
      const rows = [Math.round((band * height) / bands), Math.round(((band + 1) * height) / bands)];
      cameras.forEach(([cell, camera], i) => entries[i] && this.drawObject(entries[i], cell, camera, rows));
      const upTo = last ? height : rows[1] - 1;
      this.drawTonemap(rects, [toned, upTo], kept);
      toned = upTo;
      if (last && t.ldr) {
        gl.bindFramebuffer(gl.READ_FRAMEBUFFER, t.ldrFbo);
        gl.bindFramebuffer(gl.DRAW_FRAMEBUFFER, null);
        gl.blitFramebuffer(0, 0, width, height, 0, 0, this.canvas.width, this.canvas.height, gl.COLOR_BUFFER_BIT, gl.LINEAR);
        gl.bindFramebuffer(gl.FRAMEBUFFER, null);
      }
      gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, new Uint8Array(4)); // the band is finished
      ms += performance.now() - start;
      if (!last) {
        yield band;
        start = performance.now();
      }
    }
    this.lastFrameMs = ms;
    if (frame === this.frameNumber) this.costs.set(this.shownKey(), ms / (width * height));
    this.canvas.dispatchEvent(new CustomEvent("frame", { detail: { ms, scale } }));
    return ms;
  }

  // The object of `entry` into `cell` (only rows [rows[0], rows[1]) when given).
  drawObject(entry, cell, camera, rows = null) {
    const gl = this.gl;
    const { payload, program } = entry;
    const env = this.environment;
    const textures = { ...entry.maps, ...entry.tables, ...entry.prefiltered, pv_env_irradiance: env.irradiance };
    gl.bindFramebuffer(gl.FRAMEBUFFER, this.targets.hdrFbo);
    gl.viewport(...cell);
    gl.useProgram(program);
    textures.pv_env = env.radiance;
    textures.pv_env_prefiltered = env.prefiltered;
    let unit = 0;
    for (const [name, tex] of Object.entries(textures)) {
      gl.activeTexture(gl.TEXTURE0 + unit);
      gl.bindTexture(gl.TEXTURE_2D, tex);
      setUniform(gl, program, name, "int", unit);
      unit += 1;
    }
    for (const u of payload.uniforms) setUniform(gl, program, u.name, u.type, u.value);
    const key = env.env;
    setUniform(gl, program, "pv_prefilter_levels", "float", env.passes.prefilter_levels);
    setUniform(gl, program, "pv_env_intensity", "float", 1.0);
    setUniform(gl, program, "pv_env_size", "vec2", [env.width, env.height]);
    setUniform(gl, program, "pv_model", "mat4", IDENTITY4);
    setUniform(gl, program, "pv_normal_matrix", "mat3", IDENTITY3);
    setUniform(gl, program, "pv_view_projection", "mat4", camera.viewProjection);
    setUniform(gl, program, "pv_camera_position", "vec3", camera.eye);
    setUniform(gl, program, "pv_key_direction", "vec3", key.key_direction);
    setUniform(gl, program, "pv_key_irradiance", "vec3", [key.key_irradiance, key.key_irradiance, key.key_irradiance]);
    const meshForm = this.mesh.closed ? "closed" : "open";
    const metresPerUv = this.mesh.metres_per_uv || payload.uv_unit_m;
    for (const u of (payload.mesh_uniforms || {})[meshForm] || []) {
      // computed on a stand-in at 1 m per UV unit: this mesh's bounding sphere and UV scale go in
      const value = {
        cnlm_sss_centre: this.mesh.centre,
        cnlm_sss_radius: this.mesh.radius,
        pv_flake_area: u.value / (metresPerUv * metresPerUv),
      }[u.name] ?? u.value;
      setUniform(gl, program, u.name, u.type, value);
    }
    if (payload.glass) {
      setUniform(gl, program, "pv_glass_centre", "vec3", this.mesh.centre);
      setUniform(gl, program, "pv_glass_radius", "float", this.mesh.radius);
      setUniform(gl, program, "pv_glass_reference", "float", payload.glass_reference);  // the glass's depth, object units
      setUniform(gl, program, "pv_glass_thin", "int", this.mesh.closed ? 0 : 1);
    }
    gl.enable(gl.DEPTH_TEST);
    if (this.mesh.closed) gl.enable(gl.CULL_FACE);
    else gl.disable(gl.CULL_FACE);
    gl.bindVertexArray(this.vertexArray(program));
    if (rows) {
      gl.enable(gl.SCISSOR_TEST);
      gl.scissor(cell[0], rows[0], cell[2], rows[1] - rows[0]);
    }
    gl.drawElements(gl.TRIANGLES, this.mesh.count, gl.UNSIGNED_INT, 0);
    gl.bindVertexArray(null);
    gl.disable(gl.SCISSOR_TEST);
    gl.disable(gl.CULL_FACE);
    gl.disable(gl.DEPTH_TEST);
  }

  // The frame's background (the blurred environment behind the objects, and around them the
  // tone-mapped background alone) depends on the view only: the cells' cameras, the environment
  // and the exposure, not the materials. A frame of a new view draws it; the next frame of the same
  // view keeps the blurred image and tone-maps the whole background once into `t.toned`; from then
  // on a frame (an edit) copies the pixels around its objects from there (the same program on the
  // same inputs: the same pixels) instead of tone-mapping them again. True when `t.toned` holds them.
  keepBackground(t, cameras) {
    const view = JSON.stringify([this.exposure, cameras.map(([cell, camera]) => [cell, camera.viewProjection])]);
    if (view !== t.backgroundView || this.environment !== t.backgroundEnv) {
      this.drawBackground(cameras);
      [t.backgroundView, t.backgroundEnv, t.tonedView] = [view, this.environment, null];
      return false;
    }
    if (t.tonedView !== view) {
      const gl = this.gl;
      this.bindTonemapInputs(t.tonedTarget());
      this.useTonemap(this.backgroundOnlyProgram);
      gl.drawArrays(gl.TRIANGLES, 0, 3);
      t.tonedView = view;
    }
    return true;
  }

  drawBackground(cameras) {
    const gl = this.gl, t = this.targets, prog = this.backgroundProgram;
    gl.bindFramebuffer(gl.FRAMEBUFFER, t.backgroundFbo);
    gl.useProgram(prog);
    gl.activeTexture(gl.TEXTURE0);
    gl.bindTexture(gl.TEXTURE_2D, this.environment.radiance);
    setUniform(gl, prog, "pv_env", "int", 0);
    setUniform(gl, prog, "pv_env_intensity", "float", 1.0);
    setUniform(gl, prog, "pv_background_lod", "float", this.environment.passes.background_lod);
    gl.bindVertexArray(this.emptyVao);
    const sx = t.backgroundWidth / t.width, sy = t.backgroundHeight / t.height;
    for (const [cell, camera] of cameras) {
      const x0 = Math.round(cell[0] * sx), x1 = Math.round((cell[0] + cell[2]) * sx);
      gl.viewport(x0, 0, Math.max(x1 - x0, 1), t.backgroundHeight);
      setUniform(gl, prog, "pv_inverse_view_projection", "mat4", invert(camera.viewProjection));
      gl.drawArrays(gl.TRIANGLES, 0, 3);
    }
  }

  // Where the object of `cell` can be: the mesh's bounding box projected (Renderer.drawn_rect).
  objectRect(cell, camera) {
    return screenRect(this.mesh.lo, this.mesh.hi, camera.viewProjection, cell);
  }

  // Edge filter, background, exposure, ACES and sRGB as the preview's tonemap() runs them: the
  // whole pass inside each cell's object rectangle, the background alone around it (no rectangle:
  // the whole cell). `cells`: [[cell, rect or null], ...]; `rows`: only rows [rows[0], rows[1]).
  // `kept`: the background around the rectangles is copied from `targets.toned` (keepBackground).
  drawTonemap(cells, rows = null, kept = false) {
    const gl = this.gl, t = this.targets;
    this.bindTonemapInputs(t.ldrFbo); // null (the canvas) for a full-size frame
    gl.enable(gl.SCISSOR_TEST);
    const within = (r) => (rows ? inRows(r, rows) : r);
    this.useTonemap(this.tonemapProgram);
    for (const [, rect] of cells) {
      const part = rect && within(rect);
      if (!part || part[2] <= 0 || part[3] <= 0) continue;
      gl.scissor(...part);
      gl.drawArrays(gl.TRIANGLES, 0, 3);
    }
    const strips = cells.flatMap(([cell, rect]) => (rect === null ? [cell] : stripsAround(rect, cell)).map(within));
    const around = strips.filter((s) => s[2] > 0 && s[3] > 0);
    gl.disable(gl.SCISSOR_TEST);
    if (kept) {
      gl.bindFramebuffer(gl.READ_FRAMEBUFFER, t.tonedFbo);
      for (const [x, y, w, h] of around) gl.blitFramebuffer(x, y, x + w, y + h, x, y, x + w, y + h, gl.COLOR_BUFFER_BIT, gl.NEAREST);
      gl.bindFramebuffer(gl.FRAMEBUFFER, t.ldrFbo);
      return;
    }
    gl.enable(gl.SCISSOR_TEST);
    this.useTonemap(this.backgroundOnlyProgram);
    for (const strip of around) {
      gl.scissor(...strip);
      gl.drawArrays(gl.TRIANGLES, 0, 3);
    }
    gl.disable(gl.SCISSOR_TEST);
  }

  // The tone map's target (`fbo`, the whole frame's viewport) and inputs: the object layer, the
  // blurred background.
  bindTonemapInputs(fbo) {
    const gl = this.gl, t = this.targets;
    gl.bindFramebuffer(gl.FRAMEBUFFER, fbo);
    gl.viewport(0, 0, t.width, t.height);
    gl.activeTexture(gl.TEXTURE0);
    gl.bindTexture(gl.TEXTURE_2D, t.hdr);
    gl.activeTexture(gl.TEXTURE1);
    gl.bindTexture(gl.TEXTURE_2D, t.background);
    gl.bindVertexArray(this.emptyVao);
  }

  useTonemap(prog) {
    const gl = this.gl;
    gl.useProgram(prog);
    setUniform(gl, prog, "pv_hdr", "int", 0);
    setUniform(gl, prog, "pv_background_image", "int", 1);
    setUniform(gl, prog, "pv_exposure", "float", this.exposure);
    setUniform(gl, prog, "pv_curve", "int", 0);
    setUniform(gl, prog, "pv_edge_aa", "int", 1);
    setUniform(gl, prog, "pv_background", "int", 1);
  }

  // -- what the last frame shows
  // RGBA bytes of the canvas, top row first.
  readPixels() {
    const gl = this.gl, w = this.canvas.width, h = this.canvas.height;
    const raw = new Uint8Array(w * h * 4);
    gl.bindFramebuffer(gl.FRAMEBUFFER, null);
    gl.readPixels(0, 0, w, h, gl.RGBA, gl.UNSIGNED_BYTE, raw);
    const out = new Uint8Array(raw.length);
    for (let y = 0; y < h; y++) out.set(raw.subarray((h - 1 - y) * w * 4, (h - y) * w * 4), y * w * 4);
    return out;
  }

  // Mean [r, g, b] of the last frame, 0..1 (sRGB-encoded values).
  meanColour() {
    const px = this.readPixels();
    const sum = [0, 0, 0];
    for (let i = 0; i < px.length; i += 4) { sum[0] += px[i]; sum[1] += px[i + 1]; sum[2] += px[i + 2]; }
    const n = px.length / 4;
    return sum.map((s) => s / (255 * n));
  }
}
