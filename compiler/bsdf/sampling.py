"""Importance sampling of an IR material's reflection lobes: a one-sample mixture of
cosine-weighted hemisphere sampling and GGX visible-normal sampling (Heitz 2018) of the
base lobe and of the coat lobe, evaluated with the mixture (balance-heuristic) pdf.

The shares per strategy depend on the model (`lobe_shares`); the preview's Monte Carlo
tiers and the Mitsuba `cnlm` plugin both use them. Everything is vectorized over lanes:
α may be one number or one value per lane.
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np

from .geometry import Real, cos_theta
from .integrate import cosine_pdf, sample_cosine
from .microfacet import reflect_about, sample_ggx_vndf, vndf_pdf

#: base model -> share of samples (cosine, base specular, coat specular): without, with a coat.
LOBE_SHARES = {
    "diffuse": ((1.0, 0.0, 0.0), (0.5, 0.0, 0.5)),
    "dielectric": ((0.5, 0.5, 0.0), (0.4, 0.3, 0.3)),
    "conductor": ((0.1, 0.9, 0.0), (0.1, 0.45, 0.45)),
    "glass": ((0.1, 0.9, 0.0), (0.1, 0.45, 0.45)),
}


def lobe_shares(base: str, coated: bool) -> tuple[float, float, float]:
    """(cosine, base lobe, coat lobe) shares of samples for a base model, summing to 1."""
    return LOBE_SHARES[base][bool(coated)]


def mixture_pdf(
    wo: Real, wi: Real, shares: Sequence[float], base_alpha: tuple[Real, Real], coat_alpha: tuple[Real, Real]
) -> Real:
    """Solid-angle pdf of wi under the mixture; `base_alpha`/`coat_alpha` are (αx, αy)."""
    pdf = shares[0] * cosine_pdf(wi)
    if shares[1] > 0:
        pdf = pdf + shares[1] * vndf_pdf(wo, wi, *base_alpha)
    if shares[2] > 0:
        pdf = pdf + shares[2] * vndf_pdf(wo, wi, *coat_alpha)
    return pdf


def sample_mixture(
    wo: Real,
    u0: Real,
    u1: Real,
    u2: Real,
    shares: Sequence[float],
    base_alpha: tuple[Real, Real],
    coat_alpha: tuple[Real, Real],
) -> Real:
    """One direction wi per lane: the strategy is chosen by u0 against the shares, then
    (u1, u2) drive it. Directions below the surface are returned as they are (pdf 0)."""
    wi = sample_cosine(u1, u2)
    for share_index, alpha in ((1, base_alpha), (2, coat_alpha)):
        low = sum(shares[:share_index])
        chosen = (u0 >= low) & (u0 < low + shares[share_index])
        if shares[share_index] > 0 and np.any(chosen):
            ax, ay = alpha
            lobe = reflect_about(wo, sample_ggx_vndf(wo, ax, ay, u1, u2))
            wi = np.where(chosen[..., None], lobe, wi)
    return wi


def sampled_weight(f: Real, wo: Real, wi: Real, pdf: Real) -> np.ndarray:
    """f cos θi / pdf per lane (0 where the pdf or cos θi vanishes), RGB (..., 3)."""
    ok = (pdf > 0) & (cos_theta(wi) > 0) & (cos_theta(wo) > 0)
    scale = np.where(ok, cos_theta(wi) / np.where(ok, pdf, 1.0), 0.0)
    return np.where(np.isfinite(f), f, 0.0) * scale[..., None]
