"""The sheen of a fibre layer (velvet, cloth): the "Charlie" lobe over the base, energy-scaled.

Estevez & Kulla 2017, "Production Friendly Microfacet Sheen BRDF" (Sony Imageworks): a
microfibre distribution whose density rises towards the grazing half vector,

    D(h) = (2 + 1/α) sin^(1/α) θh / (2π),

and the paper's fitted masking: Λ(μ) = exp(L(μ)) for μ < 1/2, exp(2 L(1/2) − L(1 − μ)) above,
L(x) = a / (1 + b x^c) + d x + e, each coefficient interpolated between its α = 1 and α = 0 fit
by (1 − α)² (the paper's table), and the height-correlated Smith form

    V = G2 / (4 μo μi),   G2 = 1 / (1 + Λ(μo) + Λ(μi)),

so f_sheen = sheen_color · D V (not multiplied by cos θi; no Fresnel: the fibres' scattering is
folded into sheen_color). α = sheen_roughness², as glTF's KHR_materials_sheen, clamped to
[SHEEN_ALPHA_MIN, 1].

**Energy.** E(μ, α) = ∫ D V cos θi dωi is the sheen's directional albedo for a white sheen. The
base below sees the light the fibres did not scatter:

    f = sheen_color ⊙ D V  +  f_base · min(1 − s E(μo), 1 − s E(μi)),   s = max(sheen_color)

(the min keeps f reciprocal; the glTF sheen extension's albedo scaling uses the same form).
Then A(μo) ≤ s E(μo) + (1 − s E(μo)) · A_base(μo) ≤ 1 whenever E ≤ 1 and A_base ≤ 1. E is
tabulated once per α and process on TABLE_SIZE nodes uniform in sqrt μ by QMC integration
(uniform hemisphere sampling of a golden-ratio lattice) and looked up linearly.

``evaluate`` stays the base BRDF; ``evaluate_sheened`` and ``albedo_sheened`` add the layer
(docs/bsdf.md, "Sheen").
"""

from __future__ import annotations

import math
from functools import lru_cache
from typing import Any

import numpy as np

from .evaluate import albedo, evaluate
from .geometry import COS_EPS, Real, as_dirs, dir_from_mu, half_vector
from .inputs import MaterialLike, as_material
from .integrate import lattice_2d

#: The narrowest sheen lobe. Below it the fitted Λ lets the albedo exceed 1 at grazing (measured,
#: 65 536 samples: E(μ = 0.005) = 0.99 at α = 0.07, 1.19 at 0.04, 1.56 at 0.02); Filament's
#: cloth model clamps at the same value.
SHEEN_ALPHA_MIN = 0.07
#: The table's grazing node: E(μ) at μ = 0 exactly is 0 (Λ → ∞) but its limit is not.
MU_GRAZING = 1e-4
#: Nodes of an albedo row (sqrt μ uniform on [0, 1]); the shader takes the material's row.
TABLE_SIZE = 32
#: QMC samples per table cell (error ~1e-3 against 65 536 samples, tests/bsdf/test_sheen.py).
TABLE_SAMPLES = 4096


def sheen_alpha(roughness: Any) -> Real:
    """α = roughness², clamped to [SHEEN_ALPHA_MIN, 1]."""
    return np.clip(np.asarray(roughness, np.float64) ** 2, SHEEN_ALPHA_MIN, 1.0)


def charlie_d(cos_h: Real, alpha: Real) -> Real:
    """D(h) = (2 + 1/α) sin^(1/α) θh / (2π) for cos θh = ``cos_h`` (normalised: ∫ D cos θh dω = 1)."""
    inv = 1.0 / np.asarray(alpha, np.float64)
    sin2 = np.clip(1.0 - np.asarray(cos_h, np.float64) ** 2, 0.0, 1.0)
    return (2.0 + inv) * sin2 ** (0.5 * inv) / (2.0 * math.pi)


#: (a, b, c, d, e) of L(x) at α = 1 and at α = 0 (Estevez & Kulla 2017, table 1).
CHARLIE_L_ALPHA_1 = (21.5473, 3.82987, 0.19823, -1.97760, -4.32054)
CHARLIE_L_ALPHA_0 = (25.3245, 3.32435, 0.16801, -1.27393, -4.85967)


def charlie_l(x: Real, alpha: Real) -> Real:
    """The fitted L(x) of the paper at width α."""
    t = (1.0 - np.asarray(alpha, np.float64)) ** 2
    a, b, c, d, e = (p1 + (p0 - p1) * t for p1, p0 in zip(CHARLIE_L_ALPHA_1, CHARLIE_L_ALPHA_0, strict=True))
    return a / (1.0 + b * np.asarray(x, np.float64) ** c) + d * x + e


def charlie_lambda(mu: Real, alpha: Real) -> Real:
    """Λ(μ) of the fitted masking (μ ∈ (0, 1]); exponent capped so exp stays finite."""
    mu = np.clip(np.asarray(mu, np.float64), 0.0, 1.0)
    low = charlie_l(mu, alpha)
    high = 2.0 * charlie_l(0.5, alpha) - charlie_l(1.0 - mu, alpha)
    return np.exp(np.minimum(np.where(mu < 0.5, low, high), 600.0))


