"""A material's shader for the preview: the GLSL backend's library form of the material and
what the preview's templates need to know about it (the plan)."""

from __future__ import annotations

import hashlib
import json
from dataclasses import dataclass
from functools import cached_property

from cnlmc.bsdf.sampling import lobe_shares

from .. import glsl
from .albedo_tables import split_fitted
from .resources import source_key

MICROFACET = ("dielectric", "conductor", "glass")
GLSL_OPTION_KEYS = ("fresnel", "multiscatter", "specialize")


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
    opts = shader_options(glsl_options)
    ir = {"ir_version": 1, "materials": [material], "diagnostics": []}
    result = glsl.emit(ir, {**opts, "form": "library"})
    files = {a.name: a.content for a in result.artifacts}
    name = material["name"]
    sidecar = json.loads(files[f"{name}.glsl.json"])
    plan = material_plan(sidecar)
    plan["split_fitted"] = split_fitted(material, plan["roughness_map"])  # split.glsl.j2: two lookups
    return MaterialShader(name, files[f"{name}.glsl"], plan, sidecar["samplers"], [n.text() for n in result.notes])
