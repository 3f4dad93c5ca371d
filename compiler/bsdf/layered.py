"""A dielectric coat over a base BSDF: Weidlich & Wilkie 2007 ("Arbitrarily layered
micro-facet surfaces", GRAPHITE 2007) for the directional part, and the classical
albedo-dependent inter-reflection of a diffuse base under a smooth dielectric for the diffuse
part (Lekner & Dorf 1988, "Why some things are darker when wet", Applied Optics 27(7); the
same sum as Twomey, Bohren & Mergenthaler 1986, Applied Optics 25(3), and as Mitsuba's
``plastic``/``roughplastic`` with ``nonlinear``):

    f(wo, wi) = f_coat(wo, wi)
              + (1 − F(cos θo)) (1 − F(cos θi)) · a(wo', wi') · [f_spec(wo', wi') / η_c²
                                                               + f_diff(wo', wi') / (η_c² (1 − ρ ⊙ K))]

- f_coat: GGX reflection of the coat (``microfacet_reflection`` with the exact
  dielectric Fresnel of the coat IOR η_c at the half-vector angle).
- wo', wi': the directions refracted into the coat at the *macro* normal (Snell:
  same azimuth, sin θ' = sin θ / η_c, pointing up). The base is evaluated with them.
- (1 − F): Fresnel transmittance at entry and exit, at the macro-normal angles.
- a: coat absorption along the two refracted path lengths,
      a = color ^ (thickness · (1/cos θo' + 1/cos θi') / 2)
  so that ``color`` is the round-trip transmittance at normal incidence for
  thickness 1 (our reading of the IR's "transmittance tint at normal incidence").
- 1/η_c²: the radiance/solid-angle compression of a single pass (exit radiance ÷ η_c², and
  cos θi dωi = η_c² cos θi' dωi'), for both parts of the base.
- The specular (directional) part of the base: the single pass only. Light it sends outside
  the escape cone is lost (a smooth lobe sends almost none; the coat's internal reflection of
  the rest is a few per cent at grazing).
- The diffuse part: the single pass, plus the light the coat reflects back down (all of it
  beyond the critical angle, F inside it) that the base scatters again, summed as a geometric
  series. A diffuse flux inside meets the coat's internal diffuse reflectance K and the base's
  diffuse (bi-hemispherical) reflectance ρ each round trip, so the exit is the single pass
  times 1 + ρK + (ρK)² + … = 1 / (1 − ρK), per channel. Without absorption
      K = F_dr_int = 1 − (1 − F_dr_ext) / η_c²,    F_dr_ext = 2∫₀¹ F(μ) μ dμ
  (a diffuse flux inside: the part inside the escape cone, 1/η_c² of it by étendue, leaves
  with the outside's 1 − F_dr_ext; the rest is reflected). With absorption, each round trip
  at inside cosine μ' also crosses the coat twice: K = 2∫₀¹ F_int(μ') color^(thickness/μ') μ' dμ'.
  ρ is the base's diffuse part's own reflectance (``diffuse_reflectance``: ρ = base_color for
  Lambert; Oren–Nayar's and a dielectric base's own interface are in it).
  Limits: a white Lambert base (ρ = 1, no absorption) gives
      ∫ f cos θi dωi = (1 − F(cos θo)) (1 − F_dr_ext) / (η_c² (1 − F_dr_int)) = 1 − F(cos θo)
  exactly (what is not reflected by the coat comes back out); ρ → 0 gives the single pass
  ρ (1 − F)(1 − F) / (π η_c²); η_c = 1 gives the base unchanged.
- A metal's Kulla–Conty compensation lobe (``series=False``) keeps the earlier treatment: no
  1/η_c² and no sum (its trapped light returns off the metal's own albedo ~0.9, for which the
  sum nearly cancels the compression: 1/(η²(1 − 0.9 F_dr_int)) ≈ 0.96 at η 1.5).

Approximations: refraction and transmission at the macro normal (the coat's roughness does
not blur the transmitted directions); the light trapped under the coat is diffuse after its
first bounce off the base. The sum is symmetric in wo, wi, hence reciprocal if the base is.
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np

from .fresnel import fresnel_dielectric
from .geometry import Real, as_dirs, both_upper, cos_theta
from .microfacet import microfacet_reflection

#: Gauss–Legendre nodes for the coat's internal reflectance (each of its two intervals)
INTERNAL_NODES = 48
#: nodes per dimension (μo, μi, Δφ) for the base's diffuse reflectance
REFLECTANCE_NODES = 16


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


def _nodes(a: float, b: float, n: int) -> tuple[np.ndarray, np.ndarray]:
    x, w = np.polynomial.legendre.leggauss(n)
    return a + 0.5 * (b - a) * (x + 1.0), 0.5 * (b - a) * w


def fresnel_diffuse_reflectance(ior: float, n: int = INTERNAL_NODES) -> float:
    """F_dr_ext = 2∫₀¹ F(μ) μ dμ: a smooth dielectric's reflectance for diffuse light from outside."""
    mu, w = _nodes(0.0, 1.0, n)
    return float(2.0 * np.sum(w * mu * fresnel_dielectric(mu, ior)))


