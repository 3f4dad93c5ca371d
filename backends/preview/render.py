"""The preview renderer: the GLSL backend's BSDF on a mesh, lit by a key light and an HDR
environment, rendered offscreen with MSAA, tone mapped to sRGB.

    r = Renderer(size=512)
    frame = r.render(material, mesh="sphere", tier="fis16")   # -> Frame(rgba8, hdr, ms)
"""

from __future__ import annotations

import hashlib
import json
import time
from dataclasses import dataclass, field
from functools import cached_property

import numpy as np

from cnlmc.bsdf.sampling import lobe_shares

from . import gl
from .albedo_tables import split_fitted
from .camera import Camera, framing_camera
from .environment import Environment, environment
from .meshes import Mesh, fit, mesh_by_name, sphere_for_pixels
from .resources import Resources, source_key
from .tiers import DEFAULT_TIER, Tier, parse_tier

MICROFACET = ("dielectric", "conductor", "glass")
GLSL_OPTION_KEYS = ("fresnel", "multiscatter", "specialize")
PREFILTER_LEVELS = 5
PREFILTER_SAMPLES = 256
IRRADIANCE_SIZE, IRRADIANCE_SAMPLES = (64, 32), 2048
MAP_SIZE = 512
#: MSAA costs 4x the object pass on llvmpipe (docs/preview.md): off, with the tone map's edge filter.
DEFAULT_MSAA = 0
#: the background (the environment blurred at mip 3) is drawn at 1/4 resolution and upsampled.
BACKGROUND_SCALE = 4


@dataclass
class Frame:
    rgba: np.ndarray  # (H, W, 4) uint8, sRGB, top row first; alpha = coverage
    hdr: np.ndarray | None  # (H, W, 4) float32 linear radiance before tone mapping (top row first)
    ms: float  # GPU frame time (draw + resolve + tone map, finished), milliseconds
    tier: str = ""
    notes: list = field(default_factory=list)


@dataclass(frozen=True)
class MaterialShader:
    name: str
    library: str
    plan: dict
    samplers: list  # [{"name", "role", ...}] from the sidecar
    notes: list

    @cached_property
    def key(self) -> str:
        """A digest of what the object program is made from: programs are cached by it."""
        return source_key(self.name, self.library, json.dumps(self.plan, sort_keys=True, default=str))


def material_plan(sidecar: dict) -> dict:
    """What the tiers need to know, read from the GLSL sidecar."""
    model = sidecar["model"]
    base = model["base"]
    uniforms = {u["name"] for u in sidecar["uniforms"]}
    coat = "cnlm_coat_ior" in uniforms
    plan = {
        "base": base,
        "microfacet": base in MICROFACET,
        "anisotropic": bool(model.get("anisotropic")) and base in MICROFACET,
        "coat": coat,
        "coat_color": "cnlm_coat_color" in uniforms,
        "normal_map": any(s["role"] == "normal" for s in sidecar["samplers"]),
        "roughness_map": any(s["role"] == "roughness" for s in sidecar["samplers"]),
    }
    plan["strategy"] = [repr(float(x)) for x in lobe_shares(base, coat)]
    plan["summary"] = " + ".join(k for k in ("base", "anisotropic", "coat", "normal_map") if plan[k] is True) or base
    plan["summary"] = f"{base}" + "".join(f", {k}" for k in ("anisotropic", "coat", "normal_map") if plan[k])
    return plan


def shader_options(glsl_options: dict | None) -> dict:
    """The GLSL backend's options that change a material's shader."""
    return {k: str(v) for k, v in (glsl_options or {}).items() if k in GLSL_OPTION_KEYS}


def shader_key(material: dict, glsl_options: dict | None) -> str:
    """What a material's shader is cached by: the material's content and the GLSL options."""
    text = json.dumps([material, shader_options(glsl_options)], sort_keys=True, default=str)
    return hashlib.sha256(text.encode()).hexdigest()


