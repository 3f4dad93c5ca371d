"""An IR material as a glTF 2.0 material: the metallic-roughness core plus the ratified
KHR_materials_* extensions it needs (glTF 2.0 spec, Appendix B; the extensions' own specs).

- roughness: glTF's alpha is roughness^2, so roughness = sqrt(alpha). An anisotropic IR material
  (alpha_x >= alpha_y) becomes KHR_materials_anisotropy, whose widths are alpha_b = roughness^2
  and alpha_t = mix(alpha_b, 1, strength^2): roughness = sqrt(alpha_y), strength =
  sqrt((alpha_x - alpha_y) / (1 - alpha_y)), rotation = the IR's anisotropy_rotation (the
  tangent is +U in both). Both invert exactly.
- diffuse: metallic 0, roughness 1, KHR_materials_specular specularFactor 0 (no specular lobe).
- dielectric: metallic 0, KHR_materials_ior. conductor: metallic 1, baseColor = f0 x tint.
- glass: KHR_materials_transmission 1, KHR_materials_ior, KHR_materials_volume: thickness the
  object's size, attenuationColor the IR's base_color and attenuationDistance its
  transmission_depth (metres): the same Beer-Lambert meaning (the colour white light turns into
  after that distance inside); baseColor white, since glTF's baseColor would tint the light
  again at each crossing. A colourless glass leaves the attenuation at infinity; a glass coloured
  by a map keeps it as its baseColorTexture (glTF's tint at each crossing), unattenuated.
- coat: KHR_materials_clearcoat 1 with clearcoatRoughness = sqrt(coat alpha).
- sheen (velvet, cloth): KHR_materials_sheen with the IR's sheen colour and roughness as they are
  (the extension's lobe is the same Charlie sheen, alpha = roughness^2, with the same albedo scaling
  of the base; docs/bsdf.md "Sheen").
The IR has no emission (cnlmc.params): KHR_materials_emissive_strength is not written.
"""

from __future__ import annotations

import math
from typing import Any

from cnlmc.bsdf.transmission import DARKEST_TRANSMITTANCE
from cnlmc.material import Material

from .conversions import alpha_pair, clip01, conductor_f0
from .gltf_subsurface import subsurface_extensions

JSON = dict[str, Any]


def roughness_of(alpha: float) -> float:
    return math.sqrt(max(alpha, 0.0))


def anisotropy_of(ax: float, ay: float) -> tuple[float, float]:
    """(roughness, anisotropyStrength) whose KHR_materials_anisotropy widths are (ax, ay), ax >= ay."""
    major, minor = max(ax, ay), min(ax, ay)
    if minor >= 1.0:
        return 1.0, 0.0
    return roughness_of(minor), math.sqrt(min(max((major - minor) / (1.0 - minor), 0.0), 1.0))


def base_colour(material: Material) -> list[float]:
    params = material.params
    if material.model.base == "glass":  # its colour is the volume's attenuation (`extensions`)
        return [1.0, 1.0, 1.0, 1.0]
    colour = conductor_f0(params) if material.model.base == "conductor" else clip01(params.base_color)
    return [*colour, 1.0]


def core(material: Material) -> JSON:
    """pbrMetallicRoughness factors (no textures)."""
    model, params = material.model, material.params
    if model.base == "diffuse":
        return {"baseColorFactor": base_colour(material), "metallicFactor": 0.0, "roughnessFactor": 1.0}
    ax, ay = alpha_pair(params)
    rough = anisotropy_of(ax, ay)[0] if model.anisotropic else roughness_of(math.sqrt(ax * ay))
    return {
        "baseColorFactor": base_colour(material),
        "metallicFactor": 1.0 if model.base == "conductor" else 0.0,
        "roughnessFactor": rough,
    }


def extensions(material: Material, thickness: float) -> JSON:
    """KHR_materials_* extension objects, by name, for this material."""
    model, params = material.model, material.params
    out: JSON = {}
    if model.base == "diffuse":
        out["KHR_materials_specular"] = {"specularFactor": 0.0}
    if model.base in ("dielectric", "glass"):
        out["KHR_materials_ior"] = {"ior": float(params.ior)}
    if model.base == "glass":
        out["KHR_materials_transmission"] = {"transmissionFactor": 1.0}
        out["KHR_materials_volume"] = glass_volume(material, thickness)
    if model.anisotropic and model.base != "diffuse":
        ax, ay = alpha_pair(params)
        strength = anisotropy_of(ax, ay)[1]
        rotation = float(params.anisotropy_rotation) + (math.pi / 2 if ay > ax else 0.0)
        out["KHR_materials_anisotropy"] = {"anisotropyStrength": strength, "anisotropyRotation": rotation}
    if model.coat and params.coat is not None:
        out["KHR_materials_clearcoat"] = {
            "clearcoatFactor": 1.0,
            "clearcoatRoughnessFactor": roughness_of(float(params.coat.alpha[0])),
        }
    if params.sheen_color is not None and max(params.sheen_color) > 0.0:
        out["KHR_materials_sheen"] = {
            "sheenColorFactor": [float(c) for c in params.sheen_color],
            "sheenRoughnessFactor": float(params.sheen_roughness),
        }
    out.update(subsurface_extensions(material, thickness))  # light inside the body (gltf_subsurface.py)
    return out


def glass_volume(material: Material, thickness: float) -> JSON:
    """KHR_materials_volume of a glass: its thickness, and its colour as an attenuation."""
    volume: JSON = {"thicknessFactor": float(thickness)}
    colour = [max(c, DARKEST_TRANSMITTANCE) for c in clip01(material.params.base_color)]  # viewers take its log
    if min(colour) < 1.0 and "base_color" not in material.maps:  # a map tints as glTF's baseColor does
        volume["attenuationColor"] = [float(c) for c in colour]
        volume["attenuationDistance"] = float(material.params.transmission_depth)
    return volume


def widths_from_gltf(material: JSON) -> tuple[float, float]:
    """(alpha_t, alpha_b) a glTF viewer uses for a material (its JSON): the inverse of `core` and
    `extensions` (tests read files back through it)."""
    rough = material.get("pbrMetallicRoughness", {}).get("roughnessFactor", 1.0)
    alpha = rough * rough
    strength = material.get("extensions", {}).get("KHR_materials_anisotropy", {}).get("anisotropyStrength", 0.0)
    return alpha + (1.0 - alpha) * strength * strength, alpha
