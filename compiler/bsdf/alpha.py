"""Perceptual roughness -> microfacet width alpha as the reference renders it (docs/ir.md, docs/bsdf.md).

The convention itself (alpha = r^2 or r, the anisotropic stretch, ALPHA_MIRROR) is stated once in
cnlmc.conventions; here alpha is clamped to [ALPHA_MIRROR, 1] for rendering: below ALPHA_MIRROR
a lobe is a perfect mirror.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from ..conventions import ALPHA_MIRROR, CONVENTIONS, alpha_isotropic, alpha_of, anisotropy_stretch

__all__ = [
    "ALPHA_MIRROR",
    "CONVENTIONS",
    "alpha_from_roughness",
    "alpha_isotropic",
    "anisotropy_stretch",
    "clamp_alpha",
]


def clamp_alpha(alpha: Any) -> np.ndarray:
    """Clamp alpha to [ALPHA_MIRROR, 1]."""
    return np.clip(np.asarray(alpha, dtype=np.float64), ALPHA_MIRROR, 1.0)


def alpha_from_roughness(roughness: Any, anisotropy: float = 0.0, convention: str = "squared") -> tuple[Any, Any]:
    """(alpha_x, alpha_y) of roughness r (clipped to [0, 1]; a float or an array per lane) by
    cnlmc.conventions.alpha_of, clamped to [ALPHA_MIRROR, 1]: two float64 arrays (0-d for a scalar)."""
    ax, ay = alpha_of(np.clip(np.asarray(roughness, dtype=np.float64), 0.0, 1.0), anisotropy, convention)
    return clamp_alpha(ax), clamp_alpha(ay)
