"""The roughness -> alpha convention, stated once; every backend reads alpha from the IR.

alpha = r^2 ("squared", the stdlib)  or  alpha = r ("linear", the paper's m)
s = sqrt(1 - 0.9 a),  alpha_x = alpha / s,  alpha_y = alpha * s   (a = anisotropy in [0, 1])
alpha_x, alpha_y are clamped to at most 1. Below ALPHA_MIRROR a lobe is a perfect mirror.
"""

from __future__ import annotations

import math

ALPHA_MIRROR = 1e-3


def alpha_of(roughness: float, anisotropy: float = 0.0, convention: str = "squared") -> list[float]:
    alpha = roughness * roughness if convention == "squared" else roughness
    s = math.sqrt(1.0 - 0.9 * min(max(anisotropy, 0.0), 1.0))
    return [min(alpha / s, 1.0), min(alpha * s, 1.0)]
