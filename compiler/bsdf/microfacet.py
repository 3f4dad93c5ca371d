"""GGX (Trowbridge–Reitz) microfacet reflection with height-correlated Smith masking.

References: Trowbridge & Reitz 1975; Walter et al. 2007 ("Microfacet models for
refraction through rough surfaces"); Heitz 2014 ("Understanding the masking-shadowing
function in microfacet-based BRDFs"); Heitz 2018 (visible-normal sampling).

Every function is written so that it has no 0/0 or ∞ for unit directions: the
stretched length ``|w|_α = sqrt(αx² wx² + αy² wy² + wz²)`` replaces tan θ, and the
BRDF uses the visibility form V = G2 / (4 cos θo cos θi), which is finite at grazing.
"""

from __future__ import annotations

import numpy as np

from .alpha import ALPHA_MIRROR
from .geometry import Real, as_dirs, both_upper, cos_theta, dot, half_vector, reflect, safe_div, upper


def stretched_length(w: Real, ax: Real, ay: Real) -> Real:
    """|w|_α = sqrt(αx² wx² + αy² wy² + wz²)."""
    x, y, z = w[..., 0], w[..., 1], w[..., 2]
    return np.sqrt((ax * x) ** 2 + (ay * y) ** 2 + z * z)


def ggx_d(h: Real, ax: Real, ay: Real) -> Real:
    """Anisotropic GGX normal distribution (Walter 2007 eq. 33; Heitz 2014 eq. 85).

        D(h) = 1 / (π αx αy (hx²/αx² + hy²/αy² + hz²)²)     for hz ≥ 0, else 0.
    For αx = αy = α this is α² / (π cos⁴θh (α² + tan²θh)²). This form has no
    cancellation: in float32 it stays accurate down to α ≈ 1e-19 (compare
    ``ggx_d_common_form``).
    """
    h = as_dirs(h)
    x, y, z = h[..., 0], h[..., 1], h[..., 2]
    q = (x / ax) ** 2 + (y / ay) ** 2 + z * z
    d = safe_div(1.0, np.pi * ax * ay * q * q)
    return np.where(z >= 0.0, d, 0.0)


def ggx_d_isotropic(cos_h: Real, alpha: Real) -> Real:
    """Isotropic GGX D from cos θh: α² / (π (cos²θh (α² − 1) + 1)²) evaluated stably.

    Written as 1/(π α² (sin²θh/α² + cos²θh)²), i.e. ``ggx_d`` with αx = αy = α.
    """
    raw = np.asarray(cos_h, float)
    c = np.clip(raw, 0.0, 1.0)
    alpha = np.asarray(alpha, float)
    q = (1.0 - c * c) / (alpha * alpha) + c * c
    return np.where(raw >= 0.0, safe_div(1.0, np.pi * alpha * alpha * q * q), 0.0)


def ggx_d_common_form(cos_h: Real, alpha: Real) -> Real:
    """The widespread shader form D = α² / (π (cos²θh (α² − 1) + 1)²), dtype-preserving.

    Kept to document its float32 breakdown (brdf_accuracy_checks.json
    "ggx_small_alpha_float32"): (α² − 1) + 1 cancels catastrophically for α ≲ 1e-3, and
    gives ∞ at cos θh = 1 for α ≤ 1e-4. Backends should use the ``ggx_d`` form.
    """
    c = np.asarray(cos_h)
    a2 = np.asarray(alpha, dtype=c.dtype) ** 2
    one = np.asarray(1.0, dtype=c.dtype)
    d = c * c * (a2 - one) + one
    with np.errstate(divide="ignore", over="ignore"):
        return a2 / (np.asarray(np.pi, dtype=c.dtype) * d * d)


def smith_lambda(w: Real, ax: Real, ay: Real) -> Real:
    """Smith Λ for GGX (Heitz 2014 eq. 86), in a cancellation-free form.

        Λ(w) = (sqrt(1 + a²) − 1)/2 = a² / (2 (1 + sqrt(1 + a²))),
        a² = (αx² wx² + αy² wy²) / wz².
    Returns ∞-free values: wz ≤ 0 gives a large finite Λ via the guard (use G1/G2,
    which return 0 there).
    """
    w = as_dirs(w)
    z2 = np.maximum(w[..., 2] ** 2, 1e-300)
    a2 = ((ax * w[..., 0]) ** 2 + (ay * w[..., 1]) ** 2) / z2
    return a2 / (2.0 * (1.0 + np.sqrt(1.0 + a2)))


