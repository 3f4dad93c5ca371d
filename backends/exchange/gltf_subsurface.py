"""The IR's medium (docs/subsurface.md) in glTF: KHR_materials_diffuse_transmission and KHR_materials_volume.

glTF has no scattering medium. The nearest it has:
- KHR_materials_diffuse_transmission (a release candidate, NOT ratified by Khronos: viewers may
  ignore it; the glTF validator reports it as an unknown extension, an info-level message): the
  share of the diffuse light that passes through the surface, and its colour;
- KHR_materials_volume (ratified): how the light it passes is attenuated inside the body
  (attenuationColor = the medium's albedo, attenuationDistance = its longest mean free path in
  metres; thicknessFactor = the object's size). The extension requires attenuationDistance > 0: a
  medium whose every radius is 0 lets no light travel inside, so it gets no volume (an opaque body).
The share comes from the numpy reference's Kubelka-Munk slab (cnlmc.bsdf.subsurface.slab) of the
medium: for a thin sheet at its thickness; for a volume at the object's size (a thick body lets
almost nothing through: its glow at thin edges is lost). base_color stays what the eye sees.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from cnlmc.bsdf.subsurface import medium_of, slab
from cnlmc.material import Material

JSON = dict[str, Any]
DIFFUSE_TRANSMISSION = "KHR_materials_diffuse_transmission"


def _through(material: Material, thickness: float) -> tuple[float, list[float]]:
    """(share of the diffuse light transmitted, its colour) of a slab of the medium `thickness` metres thick."""
    medium = material.params.subsurface
    assert medium is not None, "only a material with a medium"
    coefficients = medium_of(medium.color, medium.radius, float(medium.anisotropy), float(material.params.ior))
    reflectance, transmittance = slab(coefficients, thickness)
    total = np.maximum(reflectance + transmittance, 1e-9)
    share = float(np.mean(transmittance / total))
    colour = np.clip(transmittance / max(share, 1e-9), 0.0, 1.0) if share > 1e-9 else np.zeros(3)
    return share, [round(float(c), 6) for c in colour]


def subsurface_extensions(material: Material, size_m: float) -> JSON:
    """The extension objects, by name, for a material with a medium (empty otherwise)."""
    medium = material.params.subsurface
    if material.model.subsurface is None or medium is None:
        return {}
    thin = material.model.subsurface == "thin"
    share, colour = _through(material, float(medium.thickness or 0.0) if thin else size_m)
    out: JSON = {
        DIFFUSE_TRANSMISSION: {
            "diffuseTransmissionFactor": round(share, 6),
            "diffuseTransmissionColorFactor": colour,
        }
    }
    distance = max(float(r) for r in medium.radius)
    if not thin and distance > 0.0:
        out["KHR_materials_volume"] = {
            "thicknessFactor": float(size_m),
            "attenuationDistance": distance,
            "attenuationColor": [float(c) for c in medium.color],
        }
    return out
