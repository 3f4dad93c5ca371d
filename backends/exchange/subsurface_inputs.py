"""The IR's medium (docs/subsurface.md) as MaterialX surface inputs (OpenPBR, Standard Surface).

Both shaders take the multiple-scattering albedo (`subsurface_color`) and a mean free path split
into a length and a per-channel shape: OpenPBR `subsurface_radius` (length) x
`subsurface_radius_scale` (colour), Standard Surface `subsurface_scale` (length) x
`subsurface_radius` (colour). The length is the IR's largest channel of `radius`, in metres: the
scene unit is taken as a metre (the USDZ preview's metersPerUnit 1). A thin sheet sets the
shader's thin-walled switch. The renderer does its own albedo inversion (OpenPBR does not fix one),
so the look is approximate; the Mitsuba target is the reference.
"""

from __future__ import annotations

from cnlmc.material import Material

from .conversions import DIGITS, clip01

Inputs = dict[str, tuple[str, float | bool | list[float]]]


def subsurface_inputs(material: Material) -> Inputs:
    """concept -> (MaterialX type, value) for the medium; empty for a material without one."""
    medium = material.params.subsurface
    if material.model.subsurface is None or medium is None:
        return {}
    radius = [float(r) for r in medium.radius]
    length = max(max(radius), 1e-9)
    out: Inputs = {
        "subsurface": ("float", 1.0),
        "subsurface_color": ("color3", clip01(medium.color)),
        "subsurface_length": ("float", round(length, DIGITS + 3)),
        "subsurface_shape": ("color3", [round(r / length, DIGITS) for r in radius]),
        "subsurface_anisotropy": ("float", float(medium.anisotropy)),
    }
    if material.model.subsurface == "thin":
        out["thin_walled"] = ("boolean", True)
    return out
