"""Vector helpers for the local shading frame.

Convention (used by every module of ``cnlmc.bsdf``): normal n = +z, tangent t = +x,
bitangent b = +y. Directions ``wo`` (towards the viewer) and ``wi`` (towards the light)
are unit vectors stored in arrays of shape (..., 3); cos θ of a direction is its z.

Directions whose cos θ is below ``COS_EPS`` count as on or below the horizon: every
BRDF returns exactly 0 for them. This keeps all normalisation terms (1/cos θ, 1/cos⁴θh)
finite, also in a float32 port.
"""

from __future__ import annotations

from typing import Any

import numpy as np

#: A float or a numpy array of floats: the kernels of cnlmc.bsdf broadcast, so their inputs and
#: results are either (numpy's own annotations cannot say "same shape as the inputs").
Real = Any

#: Smallest cos θ treated as above the horizon (θ ≈ 89.99999°).
COS_EPS = 1e-7
#: Guard for normalising vectors of zero length.
TINY = 1e-300


def as_dirs(w: Real) -> np.ndarray:
    """Return ``w`` as a float64 array of shape (..., 3)."""
    return np.asarray(w, dtype=np.float64)


def dot(a: np.ndarray, b: np.ndarray) -> Real:
    """Dot product over the last axis: a·b, shape (...)."""
    return np.sum(a * b, axis=-1)


def normalize(v: np.ndarray) -> Real:
    """v / |v|; a zero vector stays zero (no NaN)."""
    length = np.sqrt(dot(v, v))
    return v / np.maximum(length, TINY)[..., None]


def cos_theta(w: np.ndarray) -> np.ndarray:
    """cos θ = w·n = w_z."""
    return w[..., 2]


def upper(w: np.ndarray) -> np.ndarray:
    """Boolean mask: cos θ ≥ COS_EPS (strictly above the horizon)."""
    return cos_theta(w) >= COS_EPS


def both_upper(wo: np.ndarray, wi: np.ndarray) -> Real:
    """Mask of pairs where both directions are above the horizon (reflection)."""
    return upper(wo) & upper(wi)


def half_vector(wo: np.ndarray, wi: np.ndarray) -> Real:
    """h = (wo + wi)/|wo + wi|; the zero vector when wo = −wi (degenerate)."""
    return normalize(wo + wi)


def reflect(w: np.ndarray) -> Real:
    """Mirror direction about the normal: (−x, −y, z)."""
    return w * np.array([-1.0, -1.0, 1.0])


def rotate_tangent(w: np.ndarray, angle: Real) -> np.ndarray:
    """Express w in a frame whose tangent is rotated by ``angle`` (radians) about n.

    t' = (cos φ, sin φ, 0), b' = (−sin φ, cos φ, 0):
    w' = (w·t', w·b', w_z).
    """
    c, s = np.cos(angle), np.sin(angle)
    x, y = w[..., 0], w[..., 1]
    return np.stack([c * x + s * y, -s * x + c * y, w[..., 2]], axis=-1)


def safe_div(num: Real, den: Real, default: Real = 0.0) -> Real:
    """num / den where den ≠ 0, else ``default`` (no warnings, no NaN)."""
    num, den = np.broadcast_arrays(np.asarray(num, float), np.asarray(den, float))
    out = np.full(num.shape, default, dtype=np.float64)
    np.divide(num, den, out=out, where=den != 0)
    return out


def spherical_dir(theta: Real, phi: Real = 0.0) -> np.ndarray:
    """Unit vector from polar angle θ and azimuth φ (radians)."""
    theta, phi = np.broadcast_arrays(np.asarray(theta, float), np.asarray(phi, float))
    st = np.sin(theta)
    return np.stack([st * np.cos(phi), st * np.sin(phi), np.cos(theta)], axis=-1)


def dir_from_mu(mu: Real, phi: Real = 0.0) -> np.ndarray:
    """Unit vector with cos θ = mu (clipped to [0, 1]) and azimuth φ."""
    mu = np.clip(np.asarray(mu, float), 0.0, 1.0)
    return spherical_dir(np.arccos(mu), phi)
