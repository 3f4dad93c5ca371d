"""Perceptual roughness → microfacet width α (docs/ir.md, docs/bsdf.md).

    α = r²       (convention "squared", the stdlib default; Burley 2012)
    α = r        (convention "linear", the paper's m)
    s = sqrt(1 − 0.9 a)          (anisotropy a in [0, 1]; Kulla & Conty 2017 form)
    αx = α / s,   αy = α · s
    both clamped to [ALPHA_MIRROR, 1].

Below ALPHA_MIRROR = 1e-3 a lobe is a perfect mirror: the GGX D term breaks down in
float32 there (data/README.md, brdf_accuracy_checks.json "ggx_small_alpha_float32").
"""

from __future__ import annotations

import numpy as np

#: Below this α a microfacet lobe is a perfect (delta) mirror.
ALPHA_MIRROR = 1e-3

CONVENTIONS = ("squared", "linear")


def alpha_isotropic(roughness, convention: str = "squared"):
    """α from perceptual roughness r: r² ("squared") or r ("linear"), unclamped."""
    r = np.clip(np.asarray(roughness, dtype=np.float64), 0.0, 1.0)
    if convention == "squared":
        return r * r
    if convention == "linear":
        return r
    raise ValueError(f"unknown alpha convention {convention!r}; use one of {CONVENTIONS}")


def anisotropy_stretch(anisotropy):
    """s = sqrt(1 − 0.9 a), a clipped to [0, 1]."""
    a = np.clip(np.asarray(anisotropy, dtype=np.float64), 0.0, 1.0)
    return np.sqrt(1.0 - 0.9 * a)


def clamp_alpha(alpha):
    """Clamp α to [ALPHA_MIRROR, 1]."""
    return np.clip(np.asarray(alpha, dtype=np.float64), ALPHA_MIRROR, 1.0)


def alpha_from_roughness(roughness, anisotropy=0.0, convention: str = "squared"):
    """(αx, αy) from roughness r and anisotropy a: αx = α/s, αy = α·s, clamped.

    α by ``convention`` (see ``alpha_isotropic``), s = sqrt(1 − 0.9 a). Returns two
    float64 arrays (0-d for scalar input).
    """
    alpha = alpha_isotropic(roughness, convention)
    s = anisotropy_stretch(anisotropy)
    return clamp_alpha(alpha / s), clamp_alpha(alpha * s)