def material_shader(material: dict, glsl_options: dict | None = None) -> MaterialShader:
    """The library form of one material, made anew (Renderer.shader keeps the ones it uses)."""
    from cnlmc.backends import glsl

    opts = shader_options(glsl_options)
    ir = {"ir_version": 1, "materials": [material], "diagnostics": []}
    result = glsl.emit(ir, {**opts, "form": "library"})
    files = {a.name: a.content for a in result.artifacts}
    name = material["name"]
    sidecar = json.loads(files[f"{name}.glsl.json"])
    plan = material_plan(sidecar)
    plan["split_fitted"] = split_fitted(material, plan["roughness_map"])  # split.glsl.j2: two lookups
    return MaterialShader(name, files[f"{name}.glsl"], plan, sidecar["samplers"], [n.text() for n in result.notes])


# ------------------------------------------------------------------ GPU resources


class EnvResources:
    """Environment textures: radiance (mip-mapped), GGX-prefiltered levels, and on demand the
    environment prefiltered at one alpha and the irradiance map (made in `resources`' context)."""

    def __init__(self, env: Environment, resources: Resources):
        self.env = env
        self.resources = resources
        self.radiance = resources.float_texture(env.image, repeat=(True, False))
        self.size = (env.image.shape[1], env.image.shape[0])
        self.mean = env.mean_radiance
        self.prefiltered = self._prefilter()
        self._at_alpha: dict = {}
        self._irradiance = None

    def prefiltered_at(self, alpha: float):
        """The environment prefiltered at exactly this GGX alpha (full resolution, one level;
        cached): the split-sum tier of a material whose alpha is uniform needs no mip blend."""
        key = round(float(alpha), 6)
        if key not in self._at_alpha:
            self._at_alpha[key] = self._prefilter_level(key)
        return self._at_alpha[key]

    @property
    def irradiance(self):
        """E(n) / pi as a small equirect texture (cosine-weighted prefilter), made on first use."""
        if self._irradiance is None:
            data = self._prefilter_pass(1.0, IRRADIANCE_SIZE, IRRADIANCE_SAMPLES, cosine=True)
            self._irradiance = self.resources.float_texture(data, mipmaps=False, repeat=(True, False))
        return self._irradiance

    def _prefilter_pass(self, alpha: float, size: tuple, samples: int, cosine: bool = False) -> np.ndarray:
        """One pass of prefilter.frag at `alpha` into a (h, w, 3) float32 array."""
        import moderngl

        ctx = self.resources.make_current()
        prog = self.resources.program(gl.shader_file("fullscreen.vert"), gl.shader_file("prefilter.frag"))
        vao = ctx.vertex_array(prog, [])
        self.radiance.use(0)
        gl.set_uniform(prog, "pv_env", 0)
        gl.set_uniform(prog, "pv_samples", samples)
        gl.set_uniform(prog, "pv_env_size", self.size)
        gl.set_uniform(prog, "pv_alpha", alpha)
        gl.set_uniform(prog, "pv_cosine", int(cosine))
        target = ctx.texture(size, 4, dtype="f4")
        fbo = ctx.framebuffer([target])
        fbo.use()
        ctx.viewport = (0, 0, *size)
        vao.render(moderngl.TRIANGLES, vertices=3)
        data = np.frombuffer(fbo.read(components=4, dtype="f4"), np.float32).reshape(size[1], size[0], 4)[..., :3]
        for item in (vao, fbo, target):
            item.release()
        return np.ascontiguousarray(data)

    def _prefilter_level(self, alpha: float):
        data = self._prefilter_pass(alpha, self.size, PREFILTER_SAMPLES)
        return self.resources.float_texture(data, mipmaps=False, repeat=(True, False))

    def _prefilter(self, samples: int = PREFILTER_SAMPLES):
        """The mip chain: level k holds the environment prefiltered at sqrt(alpha) = k / LEVELS."""
        tex = self.resources.float_texture(self.env.image, repeat=(True, False))
        for level in range(1, PREFILTER_LEVELS + 1):
            size = (max(self.size[0] >> level, 4), max(self.size[1] >> level, 2))
            data = self._prefilter_pass((level / PREFILTER_LEVELS) ** 2, size, samples)
            tex.write(data.tobytes(), level=level)
        return tex


