"""Fresnel reflectance: exact dielectric and conductor, Schlick, F82-tint.

All functions take cos θ (angle between the direction and the normal or half-vector)
and use |cos θ| clipped to [0, 1]; they broadcast over their arguments. Colour enters
through array parameters with a trailing RGB axis, e.g. ``eta`` of shape (3,) with
``cos_theta[..., None]``; the helpers ``*_rgb`` do that broadcasting for you.
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np

from .geometry import Real, safe_div

#: cos of the F82 angle (θ = acos(1/7) ≈ 81.79°), Hoffman 2019.
MU_BAR = 1.0 / 7.0


def _cos(cos_theta: Real) -> Real:
    return np.clip(np.abs(np.asarray(cos_theta, dtype=np.float64)), 0.0, 1.0)


def f0_from_ior(ior: Real) -> Real:
    """Normal-incidence reflectance of a dielectric: F0 = ((η − 1)/(η + 1))²."""
    ior = np.asarray(ior, dtype=np.float64)
    return ((ior - 1.0) / (ior + 1.0)) ** 2


def ior_from_f0(f0: Real) -> Real:
    """Inverse of ``f0_from_ior`` for η ≥ 1: η = (1 + √F0)/(1 − √F0)."""
    s = np.sqrt(np.clip(np.asarray(f0, dtype=np.float64), 0.0, 0.999999))
    return (1.0 + s) / (1.0 - s)


def f0_conductor(eta: Real, k: Real) -> Real:
    """Normal-incidence reflectance of a conductor: ((η−1)² + k²)/((η+1)² + k²)."""
    eta, k = np.asarray(eta, float), np.asarray(k, float)
    return ((eta - 1.0) ** 2 + k * k) / ((eta + 1.0) ** 2 + k * k)


def fresnel_dielectric(cos_theta: Real, eta: Real) -> Real:
    """Exact unpolarised Fresnel reflectance of a dielectric interface.

    η = η_t / η_i (relative; η < 1 means leaving the denser medium). With c = cos θi:
        c_t² = (η² − 1 + c²)/η²            (total internal reflection if c_t² < 0 → 1)
        r_s = (c − η c_t)/(c + η c_t),   r_p = (η c − c_t)/(η c + c_t)
        F = (r_s² + r_p²)/2
    η = 1 gives exactly 0 at every angle (also at grazing). (Born & Wolf; Walter 2007.)
    """
    c = _cos(cos_theta)
    eta = np.asarray(eta, dtype=np.float64)
    ct2 = ((eta * eta - 1.0) + c * c) / (eta * eta)  # = 1 − sin²θ/η², no cancellation at η = 1
    ct = np.sqrt(np.maximum(ct2, 0.0))
    rs = safe_div(c - eta * ct, c + eta * ct)
    rp = safe_div(eta * c - ct, eta * c + ct)
    f = np.where(ct2 < 0.0, 1.0, 0.5 * (rs * rs + rp * rp))
    return np.where(eta == 1.0, 0.0, f)  # exact even where c² underflows


def _conductor_ab(c: Real, eta: Real, k: Real) -> Real:
    """a² + b² and a of the conductor Fresnel formula (a + ib = sqrt(η̂² − sin²θ))."""
    s2 = 1.0 - c * c
    t0 = (eta * eta - 1.0) - k * k + c * c  # η² − k² − sin²θ, exact at η = 1, k = 0
    a2b2 = np.sqrt(t0 * t0 + 4.0 * eta * eta * k * k)
    a = np.sqrt(np.maximum(0.5 * (a2b2 + t0), 0.0))
    return a2b2, a, s2


def fresnel_conductor(cos_theta: Real, eta: Real, k: Real) -> Real:
    """Exact unpolarised Fresnel reflectance for a complex index η̂ = η + i k.

    With c = cos θ, s² = 1 − c², t0 = η² − k² − s², a² + b² = sqrt(t0² + 4η²k²),
    a = sqrt((a² + b² + t0)/2):
        R_s = (a² + b² − 2ac + c²)/(a² + b² + 2ac + c²)
        R_p = R_s · (c²(a² + b²) − 2ac s² + s⁴)/(c²(a² + b²) + 2ac s² + s⁴)
        F = (R_s + R_p)/2
    Real arithmetic only (GLSL friendly). k = 0 reproduces ``fresnel_dielectric``
    (including TIR for η < 1 and F ≡ 0 for η = 1); grazing (c = 0) gives 1 unless
    η̂ = 1. (Born & Wolf §13.2; Lazányi & Szirmay-Kalos 2005; Pharr et al., PBRT.)
    """
    c = _cos(cos_theta)
    eta, k = np.asarray(eta, float), np.asarray(k, float)
    a2b2, a, s2 = _conductor_ab(c, eta, k)
    rs = safe_div(a2b2 - 2.0 * a * c + c * c, a2b2 + 2.0 * a * c + c * c)
    p_num = c * c * a2b2 - 2.0 * a * c * s2 + s2 * s2
    p_den = c * c * a2b2 + 2.0 * a * c * s2 + s2 * s2
    rp = rs * safe_div(p_num, p_den)
    return np.clip(0.5 * (rs + rp), 0.0, 1.0)


def fresnel_schlick(cos_theta: Real, f0: Real, f90: Real = 1.0) -> Real:
    """Schlick 1994: F = F0 + (F90 − F0)(1 − cos θ)⁵."""
    c = _cos(cos_theta)
    f0 = np.asarray(f0, dtype=np.float64)
    return f0 + (np.asarray(f90, float) - f0) * (1.0 - c) ** 5


def _f82_shape(c: Real) -> Real:
    """The F82 correction shape μ(1 − μ)⁶ / (μ̄(1 − μ̄)⁶), 1 at μ = μ̄ = 1/7."""
    return c * (1.0 - c) ** 6 / (MU_BAR * (1.0 - MU_BAR) ** 6)


def fresnel_f82(cos_theta: Real, f0: Real, f82: Real) -> Real:
    """Hoffman 2019 "F82" model with the measured reflectance F82 at θ = acos(1/7).

        F(μ) = Schlick(F0, μ) − [Schlick(F0, μ̄) − F82] · μ(1 − μ)⁶ / (μ̄(1 − μ̄)⁶)
    so that F(μ̄) = F82 exactly. (Hoffman, "Fresnel Equations Considered Harmful",
    EGSR 2019; OpenPBR 1.0 §metal.) Clipped below at 0 only: measured F0 can exceed 1
    in linear sRGB (gold's red channel), and the model is then reproduced unclipped.
    """
    c = _cos(cos_theta)
    f0, f82 = np.asarray(f0, float), np.asarray(f82, float)
    dip = fresnel_schlick(MU_BAR, f0) - f82
    return np.maximum(fresnel_schlick(c, f0) - dip * _f82_shape(c), 0.0)


def f82_from_tint(f0: Real, tint: Real) -> Real:
    """F82 = tint · Schlick(F0, μ̄) (OpenPBR ``specular_color`` as the F82 tint)."""
    return np.asarray(tint, float) * fresnel_schlick(MU_BAR, f0)


def fresnel_f82_tint(cos_theta: Real, f0: Real, tint: Real) -> Real:
    """The OpenPBR F82-tint form: ``fresnel_f82`` with F82 = tint · Schlick(F0, 1/7).

    Expanded: F(μ) = Schlick(F0, μ) − Schlick(F0, μ̄)(1 − tint) μ(1 − μ)⁶/(μ̄(1 − μ̄)⁶).
    tint = 1 reduces to Schlick.
    """
    return fresnel_f82(cos_theta, f0, f82_from_tint(f0, tint))


def fresnel_average(fresnel: Callable[[Real], Real], n: int = 64) -> Real:
    """Hemispherical (cosine-weighted) average F_avg = 2∫₀¹ F(μ) μ dμ.

    ``fresnel`` is a callable of μ of shape (n, ...) → (n, ...); Gauss–Legendre
    quadrature with ``n`` nodes. (Kulla & Conty 2017.)
    """
    x, w = np.polynomial.legendre.leggauss(n)
    mu = 0.5 * (x + 1.0)
    values = np.asarray(fresnel(mu), dtype=np.float64)
    weights = (w * mu).reshape((n,) + (1,) * (values.ndim - 1))
    return np.sum(values * weights, axis=0)


def fresnel_schlick_average(f0: Real) -> Real:
    """Closed form of ``fresnel_average`` for Schlick: F0 + (1 − F0)/21."""
    f0 = np.asarray(f0, float)
    return f0 + (1.0 - f0) / 21.0
