"""Diffuse lobes: Lambert and Oren–Nayar (qualitative model).

Both return RGB (..., 3) BRDF values for an albedo of shape (3,) (or broadcastable),
0 when either direction is below the horizon. Both are reciprocal.
"""

from __future__ import annotations

import numpy as np

from .geometry import Real, as_dirs, both_upper, cos_theta, dot, safe_div


def _rgb(albedo: Real) -> Real:
    return np.asarray(albedo, dtype=np.float64)


def lambert(wo: Real, wi: Real, albedo: Real = (1.0, 1.0, 1.0)) -> Real:
    """Lambert: f = ρ / π (Lambert 1760). Directional albedo is exactly ρ."""
    wo, wi = as_dirs(wo), as_dirs(wi)
    mask = both_upper(wo, wi).astype(float)
    return (mask / np.pi)[..., None] * _rgb(albedo)


def oren_nayar_ab(sigma: Real) -> Real:
    """Oren & Nayar 1994 qualitative-model coefficients for slope deviation σ (rad).

    A = 1 − 0.5 σ² / (σ² + 0.33),   B = 0.45 σ² / (σ² + 0.09)
    """
    s2 = np.asarray(sigma, dtype=np.float64) ** 2
    return 1.0 - 0.5 * s2 / (s2 + 0.33), 0.45 * s2 / (s2 + 0.09)


def oren_nayar_angular(wo: Real, wi: Real) -> Real:
    """max(0, cos(φi − φo)) sin α tan β with α = max(θi, θo), β = min(θi, θo).

    Computed without trigonometry: sin θi sin θo cos(φi − φo) = wi·wo − zi zo, and
    sin α tan β = sin θi sin θo / max(cos θi, cos θo), so the term is
    max(0, wi·wo − zi zo) / max(zi, zo).
    """
    zo, zi = cos_theta(wo), cos_theta(wi)
    s = np.maximum(dot(wo, wi) - zo * zi, 0.0)
    return safe_div(s, np.maximum(zo, zi))


def oren_nayar(wo: Real, wi: Real, albedo: Real = (1.0, 1.0, 1.0), sigma: Real = 0.0) -> Real:
    """Oren–Nayar qualitative model (Oren & Nayar 1994, eq. 30):

        f = ρ/π · (A + B · max(0, cos(φi − φo)) · sin α · tan β)
    σ in radians; σ = 0 is exactly Lambert. Not energy conserving in general (the
    model omits interreflection; see tests for its measured albedo).
    """
    wo, wi = as_dirs(wo), as_dirs(wi)
    a, b = oren_nayar_ab(sigma)
    shape = (a + b * oren_nayar_angular(wo, wi)) * both_upper(wo, wi)
    return (shape / np.pi)[..., None] * _rgb(albedo)