def internal_reflectance(ior: float, color: Real = (1.0, 1.0, 1.0), thickness: float = 0.0) -> np.ndarray:
    """K, RGB (3,): what the coat sends back down of a diffuse flux leaving the base, including
    its absorption over the round trip: K = 2∫₀¹ F_int(μ') color^(thickness/μ') μ' dμ'. Split at
    the critical cosine μc = sqrt(1 − 1/η²): below it F_int = 1 (total internal reflection);
    above it the integral is taken over the outside cosine μ (μ' dμ' = μ dμ / η², F_int(μ') =
    F(μ)), where the integrand is smooth. Without absorption K = 1 − (1 − F_dr_ext)/η² exactly."""
    eta = float(ior)
    color = np.clip(np.broadcast_to(np.asarray(color, np.float64), (3,)), 0.0, 1.0)
    log_c = np.log(np.maximum(color, 1e-300))

    def crossing(mu_in: np.ndarray) -> np.ndarray:  # color^(thickness/μ'), (n, 3); 1 for thickness 0
        if thickness == 0.0:
            return np.ones(mu_in.shape + (3,))
        out: np.ndarray = np.exp(log_c * (thickness / np.maximum(mu_in, 1e-12))[:, None])
        return out

    mu_c = np.sqrt(max(1.0 - 1.0 / (eta * eta), 0.0))
    trapped = np.zeros(3)
    if mu_c > 0.0:
        mu, w = _nodes(0.0, mu_c, INTERNAL_NODES)
        trapped = 2.0 * np.sum((w * mu)[:, None] * crossing(mu), axis=0)
    mu, w = _nodes(0.0, 1.0, INTERNAL_NODES)
    mu_in = np.sqrt(np.maximum(1.0 - (1.0 - mu * mu) / (eta * eta), 0.0))
    escaping = 2.0 / (eta * eta) * np.sum((w * mu * fresnel_dielectric(mu, eta))[:, None] * crossing(mu_in), axis=0)
    total: np.ndarray = trapped + escaping
    return total


def diffuse_reflectance(diffuse: Callable[[Real, Real], Real], n: int = REFLECTANCE_NODES) -> np.ndarray:
    """ρ, RGB (3,): the bi-hemispherical reflectance (1/π)∬ f cos θo cos θi dωo dωi of a BRDF
    part ``diffuse(wo, wi) → (..., 3)``, by Gauss–Legendre in μo, μi and the trapezoidal rule in
    the azimuth difference (periodic): the albedo a diffuse flux sees. Lambert(ρ) gives ρ."""
    mu, w = _nodes(0.0, 1.0, n)
    phi = (np.arange(n) + 0.5) * (2.0 * np.pi / n)
    sin = np.sqrt(1.0 - mu * mu)
    wo = np.stack(np.broadcast_arrays(sin, 0.0 * sin, mu), -1)[:, None, None, :]
    wi = np.stack([sin[:, None] * np.cos(phi), sin[:, None] * np.sin(phi), np.broadcast_to(mu[:, None], (n, n))], -1)
    wo, wi = np.broadcast_arrays(wo, wi[None, :, :, :])
    f = np.broadcast_to(np.asarray(diffuse(wo, wi), np.float64), (n, n, n, 3))
    weight = (w * mu)[:, None, None] * (w * mu)[None, :, None] * (2.0 * np.pi / n)
    rho: np.ndarray = 2.0 * np.einsum("abc,abcd->d", weight, f)
    return rho


def coat_gain(ior: float, reflectance: Real, internal: Real) -> np.ndarray:
    """1 / (η² (1 − ρ ⊙ K)), RGB: what the coat does to the base's diffuse part beyond the
    Fresnel transmittances and the single-pass absorption."""
    rk = np.clip(np.asarray(reflectance, np.float64) * np.asarray(internal, np.float64), 0.0, 1.0 - 1e-9)
    return 1.0 / (float(ior) ** 2 * (1.0 - rk))


def coated(
    wo: Real,
    wi: Real,
    base: Callable[[Real, Real], tuple[Real, Real]],
    ior: Real = 1.5,
    alpha: Real = (0.001, 0.001),
    color: Real = (1.0, 1.0, 1.0),
    thickness: Real = 0.0,
    reflectance: Real | None = None,
    series: bool = True,
) -> Real:
    """The coat over ``base``: a callable (wo', wi') → (f_spec, f_diff), both RGB (..., 3) (see
    the module docstring for how each part is transmitted).

    ``alpha`` = (αx, αy) of the coat; ``color`` and ``thickness`` as in the IR coat entry.
    ``reflectance``: ρ of the base's diffuse part (``diffuse_reflectance``), RGB; None: integrated
    here from ``base`` (which must then take any directions). ``series=False``: the diffuse part
    as a metal's compensation lobe (module docstring). Returns RGB (..., 3); 0 below the horizon.
    """
    wo, wi = as_dirs(wo), as_dirs(wi)
    wo_in, wi_in = refract_into_coat(wo, ior), refract_into_coat(wi, ior)
    through = coat_transmission(wo, wi, ior) * both_upper(wo, wi)
    f_spec, f_diff = base(wo_in, wi_in)
    if series:
        if reflectance is None:
            reflectance = diffuse_reflectance(lambda o, i: base(o, i)[1])
        gain = coat_gain(float(ior), reflectance, internal_reflectance(float(ior), color, float(thickness)))
    else:
        gain = np.ones(3)
    under = (f_spec / (ior * ior) + f_diff * gain) * coat_absorption(wo_in, wi_in, color, thickness)
    spec = coat_specular(wo, wi, ior, alpha[0], alpha[1])
    return spec[..., None] + through[..., None] * under
