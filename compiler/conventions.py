"""The roughness -> alpha convention and the mirror threshold, stated once for the IR and every backend.

alpha = r^2 ("squared", the stdlib)  or  alpha = r ("linear", the paper's m)
s = sqrt(1 - 0.9 a),  alpha_x = alpha / s,  alpha_y = alpha * s   (a = anisotropy in [0, 1])
alpha_x, alpha_y are clamped to at most 1 (the IR's numbers are not clamped below).
Below ALPHA_MIRROR a lobe is a perfect mirror: renderers clamp alpha up to it (cnlmc.bsdf.alpha),
the GLSL library states it as CNLM_ALPHA_MIRROR.
"""

from __future__ import annotations

import math
from typing import Any

#: Below this alpha a microfacet lobe is a perfect (delta) mirror: the GGX D term breaks down
#: in float32 there (data/README.md, brdf_accuracy_checks.json "ggx_small_alpha_float32").
ALPHA_MIRROR = 1e-3

CONVENTIONS = ("squared", "linear")


def alpha_isotropic(roughness: Any, convention: str = "squared") -> Any:
    """alpha from perceptual roughness r: r^2 ("squared") or r ("linear"); a float or a numpy array."""
    if convention == "squared":
        return roughness * roughness
    if convention == "linear":
        return roughness
    raise ValueError(f"unknown alpha convention {convention!r}; use one of {CONVENTIONS}")


def anisotropy_stretch(anisotropy: float) -> float:
    """s = sqrt(1 - 0.9 a), a clipped to [0, 1]."""
    return math.sqrt(1.0 - 0.9 * min(max(anisotropy, 0.0), 1.0))


def _at_most_one(x: Any) -> Any:
    return min(x, 1.0) if isinstance(x, float) else x.clip(max=1.0)  # a numpy array: per lane


def alpha_of(roughness: Any, anisotropy: float = 0.0, convention: str = "squared") -> list[Any]:
    """[alpha_x, alpha_y] of roughness r (a float, or a numpy array per lane), at most 1."""
    if type(roughness) is float and type(anisotropy) is float and convention == "squared":
        alpha = roughness * roughness  # every IR material: the steps below, without their calls
        if anisotropy == 0.0:  # isotropic (most materials, every coat): s = 1, and x / 1 = x * 1 = x
            alpha = min(alpha, 1.0)
            return [alpha, alpha]
        s = math.sqrt(1.0 - 0.9 * min(max(anisotropy, 0.0), 1.0))
        return [min(alpha / s, 1.0), min(alpha * s, 1.0)]
    alpha = alpha_isotropic(roughness, convention)
    s = anisotropy_stretch(anisotropy)
    return [_at_most_one(alpha / s), _at_most_one(alpha * s)]
