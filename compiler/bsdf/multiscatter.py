"""Kulla & Conty 2017 multiple-scattering energy compensation for GGX.

Single-scattering GGX loses energy: its white-furnace albedo E(μ) < 1 (0.306 at α = 1,
μ = 1). Kulla & Conty ("Revisiting physically based shading at Imageworks", SIGGRAPH
2017 course) add a diffuse-like lobe that returns the missing energy:

    f_ms(μo, μi) = (1 − E(μo)) (1 − E(μi)) / (π (1 − E_avg))
    E_avg        = 2 ∫₀¹ E(μ) μ dμ
and, for a coloured (Fresnel) lobe, scale it by the average multiply-bounced Fresnel

    F_ms = F_avg² E_avg / (1 − F_avg (1 − E_avg)),     F_avg = 2 ∫₀¹ F(μ) μ dμ

so the white furnace is exactly 1 and coloured metals gain saturation. E(μ, α) is
precomputed once per process (``lru_cache``) on a TABLE_SIZE² grid by QMC
visible-normal sampling and interpolated bilinearly; anisotropic lobes use
α = sqrt(αx αy) (an approximation).
"""

from __future__ import annotations

from collections.abc import Callable
from functools import lru_cache

import numpy as np

from .geometry import Real, as_dirs, both_upper, cos_theta, dir_from_mu
from .integrate import lattice_2d
from .microfacet import reflect_about, sample_ggx_vndf, smith_g1, smith_g2

#: Grid points per axis of the E(μ, α) table (μ and α uniform on [0, 1]).
TABLE_SIZE = 32
#: QMC samples per table entry.
TABLE_SAMPLES = 2048
#: Smallest μ and α used when building the table (μ = 0 and α = 0 are limits).
_MU_MIN, _ALPHA_MIN = 1e-3, 1e-3


def ggx_albedo(mu: Real, alpha: Real, n: int = 4096, correlated: bool = True) -> Real:
    """White-furnace directional albedo E(μ) of single-scattering GGX (F = 1).

    Estimated by QMC visible-normal sampling: E(μ) = E_h[G2(wo, wi)/G1(wo)] for the
    height-correlated G2, or E_h[G1(wi)] for the separable G2 = G1(wo) G1(wi).
    ``mu`` and ``alpha`` broadcast; returns their broadcast shape.
    """
    mu, alpha = np.broadcast_arrays(np.asarray(mu, float), np.asarray(alpha, float))
    u1, u2 = lattice_2d(n)
    wo = dir_from_mu(mu)[..., None, :]
    a = alpha[..., None]
    wi = reflect_about(np.broadcast_to(wo, wo.shape[:-2] + (n, 3)), sample_ggx_vndf(wo, a, a, u1, u2))
    if correlated:
        ratio = smith_g2(wo, wi, a, a) / np.maximum(smith_g1(wo, a, a), 1e-300)
    else:
        ratio = smith_g1(wi, a, a)
    return np.mean(ratio, axis=-1)


def average_over_mu(values_of_mu: Callable[[Real], Real], n: int = 32) -> Real:
    """2 ∫₀¹ g(μ) μ dμ by n-point Gauss–Legendre; ``values_of_mu`` maps μ (n,) → (n, ...)."""
    x, w = np.polynomial.legendre.leggauss(n)
    mu = 0.5 * (x + 1.0)
    vals = np.asarray(values_of_mu(mu), dtype=np.float64)
    return np.tensordot(w * mu, vals, axes=(0, 0))


def table_axes() -> Real:
    """The μ and α sample positions of the E table (ends nudged off 0). μ is uniform in sqrt(μ):
    near grazing a smooth lobe's E falls from 1 within a few α of μ = 0, and a uniform μ axis
    blended that drop into μ = 0.02, where the compensation then added 5 % (issue #15: furnace)."""
    grid = np.linspace(0.0, 1.0, TABLE_SIZE)
    return np.maximum(grid * grid, _MU_MIN), np.maximum(grid, _ALPHA_MIN)


@lru_cache(maxsize=1)
def albedo_table() -> Real:
    """E[α_index, μ_index] (TABLE_SIZE², float64), computed once by ``ggx_albedo``."""
    mus, alphas = table_axes()
    rows = [ggx_albedo(mus, a, TABLE_SAMPLES) for a in alphas]
    table = np.stack(rows)
    table.setflags(write=False)
    return table


def _lerp_index(x: Real) -> Real:
    """Fractional grid index of x ∈ [0, 1] on the uniform table axis."""
    t = np.clip(np.asarray(x, float), 0.0, 1.0) * (TABLE_SIZE - 1)
    i0 = np.minimum(np.floor(t).astype(int), TABLE_SIZE - 2)
    return i0, t - i0


def albedo_lookup(mu: Real, alpha: Real) -> Real:
    """Bilinear interpolation of the E(μ, α) table."""
    table = albedo_table()
    ia, fa = _lerp_index(alpha)
    im, fm = _lerp_index(np.sqrt(np.clip(np.asarray(mu, float), 0.0, 1.0)))
    e0 = table[ia, im] * (1 - fm) + table[ia, im + 1] * fm
    e1 = table[ia + 1, im] * (1 - fm) + table[ia + 1, im + 1] * fm
    return e0 * (1 - fa) + e1 * fa


@lru_cache(maxsize=1)
def average_albedo_table() -> Real:
    """E_avg(α) per table row: 2 ∫ E(μ) μ dμ by the trapezoid rule on the table grid."""
    mus = np.linspace(0.0, 1.0, TABLE_SIZE) ** 2
    return np.trapezoid(2.0 * albedo_table() * mus, mus, axis=1)


def average_albedo(alpha: Real) -> Real:
    """E_avg(α), linearly interpolated from ``average_albedo_table``."""
    ia, fa = _lerp_index(alpha)
    tab = average_albedo_table()
    return tab[ia] * (1 - fa) + tab[ia + 1] * fa


def fresnel_multiscatter(f_avg: Real, e_avg: Real) -> Real:
    """F_ms = F_avg² E_avg / (1 − F_avg (1 − E_avg)) (Kulla & Conty 2017)."""
    f_avg, e_avg = np.asarray(f_avg, float), np.asarray(e_avg, float)
    return f_avg * f_avg * e_avg / (1.0 - f_avg * (1.0 - e_avg))


def multiscatter_lobe(wo: Real, wi: Real, alpha: Real, f_avg: Real = 1.0) -> Real:
    """Kulla–Conty compensation BRDF f_ms · F_ms (see module docstring).

    ``f_avg`` scalar or RGB (3,); returns (...) or (..., 3). 0 below the horizon.
    Reciprocal (symmetric in μo, μi). Its albedo is (1 − E(μo)) F_ms exactly (up to
    quadrature), so with F = 1 single + multiple scattering gives a white furnace of 1.
    """
    wo, wi = as_dirs(wo), as_dirs(wi)
    e_o = albedo_lookup(cos_theta(wo), alpha)
    e_i = albedo_lookup(cos_theta(wi), alpha)
    e_avg = average_albedo(alpha)
    lobe = (1.0 - e_o) * (1.0 - e_i) / (np.pi * np.maximum(1.0 - e_avg, 1e-12))
    lobe = np.where(both_upper(wo, wi), lobe, 0.0)
    f_ms = fresnel_multiscatter(f_avg, e_avg)
    return lobe[..., None] * f_ms if np.ndim(f_ms) > np.ndim(e_avg) else lobe * f_ms
