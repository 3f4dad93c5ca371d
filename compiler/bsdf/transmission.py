"""Rough dielectric transmission (BTDF) and the full two-sided glass BSDF.

Walter, Marschner, Li & Torrance 2007, "Microfacet models for refraction through rough
surfaces", eq. 21, with GGX and Smith masking (Heitz 2014). Conventions (docs/bsdf.md):

- local frame n = +z; the **outside** (air, index 1) is z > 0, the **inside** (index
  ``ior``) is z < 0. ``wo`` points towards the viewer, ``wi`` towards the light; a
  transmission pair has wo and wi on opposite sides.
- η_o, η_i: the indices of the media on wo's and wi's side (1 or ``ior``).
- generalized half vector h = −(η_i wi + η_o wo)/|…|, oriented to h_z ≥ 0.
- the BTDF (radiance transport, wo = direction the radiance leaves towards the viewer):

      f_t(wo, wi) = |wi·h| |wo·h| / (|wi·n| |wo·n|)
                    · η_o² (1 − F) D(h) G2(wo, wi) / (η_i wi·h + η_o wo·h)²

  not multiplied by |cos θi|. For importance (adjoint) transport the value is
  f_t · (η_i/η_o)²; both obey the generalized reciprocity f_t(wo, wi)/η_o² = f_t(wi, wo)/η_i².
- F is the dielectric Fresnel at the microfacet, evaluated on the outside direction
  (cos = |w_out·h|, relative index ``ior``): the same value from both sides (Stokes), so
  reciprocity holds bitwise up to rounding.

Edges: η = 1 (the interface is invisible: transmission is the delta wi = −wo of weight 1,
the non-delta part returned here is 0); pairs no microfacet can refract into each other
(past the critical angle: total internal reflection) give exactly 0; α < ALPHA_MIRROR is the
smooth interface (non-delta part 0, see ``mirror_transmittance``); directions within
COS_EPS of the plane give 0.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from .alpha import ALPHA_MIRROR
from .evaluate import evaluate, local_dirs, material_alpha, with_ior
from .fresnel import f0_from_ior, fresnel_dielectric, fresnel_schlick
from .geometry import COS_EPS, Real, as_dirs, dot, normalize, safe_div
from .inputs import MaterialLike, as_material
from .microfacet import ggx_d, is_mirror, smith_lambda

#: Masking-shadowing forms for transmission pairs (see ``transmission_g2``).
G2_FORMS = ("correlated", "separable", "beta")
#: Transport modes: radiance (wo = towards the viewer) or importance (adjoint).
MODES = ("radiance", "importance")


def side_index(w: Real, ior: Real) -> Real:
    """Index of refraction of the medium w points into: 1 above (z > 0), ``ior`` below."""
    return np.where(as_dirs(w)[..., 2] > 0.0, 1.0, np.asarray(ior, float))


def opposite_sides(wo: Real, wi: Real) -> Real:
    """Mask of transmission pairs: |cos θ| ≥ COS_EPS for both and opposite signs."""
    zo, zi = wo[..., 2], wi[..., 2]
    return (np.abs(zo) >= COS_EPS) & (np.abs(zi) >= COS_EPS) & (zo * zi < 0.0)


def generalized_half_vector(wo: Real, wi: Real, eta_o: Real, eta_i: Real) -> Real:
    """h = −(η_i wi + η_o wo)/|η_i wi + η_o wo|, flipped so that h_z ≥ 0 (Walter 2007 eq. 16).

    The zero vector when η_i wi + η_o wo = 0 (η_i = η_o and wi = −wo: the delta direction).
    """
    h = -normalize(eta_i[..., None] * wi + eta_o[..., None] * wo)
    return np.where((h[..., 2] < 0.0)[..., None], -h, h)


def refraction_possible(wo: Real, wi: Real, h: Real) -> Real:
    """χ⁺ terms of Walter 2007 eq. 21 / Heitz 2014: each direction is on the same side of the
    microfacet as of the macro surface, (w·h)(w·n) > 0, and h is not degenerate."""
    return (dot(wo, h) * wo[..., 2] > 0.0) & (dot(wi, h) * wi[..., 2] > 0.0) & (h[..., 2] > 0.0)


def _upper(w: Real) -> Real:
    """w mirrored into the upper hemisphere (z → |z|): Λ depends on |tan θ| only."""
    return w * np.where(w[..., 2] < 0.0, -1.0, 1.0)[..., None]


def _log_beta_1p(a: Real, b: Real) -> Real:
    """log B(1 + a, 1 + b) = lgamma(1+a) + lgamma(1+b) − lgamma(2+a+b)."""
    lg = np.vectorize(math.lgamma, otypes=[float])
    return lg(1.0 + a) + lg(1.0 + b) - lg(2.0 + a + b)


def transmission_g2(wo: Real, wi: Real, ax: Real, ay: Real, form: str = "correlated") -> Real:
    """Masking-shadowing of a transmission pair (Λ of the directions mirrored to z > 0).

        "correlated":  G2 = 1 / (1 + Λ(wo) + Λ(wi))   (the reflection lobe's form; PBRT-v4)
        "separable":   G2 = G1(wo) G1(wi) = 1/((1 + Λ(wo))(1 + Λ(wi)))   (Walter 2007, Mitsuba 3)
        "beta":        G2 = B(1 + Λ(wo), 1 + Λ(wi))   (Heitz 2014 §6, height-correlated
                       transmission: ∫₀¹ C^Λo (1 − C)^Λi dC)
    All three reduce to G1 of the other direction when one Λ is 0, and are ≤ min(G1(wo), G1(wi)).
    """
    lo, li = smith_lambda(_upper(wo), ax, ay), smith_lambda(_upper(wi), ax, ay)
    if form == "correlated":
        return 1.0 / (1.0 + lo + li)
    if form == "separable":
        return 1.0 / ((1.0 + lo) * (1.0 + li))
    if form == "beta":
        return np.exp(_log_beta_1p(lo, li))
    raise ValueError(f"unknown G2 form {form!r}; use one of {G2_FORMS}")


def interface_fresnel(cos_outside: Real, ior: Real, fresnel: str = "exact") -> Real:
    """F at the microfacet from the outside angle: exact dielectric(ior), or Schlick(F0(ior))."""
    if fresnel == "exact":
        return fresnel_dielectric(cos_outside, ior)
    return fresnel_schlick(cos_outside, f0_from_ior(ior))


def mode_scale(eta_o: Real, eta_i: Real, mode: str = "radiance") -> Real:
    """1 for radiance transport, (η_i/η_o)² for importance transport."""
    if mode == "radiance":
        return np.ones_like(eta_o)
    if mode == "importance":
        return (eta_i / eta_o) ** 2
    raise ValueError(f"unknown transport mode {mode!r}; use one of {MODES}")


def microfacet_transmission(
    wo: Real,
    wi: Real,
    ax: Real,
    ay: Real,
    ior: Real,
    g2: str = "correlated",
    mode: str = "radiance",
    fresnel: str = "exact",
) -> Real:
    """The rough dielectric BTDF f_t(wo, wi) of the module docstring (scalar, shape (...)).

    Exactly 0 for same-side pairs, directions within COS_EPS of the plane, ior = 1, pairs no
    microfacet can refract (TIR region) and α below ALPHA_MIRROR (both axes).
    """
    wo, wi = as_dirs(wo), as_dirs(wi)
    ax, ay = np.asarray(ax, float), np.asarray(ay, float)
    ior = np.asarray(ior, float)
    eta_o, eta_i = side_index(wo, ior), side_index(wi, ior)
    h = generalized_half_vector(wo, wi, eta_o, eta_i)
    ok = opposite_sides(wo, wi) & refraction_possible(wo, wi, h) & (ior != 1.0) & ~is_mirror(ax, ay)
    ax_c, ay_c = np.maximum(ax, ALPHA_MIRROR), np.maximum(ay, ALPHA_MIRROR)
    oh, ih = dot(wo, h), dot(wi, h)
    cos_out = np.abs(np.where(wo[..., 2] > 0.0, oh, ih))
    one_minus_f = 1.0 - interface_fresnel(cos_out, ior, fresnel)
    den = (eta_i * ih + eta_o * oh) ** 2 * np.abs(wo[..., 2] * wi[..., 2])
    jac = safe_div(np.abs(ih * oh) * eta_o**2, np.where(ok, den, 1.0))
    value = jac * one_minus_f * ggx_d(h, ax_c, ay_c) * transmission_g2(wo, wi, ax_c, ay_c, g2)
    value = value * mode_scale(eta_o, eta_i, mode)
    return np.where(ok & np.isfinite(value), value, 0.0)


def dielectric_reflection(
    wo: Real, wi: Real, ax: Real, ay: Real, ior: Real, g2: str = "correlated", fresnel: str = "exact"
) -> Real:
    """Reflection lobe of the interface seen from either side: F D G2 / (4 |cos θo| |cos θi|).

    Both directions above: η = ior; both below (inside the glass): the mirrored configuration
    with η = 1/ior (TIR → F = 1). G2 as in ``transmission_g2`` ("correlated" is the library's
    reflection G2, "separable" Mitsuba's, "beta" falls back to "correlated" for reflection).
    """
    wo, wi = as_dirs(wo), as_dirs(wi)
    ax, ay = np.asarray(ax, float), np.asarray(ay, float)
    same = (wo[..., 2] * wi[..., 2] > 0.0) & (np.abs(wo[..., 2]) >= COS_EPS) & (np.abs(wi[..., 2]) >= COS_EPS)
    uo, ui = _upper(wo), _upper(wi)
    h = normalize(uo + ui)
    ok = same & (h[..., 2] > 0.0) & ~is_mirror(ax, ay)
    ax_c, ay_c = np.maximum(ax, ALPHA_MIRROR), np.maximum(ay, ALPHA_MIRROR)
    eta = np.where(wo[..., 2] > 0.0, np.asarray(ior, float), 1.0 / np.asarray(ior, float))
    cos_d = np.clip(0.5 * (dot(uo, h) + dot(ui, h)), 0.0, 1.0)
    f = fresnel_dielectric(cos_d, eta) if fresnel == "exact" else fresnel_schlick(cos_d, f0_from_ior(ior))
    lo, li = smith_lambda(uo, ax_c, ay_c), smith_lambda(ui, ax_c, ay_c)
    g = 1.0 / ((1.0 + lo) * (1.0 + li)) if g2 == "separable" else 1.0 / (1.0 + lo + li)
    den = 4.0 * np.abs(wo[..., 2] * wi[..., 2])
    value = f * ggx_d(h, ax_c, ay_c) * safe_div(g, np.where(ok, den, 1.0))
    return np.where(ok & np.isfinite(value), value, 0.0)


def refract(w: Real, ior: Real) -> Real:
    """Refract w (pointing away from the surface) through the smooth interface (normal +z).

    Returns (t, ok): t = −(w/η_rel) + (c/η_rel − c_t) n with η_rel = η_t/η_w and the sign
    of n chosen on w's side; ok is False under total internal reflection (t = 0 there).
    """
    w = as_dirs(w)
    ior = np.asarray(ior, float)
    eta_rel = side_index(-w, ior) / side_index(w, ior)
    c = np.abs(w[..., 2])
    ct2 = 1.0 - (1.0 - c * c) / (eta_rel * eta_rel)
    ok = ct2 >= 0.0
    ct = np.sqrt(np.maximum(ct2, 0.0))
    sign = np.where(w[..., 2] > 0.0, 1.0, -1.0)
    t = -w / eta_rel[..., None]
    t = t.copy()
    t[..., 2] = -sign * ct
    return np.where(ok[..., None], t, 0.0), ok


def mirror_transmittance(wo: Real, ior: Real, mode: str = "radiance") -> Real:
    """The delta (smooth interface) transmission for α < ALPHA_MIRROR.

    Returns (wi, weight): wi the refracted direction of wo and weight = (1 − F) · s, F the
    Fresnel of the interface (the same from both sides), s = (η_o/η_i)² for radiance and 1 for
    importance transport. Under total internal reflection (wo inside, sin θo > 1/ior) and for
    wo within COS_EPS of the plane, wi = 0 and the weight is exactly 0. ior = 1: wi = −wo,
    weight 1.
    """
    wo = as_dirs(wo)
    ior = np.asarray(ior, float)
    wi, ok = refract(wo, ior)
    eta_o, eta_i = side_index(wo, ior), side_index(-wo, ior)
    cos_out = np.where(wo[..., 2] > 0.0, wo[..., 2], np.abs(wi[..., 2]))
    weight = (1.0 - fresnel_dielectric(cos_out, ior)) * (eta_o / eta_i) ** 2 * mode_scale(eta_o, eta_i, mode)
    visible = ok & (np.abs(wo[..., 2]) >= COS_EPS)
    return np.where(visible[..., None], wi, 0.0), np.where(visible, weight, 0.0)


#: the darkest transmittance a target's glass medium is given (the preview's shader, Mitsuba's medium,
#: glTF's attenuation): a colour channel of 0 would need an infinite extinction, 9.2 / depth here
DARKEST_TRANSMITTANCE = 1e-4


def absorption(material: MaterialLike, length: Any) -> Real:
    """The glass's transmittance along a path of `length` metres inside it, RGB (..., 3):
    base_color^(length / transmission_depth) (Beer-Lambert). A colour channel of 0 passes
    nothing along any path longer than 0; a path of length 0 passes everything."""
    material = as_material(material)
    colour = np.clip(np.asarray(material.params.base_color, float), 0.0, 1.0)
    length = np.asarray(length, float)[..., None]
    ratio = np.where(length > 0.0, length, 0.0) / float(material.params.transmission_depth)  # NaN stays NaN
    with np.errstate(divide="ignore", invalid="ignore"):
        kept = np.exp(ratio * np.log(colour))  # NaN at 0 * log(0) and inf * log(1): replaced below
    kept = np.where(colour >= 1.0, 1.0, np.where(colour > 0.0, kept, 0.0))
    return np.where(np.isnan(length), np.nan, np.where(ratio > 0.0, kept, 1.0))


def evaluate_transmission(
    material: MaterialLike, wo: Any, wi: Any, g2: str = "correlated", mode: str = "radiance", fresnel: str = "exact"
) -> Real:
    """The material's BTDF f_t(wo, wi), RGB (..., 3): the interface alone, colourless; the glass's
    colour is absorbed along the path inside (``absorption``), which the geometry decides.

    Non-zero only for ``model.base == "glass"`` and pairs on opposite sides of the surface.
    ``fresnel="schlick"``/``"f82"``: 1 − Schlick(F0(ior)) at the outside angle.
    """
    material = as_material(material)
    wo, wi = local_dirs(material, wo, wi)
    shape = np.broadcast_shapes(wo.shape, wi.shape)[:-1]
    if material.model.base != "glass":
        return np.zeros(shape + (3,))
    ax, ay = material_alpha(material)
    ior = float(material.params.ior)
    ft = microfacet_transmission(wo, wi, ax, ay, ior, g2, mode, "exact" if fresnel == "exact" else "schlick")
    return np.repeat(np.broadcast_to(ft, shape)[..., None], 3, axis=-1)


def evaluate_bsdf(
    material: MaterialLike,
    wo: Any,
    wi: Any,
    fresnel: str = "exact",
    multiscatter: bool = False,
    ward_form: str = "gmd",
    g2: str = "correlated",
    mode: str = "radiance",
) -> Real:
    """The full BSDF, RGB (..., 3): ``evaluate`` (reflection) for pairs above the surface,
    ``evaluate_transmission`` for pairs on opposite sides and, for glass, the internal
    reflection (the mirrored pair with η = 1/ior) for pairs below it. Opaque models are 0
    below the horizon, as in ``evaluate``.
    """
    material = as_material(material)
    wo, wi = as_dirs(wo), as_dirs(wi)
    shape = np.broadcast_shapes(wo.shape, wi.shape)[:-1]
    wo, wi = np.broadcast_to(wo, shape + (3,)), np.broadcast_to(wi, shape + (3,))
    out = evaluate(material, wo, wi, fresnel=fresnel, multiscatter=multiscatter, ward_form=ward_form)
    if material.model.base != "glass":
        return out
    out = out + evaluate_transmission(material, wo, wi, g2, mode, fresnel)
    below = (wo[..., 2] < 0.0) & (wi[..., 2] < 0.0)
    if below.any():
        inner = with_ior(material, 1.0 / float(material.params.ior))
        flip = np.array([1.0, 1.0, -1.0])
        out = out + np.where(
            below[..., None], evaluate(inner, wo * flip, wi * flip, fresnel=fresnel, ward_form=ward_form), 0.0
        )
    return out


def interface_albedo(mu: Any, ior: float, alpha: float, n: int = 2048, g2: str = "correlated") -> tuple[Real, Real]:
    """(R, T): the energy a rough dielectric interface (GGX, isotropic α) reflects and transmits
    (importance: energy, no η² scaling) for light arriving at cos θ = mu from the side whose relative
    index across is ``ior`` (< 1 from inside: TIR). Visible normals sampled from wo (Heitz 2018,
    golden-ratio lattice); each reflects with F·G2/G1 or refracts with (1 − F)·G2/G1, ``g2`` the
    masking–shadowing form ("correlated": 1/(1 + Λo + Λi); "separable": G1 G1, Mitsuba 3's).
    Single scattering: 1 − R − T is the light the model loses (rough glass, docs/bsdf.md)."""
    from .integrate import lattice_2d
    from .microfacet import sample_ggx_vndf

    if g2 not in ("correlated", "separable"):
        raise ValueError(f"unknown G2 form {g2!r}; use correlated or separable")
    a = max(float(alpha), ALPHA_MIRROR)
    mus = np.atleast_1d(np.asarray(mu, np.float64))
    u1, u2 = lattice_2d(n)
    wo = np.broadcast_to(np.stack([np.sqrt(1 - mus**2), 0 * mus, mus], -1)[:, None, :], (len(mus), n, 3))
    h = sample_ggx_vndf(wo, a, a, u1, u2)
    c = np.clip(np.sum(wo * h, axis=-1), 0.0, 1.0)
    fresnel = fresnel_dielectric(c, ior)
    lam_o = smith_lambda(wo, a, a)
    reflected = 2.0 * c[..., None] * h - wo
    ct = np.sqrt(np.maximum(1.0 - (1.0 - c * c) / (ior * ior), 0.0))
    refracted = -wo / ior + (c / ior - ct)[..., None] * h

    def kept(w: Real, ok: Real) -> Real:
        lam_i = smith_lambda(np.abs(w), a, a)
        g = (1 + lam_o) / (1 + lam_o + lam_i) if g2 == "correlated" else 1.0 / (1.0 + lam_i)
        return np.where(ok, g, 0.0)

    r = np.mean(fresnel * kept(reflected, reflected[..., 2] > 0), axis=-1)
    t = np.mean((1.0 - fresnel) * kept(refracted, refracted[..., 2] < 0), axis=-1)
    return r, t


__all__ = [
    "G2_FORMS",
    "MODES",
    "dielectric_reflection",
    "evaluate_bsdf",
    "DARKEST_TRANSMITTANCE",
    "absorption",
    "evaluate_transmission",
    "generalized_half_vector",
    "interface_albedo",
    "microfacet_transmission",
    "mirror_transmittance",
    "refract",
    "refraction_possible",
    "side_index",
    "transmission_g2",
]
