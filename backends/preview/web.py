"""The preview's scene as data for a WebGL2 client (the studio's live view, cnlmc.studio.view_payload,
docs/studio.md "View"): the object shader of the `splitsum` tier in GLSL ES 3.00 (the GLSL backend's
library with profile=es300 inside the preview's own templates), the material's uniforms, its
split-sum albedo tables and baked maps, and by name the environments, meshes and full-screen passes
(prefilter, background, tone map). The client repeats the preview's passes with these, so a browser
frame shows what `cnlmc preview` shows.

Binary data travels in one container format (`pack`): b"CNLV", a little-endian uint32 header
length, a JSON header (padded with spaces to 4 bytes) naming each array's dtype, shape and byte
offset after the header, then the arrays, each 4-byte aligned."""

from __future__ import annotations

import base64
import dataclasses
import json
import struct
import zlib
from collections.abc import Callable, Mapping
from pathlib import Path
from typing import Any

import numpy as np

from cnlmc.bsdf.evaluate import coat_alpha, material_alpha
from cnlmc.material import Material

from ..glsl.options import parse_glsl_options
from ..glsl.render import ShaderWriter
from . import gl
from .albedo_tables import TableCache
from .environment import environment
from .environment_pass import IRRADIANCE_SAMPLES, IRRADIANCE_SIZE, PREFILTER_LEVELS, PREFILTER_SAMPLES
from .flakes import flake_uniforms
from .glass import bounding_sphere, internal_paths, reference_units
from .material_textures import MAP_SIZE, bake_maps, encode_map
from .mesh import Mesh, make_mesh
from .meshes import MESHES, UV_UNIT_M, fit, sphere
from .scene import scene_mesh
from .shader import material_shader
from .sheen import sheen_uniforms
from .subsurface import boundary_material, lut_image, subsurface_uniforms

MAGIC = b"CNLV"
#: the tier the browser draws: the preview's default (docs/preview.md), the one its tables serve
TIER = "splitsum"
#: the frame size the built-in sphere is tessellated for (meshes.sphere_for_pixels): our choice,
#: the studio's canvas size; a smaller canvas draws a few more triangles than it needs
MESH_PIXELS = 512
ES_HEADER = "#version 300 es\nprecision highp float;\nprecision highp int;\nprecision highp sampler2D;"
ENVIRONMENTS = ("studio", "sky", "sun")
PASSES = ("fullscreen.vert", "prefilter.frag", "background.frag", "tonemap.frag")
#: what a WebGL2 client needs to repeat environment_pass.py (the preview's constants)
ENV_PASSES = {
    "prefilter_levels": PREFILTER_LEVELS,
    "prefilter_samples": PREFILTER_SAMPLES,
    "irradiance_size": list(IRRADIANCE_SIZE),
    "irradiance_samples": IRRADIANCE_SAMPLES,
    "background_lod": 3.0,
}
Writer = Callable[[list[tuple[str, bytes]]], None]
#: what the stored environment textures are made from (the cache is rebuilt when one changes)
BAKE_SOURCES = [
    Path(__file__),
    gl.SHADERS / "prefilter.frag",
    gl.SHADERS / "fullscreen.vert",
    Path(gl.__file__).with_name("environment.py"),
    Path(gl.__file__).with_name("environment_pass.py"),
]


def es300(source: str) -> str:
    """A preview shader (`#version 330 core` first) as GLSL ES 3.00, without its comment lines:
    they name the material and its values, which are uniforms, so a client can keep one program
    per shader (a colour change is not a recompile)."""
    first, rest = source.split("\n", 1)
    if not first.startswith("#version"):
        raise ValueError("a preview shader starts with its #version line")
    lines = [line for line in rest.split("\n") if line.strip() and not line.lstrip().startswith("//")]
    return "\n".join([ES_HEADER, *lines, ""])


def pack(header: Mapping[str, Any], arrays: Mapping[str, np.ndarray]) -> bytes:
    """The container: header + arrays (see the module docstring)."""
    blobs, table, offset = [], {}, 0
    for name, array in arrays.items():
        data = np.ascontiguousarray(array).tobytes()
        table[name] = {"dtype": array.dtype.str, "shape": list(array.shape), "offset": offset}
        data += b"\0" * (-len(data) % 4)
        blobs.append(data)
        offset += len(data)
    text = json.dumps({**header, "arrays": table}).encode()
    text += b" " * (-len(text) % 4)
    return MAGIC + struct.pack("<I", len(text)) + text + b"".join(blobs)


