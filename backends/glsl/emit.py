"""One material -> the library form, the standalone pair and the JSON sidecar."""

from __future__ import annotations

import json
import re
from typing import Any

import numpy as np

from cnlmc.material import Material

from ..base import Artifact
from .options import GlslOptions
from .plan import Plan, make_plan, make_uber_plan
from .render import PROFILES, ShaderWriter

#: specialize option -> (plan builder, library template).
LIBRARY_KINDS = {True: (make_plan, "library.glsl.j2"), False: (make_uber_plan, "uber.glsl.j2")}
#: form option -> which artifacts it writes.
FORM_PARTS = {"library": ("library",), "standalone": ("standalone",), "both": ("library", "standalone")}
#: Attributes and uniforms of the standalone pair (besides the material's own).
STANDALONE_ATTRIBUTES = {"in_position": "vec3", "in_normal": "vec3", "in_tangent": "vec3", "in_uv": "vec2"}
STANDALONE_UNIFORMS = {
    "cnlm_model": ("mat4", "object to world"),
    "cnlm_normal_matrix": ("mat3", "inverse transpose of the model matrix's upper 3x3"),
    "cnlm_view_projection": ("mat4", "world to clip"),
    "cnlm_camera_position": ("vec3", "world-space eye position"),
    "cnlm_light_direction": ("vec3", "world-space direction towards the light (default (0.4, 0.6, 0.7))"),
    "cnlm_light_radiance": ("vec3", "linear radiance of the light (default 3)"),
    "cnlm_ambient_radiance": ("vec3", "constant ambient radiance (default 0.05)"),
}
#: ... and a glass's: the path through it (cnlm_glass_absorption; at 0 nothing is absorbed)
GLASS_UNIFORMS = {
    "cnlm_glass_thickness": ("float", "metres of glass the light behind crosses (default 0.1, the preview ball)"),
}


def model_summary(plan: Plan) -> str:
    parts = [plan.base]
    if plan.distribution:
        parts.append(plan.distribution + (" anisotropic" if plan.anisotropic else ""))
    if plan.diffuse:
        parts.append(plan.diffuse)
    if plan.fresnel:
        parts.append(f"fresnel {plan.fresnel}")
    if plan.coat:
        parts.append("coat" + (" (tinted)" if plan.coat_color else ""))
    if plan.multiscatter:
        parts.append("multiscatter")
    if plan.maps:
        parts.append("maps: " + ", ".join(plan.maps))
    return " + ".join(parts)


def library_context(material: Material, plan: Plan, options: GlslOptions, writer: ShaderWriter) -> dict[str, Any]:
    profile = PROFILES[options.profile]
    return {
        "name": material.name,
        "phrase": material.phrase,
        "model_summary": model_summary(plan),
        "options": options.as_dict(),
        "plan": plan,
        "uniforms": plan.uniforms,
        "samplers": plan.samplers,
        "precision": profile["precision"],
        "initializers": profile["initializers"],
        "snippets": [writer.snippet(name) for name in plan.snippets],
        "ms": writer.multiscatter_tables if plan.multiscatter else None,
        "fallback": fallback_values(material),
        "sss_lut": lut_constant(plan),
    }


def float_literal(value: float) -> str:
    """A GLSL float literal (ES has no implicit int -> float: 1 is written 1.0)."""
    text = f"{value:.9g}"
    return text if any(c in text for c in ".en") else text + ".0"


def lut_constant(plan: Plan) -> dict[str, Any] | None:
    """The body's pre-integrated table as the library's const array (maps=none: no image): its size and
    its samples, row-major from row 0 (cos(theta) = -1), quantized as the 16-bit PNG stores them."""
    if not plan.lut_const:
        return None
    from ..preview.subsurface import lut_image

    table = np.asarray(lut_image(), np.float64)
    values = [float_literal(v) for v in (np.round(np.clip(table, 0.0, 1.0) * 65535.0) / 65535.0).ravel()]
    lines = [", ".join(values[i : i + 8]) for i in range(0, len(values), 8)]
    return {"rows": table.shape[0], "columns": table.shape[1], "lines": lines}


def fallback_values(material: Material) -> dict[str, str]:
    """GLSL literals a library uses where a map's sampler has no texture bound: the IR's uniform
    base colour and perceptual roughness."""
    r, g, b = (min(max(float(c), 0.0), 1.0) for c in material.params.base_color)
    return {
        "base_color": f"vec3({r:.6g}, {g:.6g}, {b:.6g})",
        "roughness": f"{min(max(float(material.params.roughness), 0.0), 1.0):.6g}",
    }


def library_source(material: Material, options: GlslOptions, writer: ShaderWriter) -> tuple[str, Plan]:
    """The library form of one material (no #version line) and its plan."""
    build_plan, template = LIBRARY_KINDS[options.specialize]
    plan = build_plan(material, options)
    return writer.render(template, **library_context(material, plan, options, writer)), plan


