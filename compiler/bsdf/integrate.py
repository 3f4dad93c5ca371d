"""Deterministic hemisphere integration (quasi-Monte-Carlo) for albedo/furnace tests.

Point set: the 2-D golden-ratio (Fibonacci) lattice u_i = ((i + ½)/N, frac(i/φ)), a
low-discrepancy rank-1 lattice. Strategies: cosine-weighted hemisphere sampling
(pdf = cos θ/π) and GGX visible-normal sampling (Heitz 2018), combined with the
balance heuristic (Veach 1997) when a lobe width is given:

    A(wo) = ∫ f(wo, wi) cos θi dωi ≈ Σ_{all 2N samples} f cos θi / (N (p_cos + p_vndf))
"""

from __future__ import annotations

from collections.abc import Callable, Sequence

import numpy as np

from .geometry import Real, as_dirs, cos_theta, dir_from_mu
from .microfacet import reflect_about, sample_ggx_vndf, vndf_pdf

GOLDEN = 0.5 * (np.sqrt(5.0) - 1.0)


def lattice_2d(n: int) -> Real:
    """(u1, u2), each shape (n,): ((i + ½)/n, frac(i · (√5 − 1)/2))."""
    i = np.arange(n, dtype=np.float64)
    return (i + 0.5) / n, np.mod(i * GOLDEN + 0.5 / n, 1.0)


def sample_cosine(u1: Real, u2: Real) -> Real:
    """Cosine-weighted hemisphere direction (Malley): r = √u1, φ = 2π u2."""
    r, phi = np.sqrt(u1), 2.0 * np.pi * u2
    z = np.sqrt(np.maximum(1.0 - u1, 0.0))
    return np.stack([r * np.cos(phi), r * np.sin(phi), z], axis=-1)


def cosine_pdf(wi: Real) -> Real:
    """pdf of ``sample_cosine``: max(cos θ, 0)/π."""
    return np.maximum(cos_theta(wi), 0.0) / np.pi


def _weighted(values: Real, weights: Real) -> Real:
    """Σ over the sample axis (the last one of `weights`) of values × weights."""
    values = np.asarray(values, dtype=np.float64)
    if values.ndim == weights.ndim:
        return np.sum(values * weights, axis=-1)
    return np.sum(values * weights[..., None], axis=-2)


def albedo_cosine(bsdf: Callable[[Real, Real], Real], wo: Real, n: int = 4096) -> Real:
    """∫ f(wo, wi) cos θi dωi by cosine-weighted QMC: (π/N) Σ f.  wo shape (3,)."""
    wi = sample_cosine(*lattice_2d(n))
    wo_b = np.broadcast_to(as_dirs(wo), wi.shape)
    return _weighted(bsdf(wo_b, wi), np.full(n, np.pi / n))


def albedo_mis(bsdf: Callable[[Real, Real], Real], wo: Real, lobes: Sequence[tuple[Real, Real]], n: int = 4096) -> Real:
    """∫ f cos θi dωi by balance-heuristic MIS of cosine sampling and GGX-VNDF sampling
    for every (αx, αy) in ``lobes`` (n samples per strategy):

        A ≈ Σ_{all samples} f cos θi / (n Σ_s p_s(wi))
    Robust for sharp lobes (GGX, Ward) down to α = 1e-3 and for grazing wo. ``wo`` may be
    one direction (3,) or a batch (..., 3): every direction gets the same point set, and
    the result has the batch's shape (followed by the BSDF's channels).
    """
    wo = as_dirs(wo)
    u1, u2 = lattice_2d(n)
    wo_n = np.broadcast_to(wo[..., None, :], wo.shape[:-1] + (n, 3))
    wi_c = np.broadcast_to(sample_cosine(u1, u2), wo_n.shape)
    samples = [wi_c] + [reflect_about(wo_n, sample_ggx_vndf(wo_n, ax, ay, u1, u2)) for ax, ay in lobes]
    wi = np.concatenate(samples, axis=-2)
    wo_all = np.broadcast_to(wo[..., None, :], wi.shape)
    pdf = cosine_pdf(wi) + sum(vndf_pdf(wo_all, wi, ax, ay) for ax, ay in lobes)
    ok = (pdf > 0) & (cos_theta(wi) > 0)
    weight = np.where(ok, cos_theta(wi) / np.where(ok, pdf * n, 1.0), 0.0)
    return _weighted(bsdf(wo_all, wi), weight)


def albedo_at_mu(
    bsdf: Callable[[Real, Real], Real],
    mu: Real,
    ax: Real | None = None,
    ay: Real | None = None,
    n: int = 4096,
    phi: float = 0.0,
) -> Real:
    """Directional albedo at cos θo = mu (azimuth φ): MIS if α is given, else cosine."""
    wo = dir_from_mu(mu, phi)
    if ax is None:
        return albedo_cosine(bsdf, wo, n)
    return albedo_mis(bsdf, wo, [(ax, ax if ay is None else ay)], n)