def unpack(data: bytes) -> tuple[dict[str, Any], dict[str, np.ndarray]]:
    """pack's inverse."""
    if data[:4] != MAGIC:
        raise ValueError("not a cnlmc view container")
    (length,) = struct.unpack("<I", data[4:8])
    header = json.loads(data[8 : 8 + length])
    base = 8 + length
    arrays = {}
    for name, spec in header.pop("arrays").items():
        dtype = np.dtype(spec["dtype"])
        count = int(np.prod(spec["shape"]))
        start = base + spec["offset"]
        arrays[name] = np.frombuffer(data, dtype, count, start).reshape(spec["shape"])
    return header, arrays


def float_table(array: np.ndarray) -> dict[str, Any]:
    """A small float32 RGBA texture (row 0 at v = 0) inline: width, height, base64 data."""
    a = np.ascontiguousarray(array, np.float32)
    return {"width": a.shape[1], "height": a.shape[0], "data": base64.b64encode(a.tobytes()).decode("ascii")}


def rgba(array: np.ndarray) -> np.ndarray:
    """(H, W[, C]) -> (H, W, 4), the missing channels 0 (alpha 1): WebGL2 renders mipmaps of RGBA only."""
    a = np.asarray(array, np.float32)
    a = a[..., None] if a.ndim == 2 else a
    out = np.zeros(a.shape[:2] + (4,), np.float32)
    out[..., 3] = 1.0
    out[..., : a.shape[2]] = a
    return out


class WebScene:
    """Turns materials and names into what the WebGL2 view draws; owns the albedo tables it has
    used, the GLSL templates (compiling them anew took 60 of a payload's 70 ms: the studio keeps one
    scene) and the OpenGL context its environments were prefiltered in (one per server, or one per
    call). Not thread-safe: its owner uses it from one thread (the context is current there)."""

    def __init__(self) -> None:
        self.tables = TableCache()
        self.writer = ShaderWriter()
        self.environments = EnvironmentBaker()

    def material(self, material_ir: Mapping[str, Any], write: Writer, exists: Callable[[str], bool]) -> dict:
        """The payload of one material (IR object); `write` stores map files by name in the
        session folder, `exists` says whether one is there already (named by the content key alone:
        the same look under another name is not baked again)."""
        # a translucent body: the preview draws its boundary with cnlm_bsdf and the body's light
        # with the subsurface term (subsurface.boundary_material, as Renderer does)
        material = boundary_material(Material.from_ir(dict(material_ir)))
        options = parse_glsl_options({"form": "library", "profile": "es300"})
        shader = material_shader(material, options, self.writer)
        fragment = gl.preview_fragment(shader.name, shader.library, shader.plan, TIER)
        notes = list(shader.notes)
        return {
            "cnlmc_view": 1,
            "name": material.name,
            "phrase": material.phrase,
            "key": material.key,
            "vertex": es300(gl.shader_file("preview.vert")),
            "fragment": es300(fragment),
            "uniforms": self.uniforms(material, shader),
            "glass": material.model.base == "glass",
            "glass_reference": reference_units(material.params.transmission_depth),
            "mesh_uniforms": mesh_uniforms(material),
            "uv_unit_m": UV_UNIT_M,
            "tables": {
                **self.split_tables(material, shader.plan.roughness_map),
                **body_tables(shader.plan),
                **glass_tables(material),
            },
            "prefilter": prefilter_alphas(material, shader.plan),
            "maps": self.maps(material, shader.samplers, write, exists, notes),
            "notes": notes,
        }

    def uniforms(self, material: Material, shader: Any) -> list[dict[str, Any]]:
        from ..glsl.plan import make_plan

        plan = make_plan(material, parse_glsl_options({"form": "library", "profile": "es300"}))
        out = [{"name": u.name, "type": u.type, "value": u.value} for u in plan.uniforms]
        for name, value in sheen_uniforms(material).items():
            arr = np.asarray(value, np.float64)
            kind = "float[]" if arr.size > 3 else ("vec3" if arr.size == 3 else "float")
            out.append({"name": name, "type": kind, "value": arr.tolist()})
        return out

    def split_tables(self, material: Material, mapped: bool) -> dict[str, Any]:
        black, tint = self.tables.tables(material, "exact", False, mapped)
        return {"pv_black_albedo": float_table(black), "pv_tint_albedo": float_table(tint)}

    def maps(
        self, material: Material, samplers: Any, write: Writer, exists: Callable[[str], bool], notes: list
    ) -> dict:
        """sampler name -> {file, width, height}: the baked maps as little-endian float16 RGBA
        (encode_map's layout: top image row at v = 1, normals n * 0.5 + 0.5), baked once per content."""
        if not samplers:
            return {}
        names = {s.role: f"{material.key}-{s.role}.f16" for s in samplers}
        if not all(exists(n) for n in names.values()):
            baked = bake_maps(material, MAP_SIZE, 0, notes)
            write([(names[r], rgba(encode_map(r, a)).astype("<f2").tobytes()) for r, a in baked.items() if r in names])
        return {s.name: {"file": names[s.role], "width": MAP_SIZE, "height": MAP_SIZE} for s in samplers}

    def asset(self, name: str) -> tuple[bytes, str] | None:
        """`env/<studio|sky|sun>` (radiance, the prefiltered chain, irradiance), `env/<name>@<alpha>`
        (prefiltered at exactly alpha), `mesh/<sphere|shader_ball|teapot>`, `shader/<pass>`; None otherwise."""
        kind, _, which = name.partition("/")
        env, _, alpha = which.partition("@")
        if kind == "env" and env in ENVIRONMENTS:
            data = self.environments.at_alpha(env, parse_alpha(alpha)) if alpha else self.environments.chain(env)
            return (data, "application/octet-stream") if data is not None else None
        if kind == "mesh" and which in MESHES:
            return mesh_bytes(which), "application/octet-stream"
        if kind == "shader" and which in PASSES:
            return es300(gl.shader_file(which)).encode(), "text/plain; charset=utf-8"
        return None

    def close(self) -> None:
        """Release the OpenGL context the environments were prefiltered in (if one was made)."""
        self.environments.close()