def standalone_sources(
    material: Material,
    library: str,
    options: GlslOptions,
    writer: ShaderWriter,
    transmission: bool = False,
    subsurface: bool = False,
) -> tuple[str, str]:
    profile = PROFILES[options.profile]
    common = {
        "name": material.name,
        "version": profile["version"],
        "precision": profile["precision"],
        "initializers": profile["initializers"],
    }
    frag = writer.render(
        "standalone.frag.j2",
        library=library,
        main_snippets=[writer.snippet("srgb")],
        transmission=transmission,
        subsurface=subsurface,
        **common,
    )
    return frag, writer.render("standalone.vert.j2", **common)


BTDF_ENTRY_POINTS = [
    "vec3 cnlm_btdf(vec3 n, vec3 t, vec3 v, vec3 l, vec2 uv)",
    "vec3 cnlm_btdf(vec3 n, vec3 v, vec3 l, vec2 uv)",
]
BTDF_RETURNS = (
    "BTDF f_t for v and l on opposite sides of n (outside = the side n points to, index 1; "
    "inside index cnlm_ior), radiance transport (includes the eta_v^2 factor: f_t(v, l)/eta_v^2 "
    "is symmetric), linear Rec.709 RGB tinted by the base colour, not multiplied by |cos(theta_l)|"
)


SUBSURFACE_ENTRY_POINT = (
    "vec3 cnlm_subsurface(vec3 p, vec3 n, vec3 v, vec3 l, vec3 light, vec3 front, vec3 back, float curvature)"
)
SUBSURFACE_RETURNS = (
    "the translucent body's radiance towards v (add it to cnlm_bsdf's, which is the boundary alone): p the "
    "position in scene units of cnlm_sss_unit metres, n the unit normal, l the unit direction to the light, light "
    "its irradiance at normal incidence, front/back the environment's irradiance / pi around n and -n, curvature "
    "1/r in 1/scene units (cnlm_sss_curvature(n, p) in a fragment shader)"
)


#: characters JSON may hold raw that a terminal obeys (DEL, C1 such as CSI, line separators, bidi overrides)
TERMINAL_CONTROLS = re.compile("[\x7f-\x9f\u2028\u2029\u202a-\u202e\u2066-\u2069]")


def sidecar_json(meta: dict[str, Any]) -> str:
    """The sidecar as JSON: unicode kept as written, the characters a terminal would obey as \\u
    escapes (inside JSON they can only be in strings, so the value is the same)."""
    text = json.dumps(meta, indent=2, ensure_ascii=False) + "\n"
    return TERMINAL_CONTROLS.sub(lambda m: f"\\u{ord(m.group()):04x}", text)


def sidecar(
    material: Material, plan: Plan, options: GlslOptions, files: list[str], maps_files: dict[str, str] | None = None
) -> dict[str, Any]:
    maps = {role: ref.to_ir() for role, ref in material.maps.items()}
    extra = {"btdf_entry_points": BTDF_ENTRY_POINTS, "btdf_returns": BTDF_RETURNS} if plan.transmission else {}
    if plan.subsurface:
        extra = {**extra, "subsurface_entry_points": [SUBSURFACE_ENTRY_POINT], "subsurface_returns": SUBSURFACE_RETURNS}
    return {
        "cnlmc_glsl": 1,
        "material": material.name,
        "phrase": material.phrase,
        "model": material.model.to_ir(),
        "options": options.as_dict(),
        "files": files,
        "entry_points": [
            "vec3 cnlm_bsdf(vec3 n, vec3 t, vec3 v, vec3 l, vec2 uv)",
            "vec3 cnlm_bsdf(vec3 n, vec3 v, vec3 l, vec2 uv)",
        ],
        "returns": "BRDF f, linear Rec.709 RGB, not multiplied by cos(theta_l)",
        **extra,
        "uniforms": [{"name": u.name, "type": u.type, "value": u.value} for u in plan.uniforms],
        "samplers": [
            {
                "name": s.name,
                "role": s.role,
                "colour_space": s.colour_space,
                "doc": s.doc,
                "map": maps.get(s.role),
                "file": (maps_files or {}).get(s.role),
            }
            for s in plan.samplers
        ],
        "standalone": {
            "output": "sRGB-encoded colour",
            "attributes": STANDALONE_ATTRIBUTES,
            "uniforms": {
                k: {"type": t, "doc": d}
                for k, (t, d) in {**STANDALONE_UNIFORMS, **(GLASS_UNIFORMS if plan.transmission else {})}.items()
            },
        },
    }


def emit_material(
    material: Material, options: GlslOptions, writer: ShaderWriter, maps_files: dict[str, str] | None = None
) -> list[Artifact]:
    """The material's shader files and sidecar; `maps_files`: role -> the baked image each sampler
    reads (relative to the output folder), recorded in the sidecar."""
    name = material.name
    library, plan = library_source(material, options, writer)
    parts = FORM_PARTS[options.form]
    artifacts = []
    if "library" in parts:
        artifacts.append(Artifact(f"{name}.glsl", library))
    if "standalone" in parts:
        frag, vert = standalone_sources(material, library, options, writer, plan.transmission, plan.subsurface)
        artifacts += [Artifact(f"{name}.frag", frag), Artifact(f"{name}.vert", vert)]
    files = [a.name for a in artifacts]
    meta = sidecar(material, plan, options, files, maps_files)
    artifacts.append(Artifact(f"{name}.glsl.json", sidecar_json(meta)))
    return artifacts
