"""IR material -> the inputs of a MaterialX surface shader (`open_pbr_surface`, `standard_surface`).

The MaterialX backend writes them as node inputs and the USD backend as UsdShade inputs; the
per-shader differences (input names, roughness fit, metal edge colour) are tables here.
"""

from __future__ import annotations

import math

from cnlmc.material import Coat, Material, Params

from .conversions import (
    DIGITS,
    alpha_pair,
    alpha_to_roughness,
    clip01,
    conductor_weight,
    f82_tint,
    gulbrandsen_edge,
    layered_diffuse_scale,
    openpbr_roughness,
    rounded,
    standard_roughness,
    weighted_f0,
)
from .subsurface_inputs import subsurface_inputs

# IR concept -> input name, per MaterialX surface shader (per-target differences as a table).
SURFACE_NAMES = {
    "open_pbr_surface": {
        "base_weight": "base_weight",
        "base_color": "base_color",
        "metalness": "base_metalness",
        "diffuse_roughness": "base_diffuse_roughness",
        "specular_weight": "specular_weight",
        "specular_color": "specular_color",
        "roughness": "specular_roughness",
        "ior": "specular_ior",
        "anisotropy": "specular_roughness_anisotropy",
        "transmission": "transmission_weight",
        "transmission_color": "transmission_color",
        "coat": "coat_weight",
        "coat_color": "coat_color",
        "coat_roughness": "coat_roughness",
        "coat_ior": "coat_ior",
        "sheen": "fuzz_weight",
        "sheen_color": "fuzz_color",
        "sheen_roughness": "fuzz_roughness",
        "subsurface": "subsurface_weight",
        "subsurface_color": "subsurface_color",
        "subsurface_length": "subsurface_radius",
        "subsurface_shape": "subsurface_radius_scale",
        "subsurface_anisotropy": "subsurface_scatter_anisotropy",
        "thin_walled": "geometry_thin_walled",
        "normal": "geometry_normal",
        "tangent": "geometry_tangent",
    },
    "standard_surface": {
        "base_weight": "base",
        "base_color": "base_color",
        "metalness": "metalness",
        "diffuse_roughness": "diffuse_roughness",
        "specular_weight": "specular",
        "specular_color": "specular_color",
        "roughness": "specular_roughness",
        "ior": "specular_IOR",
        "anisotropy": "specular_anisotropy",
        "rotation": "specular_rotation",
        "transmission": "transmission",
        "transmission_color": "transmission_color",
        "coat": "coat",
        "coat_color": "coat_color",
        "coat_roughness": "coat_roughness",
        "coat_ior": "coat_IOR",
        "sheen": "sheen",
        "sheen_color": "sheen_color",
        "sheen_roughness": "sheen_roughness",
        "subsurface": "subsurface",
        "subsurface_color": "subsurface_color",
        "subsurface_length": "subsurface_scale",
        "subsurface_shape": "subsurface_radius",
        "subsurface_anisotropy": "subsurface_anisotropy",
        "thin_walled": "thin_walled",
        "normal": "normal",
        "tangent": "tangent",
    },
}
ROUGHNESS_FIT = {"open_pbr_surface": openpbr_roughness, "standard_surface": standard_roughness}
METAL_EDGE = {"open_pbr_surface": f82_tint, "standard_surface": gulbrandsen_edge}
SURFACES = tuple(SURFACE_NAMES)


Value = float | bool | list[float]
Inputs = dict[str, tuple[str, Value]]


