"""A dielectric coat over a base BSDF, after Weidlich & Wilkie 2007
("Arbitrarily layered micro-facet surfaces", GRAPHITE 2007).

    f(wo, wi) = f_coat(wo, wi)
              + (1 − F(cos θo)) (1 − F(cos θi)) · a(wo', wi') · [f_spec(wo', wi') / η_c²
                                                               + f_diff(wo', wi')]

- f_coat: GGX reflection of the coat (``microfacet_reflection`` with the exact
  dielectric Fresnel of the coat IOR η_c at the half-vector angle).
- wo', wi': the directions refracted into the coat at the *macro* normal (Snell:
  same azimuth, sin θ' = sin θ / η_c, pointing up). The base is evaluated with them.
- (1 − F): Fresnel transmittance at entry and exit, at the macro-normal angles.
- a: coat absorption along the two refracted path lengths,
      a = color ^ (thickness · (1/cos θo' + 1/cos θi') / 2)
  so that ``color`` is the round-trip transmittance at normal incidence for
  thickness 1 (our reading of the IR's "transmittance tint at normal incidence").
- The base is given in two parts. Its specular (directional) part gets the
  radiance/solid-angle compression 1/η_c² (exit radiance ÷ η_c², and
  cos θi dωi = η_c² cos θi' dωi'), which makes the single pass exact and keeps the
  base lobe's albedo. Its diffuse part does not: for a diffuse base the light
  trapped by total internal reflection returns after further bounces, and in the
  white limit that return balances the 1/η_c² compression (physically the white
  result is 1 − F(cos θo); this form gives (1 − F(cos θo))(1 − F_avg), ≤ 1).

Approximations (as in Weidlich & Wilkie): no explicit inter-reflection between coat
and base; refraction at the macro normal (the coat's roughness does not blur the
transmitted directions); transmission Fresnel at the macro-normal angle. The sum is
symmetric in wo, wi, hence reciprocal if the base is.
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np

from .fresnel import fresnel_dielectric
from .geometry import Real, as_dirs, both_upper, cos_theta
from .microfacet import microfacet_reflection


def refract_into_coat(w: Real, eta: Real) -> Real:
    """Direction inside a coat of relative IOR η ≥ 1, refracted at the macro normal.

    (x, y, z) → (x/η, y/η, sqrt(1 − (x² + y²)/η²)): same azimuth, sin θ' = sin θ/η.
    Directions below the horizon keep z' = 0 (they are masked by the caller).
    """
    w = as_dirs(w)
    xy = w[..., :2] / eta
    z = np.sqrt(np.maximum(1.0 - np.sum(xy * xy, axis=-1), 0.0))
    z = np.where(cos_theta(w) > 0, z, 0.0)
    return np.concatenate([xy, z[..., None]], axis=-1)


def coat_absorption(wo_in: Real, wi_in: Real, color: Real, thickness: Real) -> Real:
    """a = color^(thickness (1/cos θo' + 1/cos θi')/2), RGB (..., 3); 1 for thickness 0."""
    inv = 1.0 / np.maximum(cos_theta(wo_in), 1e-12) + 1.0 / np.maximum(cos_theta(wi_in), 1e-12)
    color = np.clip(np.asarray(color, dtype=np.float64), 0.0, 1.0)
    return np.power(color, (0.5 * thickness * inv)[..., None])


def coat_transmission(wo: Real, wi: Real, ior: Real) -> Real:
    """(1 − F(cos θo)) (1 − F(cos θi)) with the exact dielectric Fresnel of the coat."""
    return (1.0 - fresnel_dielectric(cos_theta(wo), ior)) * (1.0 - fresnel_dielectric(cos_theta(wi), ior))


def coat_specular(wo: Real, wi: Real, ior: Real, ax: Real, ay: Real) -> Real:
    """The coat's own GGX reflection lobe (scalar, colourless)."""
    return microfacet_reflection(wo, wi, ax, ay, lambda c: fresnel_dielectric(c, ior))


def coated(
    wo: Real,
    wi: Real,
    base: Callable[[Real, Real], tuple[Real, Real]],
    ior: Real = 1.5,
    alpha: Real = (0.001, 0.001),
    color: Real = (1.0, 1.0, 1.0),
    thickness: Real = 0.0,
) -> Real:
    """Weidlich–Wilkie coat over ``base``: a callable (wo', wi') → (f_spec, f_diff),
    both RGB (..., 3) (see the module docstring for how each part is transmitted).

    ``alpha`` = (αx, αy) of the coat; ``color`` and ``thickness`` as in the IR coat
    entry. Returns RGB (..., 3); 0 below the horizon.
    """
    wo, wi = as_dirs(wo), as_dirs(wi)
    wo_in, wi_in = refract_into_coat(wo, ior), refract_into_coat(wi, ior)
    through = coat_transmission(wo, wi, ior) * both_upper(wo, wi)
    f_spec, f_diff = base(wo_in, wi_in)
    under = (f_spec / (ior * ior) + f_diff) * coat_absorption(wo_in, wi_in, color, thickness)
    spec = coat_specular(wo, wi, ior, alpha[0], alpha[1])
    return spec[..., None] + through[..., None] * under