def parse_alpha(text: str) -> float | None:
    """An `@alpha` of an asset name: a number in [1e-3, 1] with at most 6 decimals, else None."""
    try:
        alpha = float(text)
    except ValueError:
        return None
    return (
        alpha
        if 1e-3 <= alpha <= 1.0 and f"{alpha:.6f}".rstrip("0").rstrip(".") == text.rstrip("0").rstrip(".")
        else None
    )


def half(array: np.ndarray) -> np.ndarray:
    return rgba(array).astype("<f2")


class EnvironmentBaker:
    """The environments' textures as the preview makes them (environment_pass.EnvResources, in an
    OpenGL context made on first need and owned here), stored on disk (cnlmc.cache) by name and alpha."""

    def __init__(self) -> None:
        self._resources: Any = None
        self._made: dict[str, Any] = {}

    def _env(self, name: str) -> Any:
        from .environment_pass import EnvResources
        from .resources import Resources

        if self._resources is None:
            self._resources = Resources()
        if name not in self._made:
            self._made[name] = EnvResources(environment(name), self._resources)
        return self._made[name]

    def chain(self, name: str) -> bytes:
        def build() -> bytes:
            res = self._env(name)
            image = res.env.image
            arrays = {"image": half(image)}
            for level in range(1, PREFILTER_LEVELS + 1):
                size = (max(image.shape[1] >> level, 4), max(image.shape[0] >> level, 2))
                data = np.frombuffer(res.prefiltered.read(level=level), np.float32).reshape(size[1], size[0], 3)
                arrays[f"level{level}"] = half(data)
            irr = res.irradiance
            arrays["irradiance"] = half(np.frombuffer(irr.read(), np.float32).reshape(irr.height, irr.width, 3))
            env = res.env
            header = {
                "name": name,
                "width": int(image.shape[1]),
                "height": int(image.shape[0]),
                "key_direction": [float(x) for x in env.key.unit],
                "key_irradiance": float(env.key.irradiance),
                "passes": ENV_PASSES,
            }
            return pack(header, arrays)

        return self._stored(f"view-env-{name}", build)

    def at_alpha(self, name: str, alpha: float | None) -> bytes | None:
        if alpha is None:
            return None

        def build() -> bytes:
            tex = self._env(name).prefiltered_at(alpha)
            data = np.frombuffer(tex.read(), np.float32).reshape(tex.height, tex.width, 3)
            return pack({"name": name, "alpha": alpha}, {"image": half(data)})

        return self._stored(f"view-env-{name}-{alpha:.6f}", build)

    def _stored(self, kind: str, build: Callable[[], bytes]) -> bytes:
        from cnlmc.cache import cached

        def load(stored: bytes) -> bytes:
            try:
                data = zlib.decompress(stored)
            except zlib.error as exc:
                raise ValueError(f"not a compressed container: {exc}") from None
            unpack(data)  # raises ValueError on what is not a container
            return data

        # compressed (zlib level 1: 30-90 ms once; a blurred environment shrinks 2-13x) so that the
        # shared cache (32 MiB by default) keeps more of them
        return cached(kind, BAKE_SOURCES, build, lambda data: zlib.compress(data, 1), load)

    def close(self) -> None:
        if self._resources is not None:
            self._resources.release()
            self._resources = None
            self._made.clear()