def abstract_inputs(material: Material, surface: str) -> Inputs:
    """IR material -> concept -> (MaterialX type, value), before naming for a surface."""
    model, params = material.model, material.params
    base = model.base
    out: Inputs = {"base_weight": ("float", 1.0)}
    if base == "conductor":
        out["base_weight"] = ("float", conductor_weight(params))
        out["base_color"] = ("color3", weighted_f0(params))
        out["metalness"] = ("float", 1.0)
        out["specular_color"] = ("color3", METAL_EDGE[surface](params))
    else:
        out["base_color"] = ("color3", clip01(params.base_color))
        out["metalness"] = ("float", 0.0)
    if base == "dielectric" and not model.coat:
        out["base_weight"] = ("float", dielectric_base_weight(material))
    if base == "diffuse":
        out["specular_weight"] = ("float", 0.0)
    else:
        out.update(_specular_inputs(params, surface))
    if base == "glass":
        out["transmission"] = ("float", 1.0)
        out["transmission_color"] = ("color3", clip01(params.base_color))
    if model.diffuse == "oren_nayar":
        out["diffuse_roughness"] = ("float", min(max(float(params.diffuse_roughness), 0.0), 1.0))
    if model.coat and params.coat is not None:
        out.update(_coat_inputs(params.coat))
    if params.sheen_color is not None and max(params.sheen_color) > 0.0:
        out.update(_sheen_inputs(params))
    out.update(subsurface_inputs(material))  # light inside the body (subsurface_inputs.py)
    return {k: (t, _rounded(v)) for k, (t, v) in out.items()}


def dielectric_base_weight(material: Material) -> float:
    """OpenPBR's and Standard Surface's diffuse base lies under the specular lobe with albedo scaling
    (1 - E(mu_o), energy-conserving: a white base gives a white furnace of 1); the IR's loses the
    light its interface reflects back in ((1 - F)(1 - F)). base_weight = the ratio of the two diffuse
    energies (`conversions.layered_diffuse_scale`, luminance), so the furnace is the IR's (#15)."""
    scale = layered_diffuse_scale(material)
    return min(max(0.2126 * scale[0] + 0.7152 * scale[1] + 0.0722 * scale[2], 0.0), 1.0)


def _rounded(value: Value) -> Value:
    if isinstance(value, bool):
        return value
    return round(value, DIGITS) if isinstance(value, float) else rounded(value)


def _specular_inputs(params: Params, surface: str) -> Inputs:
    ax, ay = alpha_pair(params)
    roughness, anisotropy = ROUGHNESS_FIT[surface](ax, ay)
    out: Inputs = {"specular_weight": ("float", 1.0), "roughness": ("float", roughness)}
    if "ior" in params.present:
        out["ior"] = ("float", float(params.ior))
    if anisotropy > 0.0:
        out["anisotropy"] = ("float", anisotropy)
        rotation = float(params.anisotropy_rotation)
        if rotation and "rotation" in SURFACE_NAMES[surface]:
            out["rotation"] = ("float", (rotation / (2 * math.pi)) % 1.0)
    return out


def _coat_inputs(coat: Coat) -> Inputs:
    """The IR's coat colour is a normal-incidence round-trip tint scaled by thickness."""
    color = [max(float(c), 0.0) ** float(coat.thickness) for c in coat.color]
    return {
        "coat": ("float", 1.0),
        "coat_color": ("color3", clip01(color)),
        "coat_roughness": ("float", alpha_to_roughness(float(coat.alpha[0]))),
        "coat_ior": ("float", float(coat.ior)),
    }


def _sheen_inputs(params: Params) -> Inputs:
    """The IR's sheen (docs/bsdf.md "Sheen") as a weight (its brightest channel) times a colour; the
    width as the lobe's alpha = r^2 (MaterialX's sheen_bsdf takes the lobe width itself)."""
    weight = max(float(c) for c in params.sheen_color or (0.0, 0.0, 0.0))
    return {
        "sheen": ("float", weight),
        "sheen_color": ("color3", clip01([float(c) / weight for c in params.sheen_color or ()])),
        "sheen_roughness": ("float", float(params.sheen_roughness) ** 2),
    }


def surface_inputs(material: Material, surface: str = "open_pbr_surface") -> Inputs:
    """IR material -> input name -> (MaterialX type, value) for `surface`."""
    names = SURFACE_NAMES[surface]
    return {names[k]: v for k, v in abstract_inputs(material, surface).items() if k in names}


def tangent_rotation(material: Material) -> float:
    """The streak direction in radians when the target has to rotate the tangent itself."""
    if not material.model.anisotropic:
        return 0.0
    return float(material.params.anisotropy_rotation)