def smith_g1(w: Real, ax: Real, ay: Real) -> Real:
    """G1(w) = 1/(1 + Λ(w)) = 2 wz / (wz + |w|_α); 0 for directions below the horizon."""
    w = as_dirs(w)
    z = cos_theta(w)
    g = safe_div(2.0 * z, z + stretched_length(w, ax, ay))
    return np.where(upper(w), g, 0.0)


def smith_g2(wo: Real, wi: Real, ax: Real, ay: Real) -> Real:
    """Height-correlated masking-shadowing (Heitz 2014 eq. 99).

        G2 = 1/(1 + Λ(wo) + Λ(wi)) = 2 zo zi / (zi |wo|_α + zo |wi|_α)
    0 when either direction is below the horizon.
    """
    wo, wi = as_dirs(wo), as_dirs(wi)
    zo, zi = cos_theta(wo), cos_theta(wi)
    mask = both_upper(wo, wi)
    den = zi * stretched_length(wo, ax, ay) + zo * stretched_length(wi, ax, ay)
    return np.where(mask, safe_div(2.0 * zo * zi, np.where(mask, den, 1.0)), 0.0)


def smith_g2_separable(wo: Real, wi: Real, ax: Real, ay: Real) -> Real:
    """Separable (uncorrelated) masking-shadowing G2 = G1(wo) G1(wi) (Walter 2007)."""
    return smith_g1(wo, ax, ay) * smith_g1(wi, ax, ay)


def ggx_visibility(wo: Real, wi: Real, ax: Real, ay: Real) -> Real:
    """V = G2 / (4 zo zi) = 1 / (2 (zi |wo|_α + zo |wi|_α)), height-correlated.

    Finite at grazing (no 1/cos); 0 below the horizon. (Heitz 2014; Hammon 2017.)
    """
    wo, wi = as_dirs(wo), as_dirs(wi)
    zo, zi = cos_theta(wo), cos_theta(wi)
    mask = both_upper(wo, wi)
    den = 2.0 * (zi * stretched_length(wo, ax, ay) + zo * stretched_length(wi, ax, ay))
    return np.where(mask, safe_div(1.0, np.where(mask, den, 1.0)), 0.0)


def half_angle_cos(wo: Real, wi: Real, h: Real) -> Real:
    """cos θd = wo·h = wi·h, computed as (wo·h + wi·h)/2 so it is bitwise symmetric
    in wo, wi (exact reciprocity in floating point), clipped to [0, 1]."""
    return np.clip(0.5 * (dot(wo, h) + dot(wi, h)), 0.0, 1.0)


def is_mirror(ax: Real, ay: Real) -> Real:
    """True where the lobe is a perfect mirror: max(αx, αy) < ALPHA_MIRROR."""
    return np.maximum(ax, ay) < ALPHA_MIRROR


def _fresnel_values(fresnel: Real, cos_d: Real) -> Real:
    """F at the half-vector angle: ``fresnel`` is an array or a callable of cos θd."""
    return np.asarray(fresnel(cos_d) if callable(fresnel) else fresnel, dtype=np.float64)


def _times_fresnel(base: Real, f: Real) -> Real:
    """base (...) · F, where F is (...) / scalar, or RGB (..., 3)."""
    if f.ndim == base.ndim + 1 or (f.ndim >= 1 and f.shape[-1] == 3 and f.ndim > base.ndim):
        return base[..., None] * f
    return base * f


def microfacet_reflection(wo: Real, wi: Real, ax: Real, ay: Real, fresnel: Real = 1.0) -> Real:
    """Single-scattering GGX reflection BRDF (Walter 2007 eq. 20, Heitz 2014 eq. 99).

        f(wo, wi) = F(wo·h) · D(h) · G2(wo, wi) / (4 cos θo cos θi)
                  = F(wo·h) · D(h) · V(wo, wi),       h = normalize(wo + wi)
    ``fresnel`` is an array of F at the half-vector angle (broadcastable; shape (...)
    or (..., 3)) or a callable F(cos θd) with cos θd = wo·h. Returns the shape of D·F.

    Edges: 0 if either direction is below the horizon (cos θ < COS_EPS) or h is
    degenerate (wo = −wi). αx, αy are clamped up to ALPHA_MIRROR individually; if
    both are below ALPHA_MIRROR the lobe is a perfect mirror and this non-delta part
    is 0 — the delta lobe (weight ``mirror_reflectance``) is the renderer's job.
    Values are finite for all unit directions (tested down to α = 1e-3, αx/αy = 1000).
    """
    wo, wi = as_dirs(wo), as_dirs(wi)
    ax, ay = np.asarray(ax, float), np.asarray(ay, float)
    mirror = is_mirror(ax, ay)
    ax_c, ay_c = np.maximum(ax, ALPHA_MIRROR), np.maximum(ay, ALPHA_MIRROR)
    h = half_vector(wo, wi)
    dv = ggx_d(h, ax_c, ay_c) * ggx_visibility(wo, wi, ax_c, ay_c)
    dv = np.where(mirror, 0.0, dv)
    return _times_fresnel(dv, _fresnel_values(fresnel, half_angle_cos(wo, wi, h)))