def typed_uniform(name: str, value: Any) -> dict[str, Any]:
    """{name, type, value} of a preview uniform given as a Python number or vector."""
    if isinstance(value, (bool, int, np.integer)) and not isinstance(value, (float, np.floating)):
        return {"name": name, "type": "int", "value": int(value)}
    arr = np.asarray(value, np.float64)
    kind = {1: "float", 2: "vec2", 3: "vec3", 4: "vec4"}.get(arr.size, "float[]")
    return {"name": name, "type": kind, "value": float(arr) if arr.ndim == 0 else arr.ravel().tolist()}


def stand_in(closed: bool) -> Mesh:
    """A closed fitted sphere or an open quad, 1 m per UV unit: what the mesh-dependent uniforms are
    computed on (the view puts in its mesh's bounding sphere and scales pv_flake_area by 1 / m²)."""
    if closed:
        mesh = fit(sphere(6, 8))
    else:
        mesh = make_mesh([(-1, 0, 0), (1, 0, 0), (1, 2, 0), (-1, 2, 0)], [(0, 1, 2), (0, 2, 3)])
    return dataclasses.replace(mesh, metres_per_uv=1.0)


def mesh_uniforms(material: Material) -> dict[str, list[dict[str, Any]]]:
    """ "closed" / "open" -> the flake and subsurface uniforms (object_pass.draw_object's) on a stand-in
    of that kind, model = identity."""
    out = {}
    for form, closed in (("closed", True), ("open", False)):
        mesh = stand_in(closed)
        values = {**flake_uniforms(material, mesh), **subsurface_uniforms(material, mesh, np.eye(4))}
        out[form] = [typed_uniform(name, value) for name, value in values.items()]
    return out


def body_tables(plan: Any) -> dict[str, Any]:
    """The body term's pre-integrated table (cnlm_sss_lut, read with texelFetch) for a translucent
    material: a texture, as the split-sum tables are (a uniform array of 561 floats would pass
    OpenGL ES 3.0's 224 fragment uniform vectors)."""
    return {"cnlm_sss_lut": float_table(rgba(lut_image()))} if plan.subsurface else {}


def glass_tables(material: Material) -> dict[str, Any]:
    """A glass's table of the light leaving a rough ball (pv_glass_paths, transmission.glsl.j2), as
    object_pass binds it: a texture like the split-sum tables."""
    if material.model.base != "glass":
        return {}
    return {"pv_glass_paths": float_table(internal_paths(float(material.params.ior)))}


def prefilter_alphas(material: Material, plan: Any) -> dict[str, float]:
    """The alphas split_textures prefilters the environment at exactly (material_textures.py)."""
    out = {}
    coat = material.params.coat if plan.coat else None
    if plan.microfacet and not plan.roughness_map:
        ax, ay = (float(a) for a in material_alpha(material))
        widen = float(coat.ior) if coat and plan.base == "conductor" else 1.0
        out["pv_env_material"] = round(min(max(float(np.sqrt(ax * ay)), 1e-3) * widen, 1.0), 6)
    if coat:
        cx, cy = (float(a) for a in coat_alpha(coat, material.params.alpha_convention))
        out["pv_env_coat"] = round(max(float(np.sqrt(cx * cy)), 1e-3), 6)
    return out


def mesh_bytes(name: str) -> bytes:
    """A named mesh as the preview fits it: interleaved position, normal, tangent, uv (11 floats),
    uint32 triangles, its bounds, bounding sphere (the glass's second interface) and closedness."""
    mesh = scene_mesh(name, (MESH_PIXELS, MESH_PIXELS))
    lo, hi = mesh.bounds
    centre, radius = bounding_sphere(mesh)
    header = {
        "name": name,
        "lo": [float(x) for x in lo],
        "hi": [float(x) for x in hi],
        "centre": [float(x) for x in centre],
        "radius": radius,
        "closed": bool(mesh.closed),
        "metres_per_uv": mesh.metres_per_uv,
    }
    return pack(header, {"vertices": mesh.interleaved(), "indices": mesh.indices.astype("<u4")})
