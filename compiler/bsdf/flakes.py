"""Flakes in a paint or plastic (metallic, pearlescent, glitter): a flake lobe under the coat.

A metallic paint is a pigmented binder holding small mirror-like flakes (aluminium, 10–50 µm;
TiO₂-coated mica for pearl; 0.2–1 mm glitter) under its clear coat. Seen from a few decimetres
a pixel covers hundreds of flakes, so the reference draws them as a *distribution* (the flake
normal distribution, a second microfacet lobe), not as single flakes: per unit area a share
``flake_density`` of the base is flakes, whose normals follow GGX with α = flake_roughness²
(the spread of their orientations), and whose reflectance is Schlick with F0 = ``flake_color``:

    f_base' = (1 − d s) · f_base  +  d · flake_color-Schlick(wo'·h) D_α(h) V_α(wo', wi'),
    s = max(flake_color)

(a flake hides the base by what it reflects: an aluminium flake ~0.92, a pearl's TiO₂-coated
mica platelet, which transmits the rest, 0.35; with s = 1 the mix is convex).

evaluated with the directions refracted into the coat (``layered.coated``: the flakes are a
directional lobe, so they get the coat's 1/η_c² compression, and the coat's Fresnel and
absorption). With white flakes the mix is convex, so the white furnace stays ≤ 1; coloured flakes
(s < 1) reflect less than s at normal incidence and a white base loses d s, so the furnace holds
wherever Schlick's rise towards grazing stays under the coat's losses (tested per phrase).
What the flakes add to the look: a bright lobe around the mirror direction that is much wider
than the coat's (the metallic "face"), darkening away from it and at grazing (the "flop"), and —
drawn by the preview, not by this mean BRDF — sparkle: the scatter of how many flakes in a
pixel's footprint face the half vector (docs/bsdf.md "Flakes", docs/preview.md).

``evaluate_flaked`` is ``evaluate`` with the flakes; ``evaluate_full`` adds the sheen over it
(the complete reflection BRDF the Mitsuba ``cnlm`` plugin draws); ``albedo_full`` integrates it.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from .evaluate import _base_parts, albedo, coat_alpha, coat_reflectance, coat_trap_of, evaluate, local_dirs, the_coat
from .fresnel import fresnel_schlick
from .geometry import Real
from .inputs import MaterialLike, as_material
from .layered import coated
from .microfacet import microfacet_reflection
from .sheen import sheen_layer

#: The narrowest flake spread: flakes are never a perfect mirror as a population (our choice:
#: α 0.01 is already far narrower than any measured paint, Ershov et al. 2001 fit 0.1–0.4).
FLAKE_ALPHA_MIN = 0.01


def has_flakes(material: MaterialLike) -> bool:
    """Whether the material carries flakes (a non-black flake_color and a density above 0)."""
    p = as_material(material).params
    return p.flake_color is not None and max(p.flake_color) > 0.0 and p.flake_density > 0.0


def flake_alpha(roughness: Any) -> Real:
    """The flake normal distribution's α = roughness², clamped to [FLAKE_ALPHA_MIN, 1]."""
    return np.clip(np.asarray(roughness, np.float64) ** 2, FLAKE_ALPHA_MIN, 1.0)


def flake_opacity(color: Any) -> float:
    """How much of the base a flake hides: its reflectance's brightest channel (an aluminium flake
    hides ~0.92, a pearl platelet, which lets through what it does not reflect, 0.35)."""
    return float(np.max(np.asarray(color, np.float64)))


def flake_lobe(wo: Any, wi: Any, color: Any, alpha: float) -> Real:
    """F D V of a population of flakes: GGX normals of width α, Schlick F0 = color; RGB (..., 3)."""
    f0 = np.asarray(color, np.float64)
    return microfacet_reflection(wo, wi, alpha, alpha, lambda c: fresnel_schlick(np.asarray(c)[..., None], f0))


