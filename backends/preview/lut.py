"""The split-sum BRDF LUT (Karis 2013): (A, B) with  E_spec(v) ~ F0 A + B  for GGX with
height-correlated Smith, indexed by (cos theta_v, sqrt(alpha)). numpy, deterministic."""
from __future__ import annotations

from functools import lru_cache

import numpy as np


def _hammersley(n: int) -> np.ndarray:
    i = np.arange(n, dtype=np.uint64)
    bits = np.zeros(n)
    for k in range(32):
        bits += ((i >> np.uint64(k)) & np.uint64(1)).astype(np.float64) * 2.0 ** -(k + 1)
    return np.stack([(np.arange(n) + 0.5) / n, bits], 1)


@lru_cache(maxsize=4)
def brdf_lut(size: int = 32, samples: int = 1024) -> np.ndarray:
    """(size, size, 2) float32; row = sqrt(alpha) index, column = cos theta_v index (texel centres)."""
    mu = (np.arange(size) + 0.5) / size
    alpha = np.maximum(((np.arange(size) + 0.5) / size) ** 2, 1e-3)
    xi = _hammersley(samples)
    a = alpha[:, None, None]
    a2 = a * a
    cos_h = np.sqrt((1 - xi[:, 0]) / (1 + (a2 - 1) * xi[:, 0]))          # (A, 1, N)
    sin_h = np.sqrt(np.maximum(1 - cos_h ** 2, 0))
    phi = 2 * np.pi * xi[:, 1]
    h = np.stack(np.broadcast_arrays(sin_h * np.cos(phi), sin_h * np.sin(phi), cos_h), -1)
    v = np.stack([np.sqrt(1 - mu ** 2), np.zeros_like(mu), mu], -1)[None, :, None, :]   # (1, M, 1, 3)
    vh = np.sum(v * h, -1)
    l = 2 * vh[..., None] * h - v
    nl, nv, nh = l[..., 2], mu[None, :, None], h[..., 2]
    lam = lambda c: np.sqrt(a2 * (1 - c * c) + c * c)  # noqa: E731
    g2 = 2 * nl * nv / (nl * lam(nv) + nv * lam(np.clip(nl, 0, 1)))
    w = np.where(nl > 0, g2 * np.clip(vh, 0, 1) / (nh * nv), 0.0)
    fc = (1 - np.clip(vh, 0, 1)) ** 5
    return np.stack([(w * (1 - fc)).mean(-1), (w * fc).mean(-1)], -1).astype(np.float32)