def charlie_visibility(mu_o: Real, mu_i: Real, alpha: Real) -> Real:
    """V = 1 / ((1 + Λ(μo) + Λ(μi)) 4 μo μi): the height-correlated Smith form of the fitted Λ."""
    g2 = 1.0 / (1.0 + charlie_lambda(mu_o, alpha) + charlie_lambda(mu_i, alpha))
    return g2 / (4.0 * mu_o * mu_i)


def sheen_lobe(wo: Any, wi: Any, alpha: Any) -> Real:
    """D V of a white sheen (scalar per pair); 0 below the horizon."""
    wo, wi = as_dirs(wo), as_dirs(wi)
    mu_o, mu_i = wo[..., 2], wi[..., 2]
    above = (mu_o >= COS_EPS) & (mu_i >= COS_EPS)
    mo, mi = np.where(above, mu_o, 1.0), np.where(above, mu_i, 1.0)
    lobe = charlie_d(half_vector(wo, wi)[..., 2], alpha) * charlie_visibility(mo, mi, alpha)
    return np.where(above, lobe, 0.0)


def sheen_albedo_direct(mu: Any, alpha: Any, n: int = TABLE_SAMPLES) -> Real:
    """E(μ, α) = ∫ D V cos θi dωi by QMC (uniform hemisphere sampling); μ, α broadcast."""
    mu, alpha = np.broadcast_arrays(np.asarray(mu, np.float64), np.asarray(alpha, np.float64))
    u1, u2 = lattice_2d(n)
    r = np.sqrt(np.clip(1.0 - u1 * u1, 0.0, 1.0))
    wi = np.stack([r * np.cos(2.0 * math.pi * u2), r * np.sin(2.0 * math.pi * u2), u1], axis=-1)
    wo = dir_from_mu(np.maximum(mu, COS_EPS))[..., None, :]
    lobe = sheen_lobe(wo, wi, alpha[..., None])
    return np.mean(lobe * u1, axis=-1) * 2.0 * math.pi


def table_axis() -> Real:
    """The table's nodes: sqrt μ uniform on [0, 1] (the grazing rise is steep in μ)."""
    return np.linspace(0.0, 1.0, TABLE_SIZE)


@lru_cache(maxsize=64)
def sheen_row(alpha: float) -> Real:
    """E at one α (clamped) on the table's sqrt-μ nodes, computed once per α and process (what
    the preview shader takes as a uniform array); a material has one sheen α, so one row."""
    mu = np.maximum(table_axis() ** 2, MU_GRAZING)
    row = np.asarray(sheen_albedo_direct(mu, max(float(alpha), SHEEN_ALPHA_MIN)), np.float64)
    row.setflags(write=False)
    return row


def sheen_albedo(mu: Any, alpha: float) -> Real:
    """E(μ, α) looked up linearly in sqrt μ in α's row."""
    return np.interp(np.sqrt(np.clip(mu, 0.0, 1.0)), table_axis(), sheen_row(float(alpha)))


def has_sheen(material: MaterialLike) -> bool:
    """Whether the material carries a sheen (a non-black sheen_color)."""
    color = as_material(material).params.sheen_color
    return color is not None and max(color) > 0.0


def sheen_layer(material: MaterialLike, wo: Any, wi: Any, base: Real) -> Real:
    """The sheen over an already evaluated base f_base (..., 3): see the module docstring."""
    m = as_material(material)
    if not has_sheen(m):
        return np.asarray(base)
    wo, wi = as_dirs(wo), as_dirs(wi)
    color = np.asarray(m.params.sheen_color, np.float64)
    alpha = float(sheen_alpha(m.params.sheen_roughness))
    s = float(color.max())
    mu_o, mu_i = np.clip(wo[..., 2], 0.0, 1.0), np.clip(wi[..., 2], 0.0, 1.0)
    e = np.maximum(sheen_albedo(mu_o, alpha), sheen_albedo(mu_i, alpha))
    scale = np.maximum(1.0 - s * e, 0.0)
    return sheen_lobe(wo, wi, alpha)[..., None] * color + np.asarray(base) * scale[..., None]


def evaluate_sheened(material: MaterialLike, wo: Any, wi: Any, **kwargs: Any) -> Real:
    """``evaluate`` (the base, kwargs passed on) with the sheen layer over it, RGB (..., 3)."""
    m = as_material(material)
    return sheen_layer(m, wo, wi, evaluate(m, wo, wi, **kwargs))


def albedo_sheened(material: MaterialLike, mu: Any, *args: Any, **kwargs: Any) -> Real:
    """Directional albedo of the sheened material: ``albedo`` of ``evaluate_sheened`` (the sheen is
    broad: cosine sampling covers it, no extra lobe)."""
    return albedo(material, mu, *args, bsdf=evaluate_sheened, **kwargs)


__all__ = [
    "SHEEN_ALPHA_MIN",
    "albedo_sheened",
    "charlie_d",
    "evaluate_sheened",
    "has_sheen",
    "charlie_lambda",
    "charlie_visibility",
    "sheen_albedo",
    "sheen_albedo_direct",
    "sheen_alpha",
    "sheen_layer",
    "sheen_lobe",
    "sheen_row",
]