def _flaked_parts(material: Any, fresnel: str, multiscatter: bool, ward_form: str, outside_ior: float) -> Any:
    """The base's (specular, diffuse) parts with the flakes mixed in (a callable of wo, wi)."""
    p = material.params
    density, alpha, color = float(p.flake_density), float(flake_alpha(p.flake_roughness)), p.flake_color
    keep = 1.0 - density * flake_opacity(color)

    def parts(wo: Real, wi: Real) -> tuple[Real, Real]:
        spec, diff = _base_parts(material, wo, wi, fresnel, multiscatter, ward_form, outside_ior)
        flakes = flake_lobe(wo, wi, color, alpha)
        return keep * spec + density * flakes, keep * diff

    return parts


def evaluate_flaked(
    material: MaterialLike, wo: Any, wi: Any, fresnel: str = "exact", multiscatter: bool = False, ward_form: str = "gmd"
) -> Real:
    """``evaluate`` with the flake lobe mixed into the base under the coat, RGB (..., 3)."""
    m = as_material(material)
    if not has_flakes(m):
        return evaluate(m, wo, wi, fresnel, multiscatter, ward_form)
    wo, wi = local_dirs(m, wo, wi)
    coat = the_coat(m)
    if coat is None:
        spec, diff = _flaked_parts(m, fresnel, multiscatter, ward_form, 1.0)(wo, wi)
        return spec + diff
    ior = float(coat.ior)
    base = _flaked_parts(m, fresnel, multiscatter, ward_form, ior)
    color = np.broadcast_to(np.asarray(coat.color, np.float64), (3,))
    rho = coat_reflectance(m, lambda mm: _flaked_parts(mm, fresnel, multiscatter, ward_form, ior))
    series = m.model.base != "conductor"
    return coated(wo, wi, base, ior, coat_alpha(coat), color, float(coat.thickness), rho, series)


def coat_trap(material: MaterialLike, fresnel: str = "exact") -> np.ndarray:
    """t, RGB (3,): the coat's round trip per unit base colour (``evaluate.coat_trap_of``), with a
    paint's flakes (they hide part of the diffuse base). Zero without a coat."""
    m = as_material(material)
    coat = the_coat(m)
    ior = float(coat.ior) if coat is not None else 1.0
    if not has_flakes(m):
        return coat_trap_of(m, lambda mm: lambda o, i: _base_parts(mm, o, i, fresnel, False, "gmd", ior))
    return coat_trap_of(m, lambda mm: _flaked_parts(mm, fresnel, False, "gmd", ior))


def evaluate_full(material: MaterialLike, wo: Any, wi: Any, **kwargs: Any) -> Real:
    """The complete reflection BRDF: the base with its flakes under the coat, the sheen over it."""
    m = as_material(material)
    return sheen_layer(m, wo, wi, evaluate_flaked(m, wo, wi, **kwargs))


def flake_proposal(material: MaterialLike) -> tuple[Real, Real] | None:
    """The flake lobe's (α, α) as seen from outside (widened by the coat's index), for MIS."""
    m = as_material(material)
    if not has_flakes(m):
        return None
    coat = the_coat(m)
    alpha = float(flake_alpha(m.params.flake_roughness)) * (float(coat.ior) if coat else 1.0)
    a = np.asarray(min(alpha, 1.0))
    return a, a


def albedo_flaked(material: MaterialLike, mu: Any, *args: Any, **kwargs: Any) -> Real:
    """``evaluate.albedo`` of the flaked base (no sheen; MIS samples the flake lobe too): what the
    preview's split-sum tables integrate (the preview draws the sheen itself). Same arguments."""
    return albedo(material, mu, *args, bsdf=evaluate_flaked, extra_lobes=[flake_proposal(material)], **kwargs)


def albedo_full(material: MaterialLike, mu: Any, *args: Any, **kwargs: Any) -> Real:
    """Directional albedo of ``evaluate_full`` (MIS of cosine, the base, coat and flake lobes)."""
    return albedo(material, mu, *args, bsdf=evaluate_full, extra_lobes=[flake_proposal(material)], **kwargs)


__all__ = [
    "FLAKE_ALPHA_MIN",
    "albedo_flaked",
    "albedo_full",
    "coat_trap",
    "evaluate_flaked",
    "evaluate_full",
    "flake_alpha",
    "flake_lobe",
    "flake_proposal",
    "has_flakes",
]