class Targets:
    """The HDR target (half float) with depth, and the 8-bit output, for one size.

    With MSAA (msaa > 1) the scene is drawn into a multisampled renderbuffer and resolved
    into `resolved_tex`; without it, straight into `resolved_tex` (no resolve pass)."""

    HDR_DTYPE = "f2"

    def __init__(self, ctx, width: int, height: int, msaa: int):
        self.size = (width, height)
        self.rect = None  # what the last draw() cleared, tone mapped and will read (None: all)
        self.samples = msaa if msaa > 1 else 0
        self.resolved_tex = ctx.texture(self.size, 4, dtype=self.HDR_DTYPE)
        if self.samples:
            self.msaa = ctx.framebuffer(
                [ctx.renderbuffer(self.size, 4, samples=msaa, dtype=self.HDR_DTYPE)],
                ctx.depth_renderbuffer(self.size, samples=msaa),
            )
            self.resolved = ctx.framebuffer([self.resolved_tex])
        else:
            self.msaa = self.resolved = ctx.framebuffer([self.resolved_tex], ctx.depth_renderbuffer(self.size))
        self.ldr = ctx.framebuffer([ctx.renderbuffer(self.size, 4)])
        self.background_size = (max(width // BACKGROUND_SCALE, 1), max(height // BACKGROUND_SCALE, 1))
        self.background_tex = ctx.texture(self.background_size, 4, dtype=self.HDR_DTYPE)
        self.background_tex.repeat_x = self.background_tex.repeat_y = False
        self.background = ctx.framebuffer([self.background_tex])

    @property
    def draw_target(self):
        return self.msaa

    def resolve(self, ctx) -> None:
        if self.samples:
            ctx.copy_framebuffer(self.resolved, self.msaa)


def env_resources(resources: Resources, env: Environment) -> EnvResources:
    return resources.once(("environment", env.content_key), lambda: EnvResources(env, resources))


def targets(resources: Resources, width: int, height: int, msaa: int) -> Targets:
    return resources.once(("targets", width, height, msaa), lambda: Targets(resources.ctx, width, height, msaa))


def mesh_buffers(resources: Resources, mesh: Mesh):
    """(vertex buffer, index buffer) of the mesh, uploaded once per mesh content."""
    ctx = resources.ctx
    return resources.once(
        ("mesh", mesh.key),
        lambda: (ctx.buffer(mesh.interleaved().tobytes()), ctx.buffer(mesh.indices.astype("u4").tobytes())),
    )


def encode_map(role: str, array: np.ndarray) -> np.ndarray:
    """Baked map -> what the shader samples: normals as n * 0.5 + 0.5; image top row at v = 1."""
    a = np.asarray(array, np.float32)
    if role == "normal":
        a = a * 0.5 + 0.5
    return np.flipud(a)


def neutral_map(role: str, params: dict, size: int = 4) -> np.ndarray:
    """A uniform stand-in for a map that cannot be baked (the material's own value)."""
    value = {
        "base_color": params.get("base_color", [0.8, 0.8, 0.8]),
        "normal": [0.0, 0.0, 1.0],
        "roughness": params.get("roughness", 0.5),
        "mask": 0.0,
        "metallic": 0.0,
    }.get(role, 0.0)
    return np.broadcast_to(np.asarray(value, np.float32), (size, size) + np.shape(value)).copy()


def bake_maps(material: dict, size: int, seed: int, notes: list | None = None) -> dict:
    """Bake every map role (the map-baking service); a role whose graph fails gets a neutral
    map and a note."""
    from cnlmc.backends.maps.service import MapBakeError, bake_arrays

    try:
        return bake_arrays(material, size, seed)
    except MapBakeError:
        pass
    arrays = {}
    for role in material.get("maps", {}):
        try:
            arrays.update(bake_arrays(material, size, seed, roles=[role]))
        except MapBakeError as exc:
            arrays[role] = neutral_map(role, material["params"])
            if notes is not None:
                notes.append(f"preview: {material['name']}: map {role} not baked ({exc.reason}); uniform value used")
    return arrays


def map_textures(resources: Resources, material: dict, samplers: list, size: int = MAP_SIZE, seed: int = 0) -> dict:
    """sampler name -> texture, baked with cnlmc.backends.maps (made once per maps and parameters)."""
    if not samplers:
        return {}
    key = (
        "maps",
        json.dumps(material.get("maps", {}), sort_keys=True),
        json.dumps(material["params"], sort_keys=True, default=str),
        size,
        seed,
    )

    def upload() -> dict:
        arrays = bake_maps(material, size, seed)
        return {role: resources.float_texture(encode_map(role, arr)) for role, arr in arrays.items()}

    baked = resources.once(key, upload)
    return {s["name"]: baked[s["role"]] for s in samplers if s["role"] in baked}


def split_textures(
    resources: Resources, material: dict, plan: dict, res: EnvResources, glsl_options: dict | None
) -> dict:
    """sampler name -> texture for the split-sum tier: the material's albedo tables, and the
    environment prefiltered at exactly the base's and the coat's alpha when they are uniform."""
    from cnlmc.bsdf.evaluate import coat_alpha, material_alpha

    opts = glsl_options or {}
    fresnel, multiscatter = str(opts.get("fresnel", "exact")), str(opts.get("multiscatter", "off")) == "on"
    key = (
        "split tables",
        json.dumps([material["model"], material["params"]], sort_keys=True, default=str),
        fresnel,
        multiscatter,
        plan["roughness_map"],
    )

    def upload() -> dict:
        black, tint = resources.tables.tables(material, fresnel, multiscatter, plan["roughness_map"])
        flat = lambda table: resources.float_texture(table, mipmaps=False, repeat=(False, False))
        return {"pv_black_albedo": flat(black), "pv_tint_albedo": flat(tint)}

    textures = dict(resources.once(key, upload))
    textures["pv_env_irradiance"] = res.irradiance
    params = material["params"]
    coat = params.get("coat") if plan["coat"] else None
    if plan["microfacet"] and not plan["roughness_map"]:
        ax, ay = (float(a) for a in material_alpha(material))
        widen = float(coat.get("ior", 1.5)) if coat and plan["base"] == "conductor" else 1.0
        textures["pv_env_material"] = res.prefiltered_at(min(max(np.sqrt(ax * ay), 1e-3) * widen, 1.0))
    if coat:
        cx, cy = (float(a) for a in coat_alpha(coat, params.get("alpha_convention", "squared")))
        textures["pv_env_coat"] = res.prefiltered_at(max(np.sqrt(cx * cy), 1e-3))
    return textures


# ------------------------------------------------------------------------ render


@dataclass
class Scene:
    mesh: Mesh
    camera: Camera
    env: Environment
    background: str = "env"  # "env" (blurred environment), "transparent", "none"
    background_lod: float = 3.0
    exposure: float = 1.0
    env_intensity: float = 1.0


def scene_mesh(name: str, size: tuple[int, int]) -> Mesh:
    """The named mesh (or file) fitted for a frame of `size`; the built-in sphere is tessellated
    for its size on screen (the framing fits it inside min(size) pixels: radius below half)."""
    if name == "sphere":
        return sphere_for_pixels(0.5 * min(size))
    return fit(mesh_by_name(name))


def default_scene(mesh: str | Mesh = "sphere", env: str | Environment = "studio", size=(512, 512)) -> Scene:
    """The framed preview scene, its mesh and environment made anew when named
    (Renderer.scene keeps them)."""
    mesh = scene_mesh(mesh, size) if isinstance(mesh, str) else mesh
    env = environment(env) if isinstance(env, str) else env
    lo, hi = mesh.bounds
    return Scene(mesh, framing_camera(lo, hi, aspect=size[0] / size[1]), env)


def screen_rect(
    points: np.ndarray, view_projection: np.ndarray, width: int, height: int, pad: int = 0
) -> tuple[int, int, int, int] | None:
    """Pixel rectangle (x, y, w, h; OpenGL window coordinates) covering homogeneous world
    points (N, 4) after projection, padded and clipped to the frame; None if a point is at or
    behind the camera plane (its projection is unbounded)."""
    clip = np.asarray(points, np.float64) @ np.asarray(view_projection, np.float64).T
    w = clip[:, 3]
    if not np.all(w > 1e-9):
        return None
    ndc = clip[:, :2] / w[:, None]
    x = (ndc[:, 0] * 0.5 + 0.5) * width
    y = (ndc[:, 1] * 0.5 + 0.5) * height
    x0, y0 = int(np.floor(x.min())), int(np.floor(y.min()))
    return grown((x0, y0, int(np.ceil(x.max())) - x0, int(np.ceil(y.max())) - y0), pad, width, height)


def grown(rect: tuple[int, int, int, int] | None, pixels: int, width: int, height: int):
    """`rect` grown by `pixels` on every side, clipped to the frame (None stays None)."""
    if rect is None:
        return None
    x0, y0 = max(rect[0] - pixels, 0), max(rect[1] - pixels, 0)
    x1, y1 = min(rect[0] + rect[2] + pixels, width), min(rect[1] + rect[3] + pixels, height)
    return (x0, y0, max(x1 - x0, 0), max(y1 - y0, 0))


def strips_around(rect: tuple[int, int, int, int], width: int, height: int) -> list[tuple[int, int, int, int]]:
    """The frame outside `rect` as up to four non-empty rectangles: below, above, left, right."""
    x, y, w, h = rect
    strips = [(0, 0, width, y), (0, y + h, width, height - y - h), (0, y, x, h), (x + w, y, width - x - w, h)]
    return [s for s in strips if s[2] > 0 and s[3] > 0]


def read_image(fbo, rect: tuple[int, int, int, int] | None, size: tuple[int, int], dtype: str) -> np.ndarray:
    """RGBA of the framebuffer, top row first; with `rect` only that rectangle is read, the rest
    is zero (transparent black, what the frame holds there)."""
    width, height = size
    numpy_type = np.uint8 if dtype == "f1" else np.float32
    if rect is None:
        data = np.frombuffer(fbo.read(components=4, dtype=dtype), numpy_type)
        return data.reshape(height, width, 4)[::-1].copy()
    image = np.zeros((height, width, 4), numpy_type)
    x, y, w, h = rect
    if w and h:
        data = np.frombuffer(fbo.read(viewport=rect, components=4, dtype=dtype), numpy_type).reshape(h, w, 4)
        image[height - y - h : height - y, x : x + w] = data[::-1]
    return image


class Renderer:
    """Offscreen renderer of one size. What it makes (programs, textures, meshes, tables) is
    kept by its `resources`, which renderers may share (`Renderer(w, resources=other.resources)`)
    and which go with `close()` (or the end of a `with` block) when this renderer made them."""

    def __init__(
        self,
        width: int = 512,
        height: int | None = None,
        msaa: int = DEFAULT_MSAA,
        edge_aa: bool = True,
        resources: Resources | None = None,
    ):
        self.width, self.height = width, height or width
        self.msaa = msaa
        self.edge_aa = edge_aa  # the tone-map pass's edge filter, used when msaa <= 1
        self._owns_resources = resources is None
        self.resources = resources or Resources()
        self.ctx = self.resources.ctx

    def close(self) -> None:
        """Release the GL context and all it holds, if this renderer made them."""
        if self._owns_resources:
            self.resources.release()

    def __enter__(self) -> Renderer:
        return self

    def __exit__(self, *exc) -> None:
        self.close()

    # -- what a frame is made from
    def shader(self, material: dict, glsl_options: dict | None = None) -> MaterialShader:
        """The material's shader (GLSL library and plan), made once per content and options."""
        key = ("shader", shader_key(material, glsl_options))
        return self.resources.once(key, lambda: material_shader(material, glsl_options))

    def scene(self, mesh: str | Mesh = "sphere", env: str | Environment = "studio") -> Scene:
        """The framed preview scene at this renderer's size (default_scene); a named mesh or
        environment is made once and kept (by name and size), a new Scene around them each call."""
        size = (self.width, self.height)
        if isinstance(mesh, str):
            mesh = self.resources.once(("scene mesh", mesh, size), lambda: scene_mesh(mesh, size))
        if isinstance(env, str):
            env = self.resources.once(("scene environment", env), lambda: environment(env))
        return default_scene(mesh, env, size)

    # -- programs
    def object_program(self, shader: MaterialShader, tier: Tier) -> tuple[str, object]:
        """(source key, program) of the object pass for this shader and tier kind."""

        def link() -> tuple[str, object]:
            vertex = gl.shader_file("preview.vert")
            fragment = gl.preview_fragment(shader.name, shader.library, shader.plan, tier.ibl)
            return source_key(vertex, fragment), self.resources.program(vertex, fragment)

        return self.resources.once(("object program", shader.key, tier.ibl), link)

    def fullscreen(self, fragment_file: str, define: str = ""):
        """(program, vertex array) of a full-screen pass, cached; `define` names a preprocessor
        symbol defined for this variant (llvmpipe runs both sides of every branch, even on a
        uniform: a variant that leaves work out must be its own program)."""

        def make():
            source = gl.shader_file(fragment_file)
            if define:
                version, rest = source.split("\n", 1)
                source = f"{version}\n#define {define}\n{rest}"
            prog = self.resources.program(gl.shader_file("fullscreen.vert"), source)
            return prog, self.ctx.vertex_array(prog, [])

        return self.resources.once(("fullscreen", fragment_file, define), make)

    def object_vao(self, program_key: str, prog, mesh: Mesh):
        def make():
            vbo, ibo = mesh_buffers(self.resources, mesh)
            layout, names = self.vertex_layout(prog)
            return self.ctx.vertex_array(prog, [(vbo, layout, *names)], index_buffer=ibo, index_element_size=4)

        return self.resources.once(("vertex array", program_key, mesh.key), make)

    def _bind_environment(self, prog, res: EnvResources, scene: Scene, tier: Tier, first_unit: int) -> int:
        units = {"pv_env": res.radiance, "pv_env_prefiltered": res.prefiltered}
        for offset, (name, tex) in enumerate(units.items()):
            tex.use(first_unit + offset)
            gl.set_uniform(prog, name, first_unit + offset)
        gl.set_uniform(prog, "pv_prefilter_levels", float(PREFILTER_LEVELS))
        gl.set_uniform(prog, "pv_env_intensity", scene.env_intensity)
        gl.set_uniform(prog, "pv_ambient", res.mean * scene.env_intensity)
        gl.set_uniform(prog, "pv_env_size", res.size)
        gl.set_uniform(prog, "pv_samples", max(tier.samples, 1))
        gl.set_uniform(prog, "pv_filtered", int(tier.filtered))
        return first_unit + len(units)

    def _draw_background(self, t: Targets, scene: Scene, res: EnvResources) -> None:
        """The blurred environment seen through each pixel, at 1/BACKGROUND_SCALE resolution."""
        import moderngl

        prog, vao = self.fullscreen("background.frag")
        res.radiance.use(0)
        gl.set_uniform(prog, "pv_env", 0)
        gl.set_uniform(prog, "pv_env_intensity", scene.env_intensity)
        gl.set_uniform(prog, "pv_background_lod", scene.background_lod)
        gl.set_uniform(prog, "pv_inverse_view_projection", np.linalg.inv(scene.camera.view_projection))
        self.ctx.disable(moderngl.DEPTH_TEST)
        t.background.use()
        self.ctx.viewport = (0, 0, *t.background_size)
        vao.render(moderngl.TRIANGLES, vertices=3)
        self.ctx.viewport = (0, 0, self.width, self.height)

    def _draw_object(
        self,
        scene: Scene,
        material: dict,
        shader: MaterialShader,
        tier: Tier,
        res: EnvResources,
        model: np.ndarray,
        glsl_options: dict | None = None,
    ) -> None:
        import moderngl

        program_key, prog = self.object_program(shader, tier)
        textures = dict(map_textures(self.resources, material, shader.samplers))
        if tier.ibl == "splitsum":
            textures.update(split_textures(self.resources, material, shader.plan, res, glsl_options))
        for unit, (name, tex) in enumerate(textures.items()):
            tex.use(unit)
            gl.set_uniform(prog, name, unit)
        self._bind_environment(prog, res, scene, tier, len(textures))
        cam = scene.camera
        gl.set_uniform(prog, "pv_model", model)
        gl.set_uniform(prog, "pv_normal_matrix", np.linalg.inv(model[:3, :3]).T)
        gl.set_uniform(prog, "pv_view_projection", cam.view_projection)
        gl.set_uniform(prog, "pv_camera_position", cam.position)
        gl.set_uniform(prog, "pv_key_direction", scene.env.key.unit)
        gl.set_uniform(prog, "pv_key_irradiance", [scene.env.key.irradiance * scene.env_intensity] * 3)
        self.ctx.enable(moderngl.DEPTH_TEST)
        if scene.mesh.closed:  # back faces of a closed mesh are never seen: not shaded
            self.ctx.enable(moderngl.CULL_FACE)
        self.object_vao(program_key, prog, scene.mesh).render(moderngl.TRIANGLES)
        self.ctx.disable(moderngl.CULL_FACE)

    VERTEX_ATTRIBUTES = (("in_position", 3), ("in_normal", 3), ("in_tangent", 3), ("in_uv", 2))

    @classmethod
    def vertex_layout(cls, prog) -> tuple[str, list[str]]:
        """The buffer format for Mesh.interleaved(); attributes the program does not use are skipped."""
        parts, names = [], []
        for name, size in cls.VERTEX_ATTRIBUTES:
            if name in prog:
                parts.append(f"{size}f")
                names.append(name)
            else:
                parts.append(f"{size * 4}x")
        return " ".join(parts), names

    def _tonemap(
        self,
        t: Targets,
        scene: Scene,
        res: EnvResources,
        background: bool,
        rect: tuple[int, int, int, int] | None = None,
    ) -> None:
        """Edge filter (without MSAA), the environment background (where the object does not
        cover the pixel), exposure, ACES, sRGB, in one pass over `rect` (x, y, w, h), where
        something was drawn, or over the whole frame when rect is None. Outside `rect`: the
        background alone (a variant without the object layer's five reads), or nothing
        (read_image() reads `rect` back; the rest is transparent black, what the pass writes)."""
        import moderngl

        self.ctx.disable(moderngl.DEPTH_TEST)
        t.ldr.use()
        vao = self._tonemap_program(t, scene, background)
        self.ctx.scissor = rect
        vao.render(moderngl.TRIANGLES, vertices=3)
        if rect is not None and background:
            vao = self._tonemap_program(t, scene, background, "PV_BACKGROUND_ONLY")
            for strip in strips_around(rect, self.width, self.height):
                self.ctx.scissor = strip
                vao.render(moderngl.TRIANGLES, vertices=3)
        self.ctx.scissor = None

    def _tonemap_program(self, t: Targets, scene: Scene, background: bool, define: str = ""):
        """The tone-map variant's vertex array, its textures bound and uniforms set."""
        prog, vao = self.fullscreen("tonemap.frag", define)
        t.resolved_tex.use(0)
        gl.set_uniform(prog, "pv_hdr", 0)
        gl.set_uniform(prog, "pv_exposure", scene.exposure)
        gl.set_uniform(prog, "pv_curve", 0)
        gl.set_uniform(prog, "pv_edge_aa", int(self.edge_aa and not t.samples))
        gl.set_uniform(prog, "pv_background", int(background))
        if background:
            t.background_tex.use(1)
            gl.set_uniform(prog, "pv_background_image", 1)
        return vao

    def draw(
        self,
        scene: Scene,
        material: dict,
        tier: Tier | str = DEFAULT_TIER,
        glsl_options: dict | None = None,
        model: np.ndarray | None = None,
        overlay=None,
    ) -> Targets:
        """Draw into the targets (no read-back); `overlay(renderer, scene)` draws extra geometry."""
        self.resources.make_current()  # ours must be the current context (another may have been made current)
        tier = parse_tier(tier) if isinstance(tier, str) else tier
        shader = self.shader(material, glsl_options)
        res = env_resources(self.resources, scene.env)
        t = targets(self.resources, self.width, self.height, self.msaa)
        model = np.eye(4) if model is None else model
        # Only the rectangle around what is drawn is cleared and tone mapped with the object
        # layer (one pixel more is cleared: the edge filter reads its neighbours); without a
        # background only it is read back.
        drawn = self.drawn_rect(scene, model, overlay)
        t.rect = None if scene.background == "env" else drawn
        t.draw_target.use()
        self.ctx.viewport = (0, 0, self.width, self.height)
        t.draw_target.clear(0.0, 0.0, 0.0, 0.0, depth=1.0, viewport=grown(drawn, 1, self.width, self.height))
        if overlay is not None:
            overlay(self, scene)
            t.draw_target.use()
        self._draw_object(scene, material, shader, tier, res, model, glsl_options)
        t.resolve(self.ctx)
        if scene.background == "env":
            self._draw_background(t, scene, res)
        self._tonemap(t, scene, res, scene.background == "env", drawn)  # composites the background
        return t

    #: pixels around the projected bounds: the edge filter's 1-pixel reach, and rounding.
    RECT_PAD = 2

    def drawn_rect(self, scene: Scene, model: np.ndarray, overlay=None) -> tuple[int, int, int, int] | None:
        """The pixel rectangle (x, y, w, h) that holds everything drawn: the object's bounding box
        (and an overlay's `world_points()`, if it has them) projected; None (the whole frame)
        when a corner is behind the camera or an overlay cannot say where it draws."""
        lo, hi = scene.mesh.bounds
        corners = np.array([[x, y, z, 1.0] for x in (lo[0], hi[0]) for y in (lo[1], hi[1]) for z in (lo[2], hi[2])])
        points = corners @ np.asarray(model, np.float64).T
        if overlay is not None:
            extra = getattr(overlay, "world_points", None)
            if extra is None:
                return None
            points = np.vstack([points, extra()])
        return screen_rect(points, scene.camera.view_projection, self.width, self.height, self.RECT_PAD)

    def render(
        self,
        material: dict,
        mesh: str | Mesh = "sphere",
        tier: Tier | str = DEFAULT_TIER,
        glsl_options: dict | None = None,
        env: str | Environment = "studio",
        scene: Scene | None = None,
        hdr: bool = False,
        **draw_options,
    ) -> Frame:
        """Render one material; returns the sRGB image (top row first) and the frame time."""
        scene = scene or self.scene(mesh, env)
        tier = parse_tier(tier) if isinstance(tier, str) else tier
        shader = self.shader(material, glsl_options)
        warm_key = (shader.key, tier.name, scene.mesh.key, scene.env.content_key, self.width, self.height)
        if self.resources.first_use(warm_key):  # the first frame compiles and uploads: drawn once untimed
            self.draw(scene, material, tier, glsl_options, **draw_options)
            self.ctx.finish()
        start = time.perf_counter()
        t = self.draw(scene, material, tier, glsl_options, **draw_options)
        self.ctx.finish()
        ms = (time.perf_counter() - start) * 1000.0
        rgba = read_image(t.ldr, t.rect, (self.width, self.height), "f1")
        linear = read_image(t.resolved, t.rect, (self.width, self.height), "f4") if hdr else None
        return Frame(rgba, linear, ms, tier.name, shader.notes)

    def frame_time(self, scene: Scene, material: dict, tier: Tier | str, glsl_options=None, repeats: int = 5) -> float:
        """Median frame time (ms) over `repeats` frames, after one warm-up frame."""
        self.draw(scene, material, tier, glsl_options)
        self.ctx.finish()
        times = []
        for _ in range(repeats):
            start = time.perf_counter()
            self.draw(scene, material, tier, glsl_options)
            self.ctx.finish()
            times.append((time.perf_counter() - start) * 1000.0)
        return float(np.median(times))