def mirror_reflectance(wo: Real, fresnel: Real = 1.0) -> Real:
    """The delta (perfect mirror) lobe for α < ALPHA_MIRROR.

    Returns (wi, weight): wi = reflect(wo) = (−x, −y, z) and weight = F(cos θo) (the
    fraction of energy reflected; the BRDF is F δ(wi − reflect(wo)) / cos θi). The
    weight is 0 for wo below the horizon. ``fresnel``: array or callable of cos θo.
    """
    wo = as_dirs(wo)
    f = _fresnel_values(fresnel, np.clip(cos_theta(wo), 0.0, 1.0))
    visible = upper(wo).astype(float)
    return reflect(wo), _times_fresnel(visible, f)


def sample_ggx_vndf(wo: Real, ax: Real, ay: Real, u1: Real, u2: Real) -> Real:
    """Sample a microfacet normal from the visible-normal distribution (Heitz 2018).

    Stretch wo to the unit-α configuration, sample the projected hemisphere
    (disk warped towards the view), unstretch. Returns h (..., 3). The pdf of the
    reflected direction wi = 2(wo·h)h − wo is D_wo(h) / (4 wo·h) with
    D_wo(h) = G1(wo) max(0, wo·h) D(h) / cos θo (see ``vndf_pdf``).
    """
    wo = as_dirs(wo)
    vh = np.stack([ax * wo[..., 0], ay * wo[..., 1], wo[..., 2]], axis=-1)
    vh = vh / np.sqrt(dot(vh, vh))[..., None]
    lensq = vh[..., 0] ** 2 + vh[..., 1] ** 2
    inv = safe_div(1.0, np.sqrt(lensq))
    t1 = np.stack([-vh[..., 1] * inv, vh[..., 0] * inv, np.zeros_like(inv)], axis=-1)
    t1 = np.where((lensq > 0)[..., None], t1, np.array([1.0, 0.0, 0.0]))
    t2 = np.cross(vh, t1)
    r, phi = np.sqrt(u1), 2.0 * np.pi * u2
    p1, p2 = r * np.cos(phi), r * np.sin(phi)
    s = 0.5 * (1.0 + vh[..., 2])
    p2 = (1.0 - s) * np.sqrt(np.maximum(1.0 - p1 * p1, 0.0)) + s * p2
    p3 = np.sqrt(np.maximum(1.0 - p1 * p1 - p2 * p2, 0.0))
    nh = p1[..., None] * t1 + p2[..., None] * t2 + p3[..., None] * vh
    ne = np.stack([ax * nh[..., 0], ay * nh[..., 1], np.maximum(nh[..., 2], 0.0)], axis=-1)
    return ne / np.maximum(np.sqrt(dot(ne, ne)), 1e-300)[..., None]


def reflect_about(wo: Real, h: Real) -> Real:
    """wi = 2 (wo·h) h − wo."""
    return 2.0 * dot(wo, h)[..., None] * h - wo


def vndf_pdf(wo: Real, wi: Real, ax: Real, ay: Real) -> Real:
    """Solid-angle pdf of wi under VNDF sampling: G1(wo) D(h) / (4 cos θo)."""
    wo, wi = as_dirs(wo), as_dirs(wi)
    h = half_vector(wo, wi)
    g1d = smith_g1(wo, ax, ay) * ggx_d(h, ax, ay)
    pdf = safe_div(g1d, 4.0 * cos_theta(wo))
    return np.where(both_upper(wo, wi) & (dot(wo, h) > 0), pdf, 0.0)
