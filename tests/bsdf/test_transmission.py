"""Rough dielectric transmission (Walter 2007 BTDF) and the two-sided glass BSDF.

Checks: finite and non-negative everywhere (η = 1, TIR, grazing, in-plane, tiny α);
generalized reciprocity f_t(wo, wi)/η_o² = f_t(wi, wo)/η_i²; white-furnace energy against
an independent brute-force Monte Carlo of the microfacet model and the smooth-interface
limit R + T = 1; agreement with Mitsuba 3's roughdielectric."""

from __future__ import annotations

import copy

import numpy as np
import pytest

from cnlmc.bsdf import (
    ALPHA_MIRROR,
    dielectric_reflection,
    evaluate,
    evaluate_bsdf,
    evaluate_transmission,
    fresnel_dielectric,
    microfacet_transmission,
    mirror_transmittance,
    sample_ggx_vndf,
    smith_lambda,
    transmission_g2,
)
from cnlmc.bsdf.integrate import lattice_2d
from cnlmc.bsdf.transmission import G2_FORMS, refract

from .directions import sphere_dirs

GLASS = {
    "name": "glass",
    "model": {"base": "glass", "distribution": "ggx", "anisotropic": False, "diffuse": None, "coat": False},
    "params": {"ior": 1.5, "roughness": 0.3, "base_color": [0.9, 0.95, 1.0], "alpha_convention": "squared"},
}


def glass(**params):
    m = copy.deepcopy(GLASS)
    m["params"].update(params)
    return m


def unit(v):
    return v / np.linalg.norm(v, axis=-1, keepdims=True)


def full_sphere_pairs():
    """Every pair of the stability grid, with the grid mirrored to the lower side too."""
    d = sphere_dirs()
    d = np.concatenate([d, d * np.array([1.0, 1.0, -1.0])])
    wo, wi = np.repeat(d, len(d), axis=0), np.tile(d, (len(d), 1))
    return np.concatenate([wo, d, d]), np.concatenate([wi, d, -d])


# ------------------------------------------------------------------ stability


@pytest.mark.parametrize("alpha", [1e-4, ALPHA_MIRROR, 0.05, 0.5, 1.0, (1.0, 1e-3)])
@pytest.mark.parametrize("ior", [1.0, 1.0001, 1.5, 2.4, 0.7])
def test_finite_nonnegative_dense_grid(alpha, ior):
    ax, ay = (alpha, alpha) if np.isscalar(alpha) else alpha
    wo, wi = full_sphere_pairs()
    for g2 in G2_FORMS:
        for mode in ("radiance", "importance"):
            f = microfacet_transmission(wo, wi, ax, ay, ior, g2, mode)
            assert np.all(np.isfinite(f)) and np.all(f >= 0.0)
    r = dielectric_reflection(wo, wi, ax, ay, ior)
    assert np.all(np.isfinite(r)) and np.all(r >= 0.0)
    m = glass(ior=ior, alpha=[ax, ay])
    full = evaluate_bsdf(m, wo, wi)
    assert np.all(np.isfinite(full)) and np.all(full >= 0.0)


def test_zero_cases():
    wo, wi = full_sphere_pairs()
    f = microfacet_transmission(wo, wi, 0.3, 0.3, 1.5)
    same = wo[:, 2] * wi[:, 2] >= 0.0
    planar = (np.abs(wo[:, 2]) < 1e-7) | (np.abs(wi[:, 2]) < 1e-7)
    assert np.all(f[same | planar] == 0.0)
    assert np.any(f > 0.0)
    # η = 1: the interface is invisible; transmission is the delta wi = −wo, non-delta part 0.
    assert np.all(microfacet_transmission(wo, wi, 0.3, 0.3, 1.0) == 0.0)
    # α below the mirror threshold: the smooth interface, non-delta part 0.
    assert np.all(microfacet_transmission(wo, wi, 1e-4, 1e-4, 1.5) == 0.0)
    # opaque models have no transmission
    plastic = glass()
    plastic["model"]["base"] = "dielectric"
    assert np.all(evaluate_transmission(plastic, wo, wi) == 0.0)


@pytest.mark.parametrize("ior", [1.5, 1.33, 2.4])
def test_tir_region_is_exactly_zero(ior):
    """No microfacet bends a ray by more than 90° − θc: pairs beyond are exactly 0."""
    rng = np.random.default_rng(3)
    wo, wi = unit(rng.normal(size=(20000, 3))), unit(rng.normal(size=(20000, 3)))
    wi[:, 2] = -np.sign(wo[:, 2]) * np.abs(wi[:, 2])
    deviation = np.degrees(np.arccos(np.clip(np.sum(-wo * wi, -1), -1, 1)))
    max_dev = 90.0 - np.degrees(np.arcsin(1.0 / ior))
    f = microfacet_transmission(wo, wi, 1.0, 1.0, ior)
    assert np.all(f[deviation > max_dev + 1e-6] == 0.0)
    assert np.mean(f[deviation < max_dev - 1.0] > 0.0) > 0.5  # (h must also face up: not all)
    # smooth interface: inside beyond the critical angle, the transmitted weight is exactly 0
    mu = np.linspace(0.0, 1.0, 101)
    w_in = np.stack([np.sqrt(1 - mu * mu), 0 * mu, -mu], -1)
    t, weight = mirror_transmittance(w_in, ior)
    beyond = mu < np.sqrt(1.0 - 1.0 / ior**2)
    assert np.all(weight[beyond] == 0.0) and np.all(t[beyond] == 0.0)
    assert np.all(weight[~beyond & (mu > 1e-6)] > 0.0)


def test_mirror_transmittance_weights():
    """Smooth interface: weight (1 − F) (η_o/η_i)² for radiance, 1 − F for importance."""
    mu = np.linspace(0.05, 1.0, 20)
    wo = np.stack([np.sqrt(1 - mu * mu), 0 * mu, mu], -1)
    t, w_rad = mirror_transmittance(wo, 1.5)
    _, w_imp = mirror_transmittance(wo, 1.5, "importance")
    np.testing.assert_allclose(w_imp, 1.0 - fresnel_dielectric(mu, 1.5), rtol=1e-12)
    np.testing.assert_allclose(w_rad, w_imp / 1.5**2, rtol=1e-12)
    np.testing.assert_allclose(np.linalg.norm(t, axis=-1), 1.0, rtol=1e-12)
    np.testing.assert_allclose(np.sqrt(1 - t[:, 2] ** 2) * 1.5, np.sqrt(1 - mu * mu), rtol=1e-12)  # Snell
    t1, w1 = mirror_transmittance(wo, 1.0)
    np.testing.assert_allclose(t1, -wo) and np.testing.assert_allclose(w1, 1.0)


# ------------------------------------------------------------------ reciprocity


@pytest.mark.parametrize("g2", G2_FORMS)
@pytest.mark.parametrize("ior", [1.5, 2.4, 0.8])
def test_generalized_reciprocity(g2, ior):
    rng = np.random.default_rng(5)
    wo, wi = unit(rng.normal(size=(5000, 3))), unit(rng.normal(size=(5000, 3)))
    wi[:, 2] = -np.sign(wo[:, 2]) * np.abs(wi[:, 2])
    eta = lambda w: np.where(w[:, 2] > 0, 1.0, ior)
    a = microfacet_transmission(wo, wi, 0.2, 0.4, ior, g2) / eta(wo) ** 2
    b = microfacet_transmission(wi, wo, 0.2, 0.4, ior, g2) / eta(wi) ** 2
    assert np.count_nonzero(a) > 300
    np.testing.assert_allclose(a, b, rtol=1e-9, atol=0)
    # importance = radiance of the swapped pair
    imp = microfacet_transmission(wo, wi, 0.2, 0.4, ior, g2, "importance")
    np.testing.assert_allclose(imp, microfacet_transmission(wi, wo, 0.2, 0.4, ior, g2), rtol=1e-9)


def test_g2_forms_ordering():
    """beta ≤ separable ≤ correlated ≤ min(G1), all equal to G1 when one Λ is 0."""
    rng = np.random.default_rng(2)
    wo, wi = unit(rng.normal(size=(2000, 3))), unit(rng.normal(size=(2000, 3)))
    g = {form: transmission_g2(wo, wi, 0.5, 0.5, form) for form in G2_FORMS}
    assert np.all(g["beta"] <= g["separable"] + 1e-12)
    assert np.all(g["separable"] <= g["correlated"] + 1e-12)
    g1 = 1.0 / (1.0 + smith_lambda(np.abs(wo), 0.5, 0.5))
    assert np.all(g["correlated"] <= g1 + 1e-12)
    up = np.tile([0.0, 0.0, -1.0], (2000, 1))
    for form in G2_FORMS:
        np.testing.assert_allclose(transmission_g2(wo, up, 0.5, 0.5, form), g1, rtol=1e-9)


# ------------------------------------------------------------------ energy


def brute_force_split(mu, alpha, ior, inside=False, n=1 << 16):
    """(R, T) energy fractions from wo straight from the microfacet model: visible normals
    m ~ D_wo (Heitz 2018), then reflect with weight F·G2/G1(wo) or refract with
    (1 − F)·G2/G1(wo) (height-correlated G2 = 1/(1 + Λo + Λi)). No BSDF formula involved."""
    eta = 1.0 / ior if inside else ior  # relative index seen from wo's side
    u1, u2 = lattice_2d(n)
    wo = np.tile([np.sqrt(1 - mu * mu), 0.0, mu], (n, 1))
    m = sample_ggx_vndf(wo, alpha, alpha, u1, u2)
    c = np.sum(wo * m, -1)
    f = fresnel_dielectric(c, eta)
    lo = smith_lambda(wo, alpha, alpha)
    r = 2 * c[:, None] * m - wo
    lr = smith_lambda(r, alpha, alpha)
    ct2 = 1.0 - (1.0 - c * c) / eta**2
    ct = np.sqrt(np.maximum(ct2, 0.0))
    t = -wo / eta + (c / eta - ct)[:, None] * m
    lt = smith_lambda(t * np.array([1, 1, -1.0]), alpha, alpha)
    R = np.where(r[:, 2] > 0, f * (1 + lo) / (1 + lo + lr), 0.0).mean()
    T = np.where((t[:, 2] < 0) & (ct2 > 0), (1 - f) * (1 + lo) / (1 + lo + lt), 0.0).mean()
    return R, T


def cap_samples(axis, half_angle, n):
    """Uniform directions in a spherical cap around ``axis`` and their pdf."""
    u1, u2 = lattice_2d(n)
    z = 1.0 - u1 * (1.0 - np.cos(half_angle))
    s = np.sqrt(np.maximum(1 - z * z, 0))
    local = np.stack([s * np.cos(2 * np.pi * u2), s * np.sin(2 * np.pi * u2), z], -1)
    a = unit(np.cross(axis, [0.0, 1.0, 0.0] if abs(axis[1]) < 0.9 else [1.0, 0.0, 0.0]))
    b = np.cross(axis, a)
    return local @ np.stack([a, b, axis]), 1.0 / (2 * np.pi * (1 - np.cos(half_angle)))


def transmitted_energy(mu, alpha, ior, inside=False, n=1 << 15):
    """T = ∫ f_t(importance) |cos θi| dωi over the far side, integrated in direction space by
    MIS of cosine sampling and caps around the smooth refraction direction (no microfacet
    sampling, so the BTDF's Jacobian is checked independently)."""
    sign = -1.0 if inside else 1.0
    wo = np.array([np.sqrt(1 - mu * mu), 0.0, sign * mu])
    t0, ok = refract(wo, ior)
    axis = t0 if ok else unit(np.array([-wo[0], 0.0, -sign * 0.05]))
    u1, u2 = lattice_2d(n)
    r = np.sqrt(u1)
    cosine = np.stack(
        [r * np.cos(2 * np.pi * u2), r * np.sin(2 * np.pi * u2), -sign * np.sqrt(np.maximum(1 - u1, 0))], -1
    )
    strategies = [(cosine, None)] + [cap_samples(axis, min(k * alpha, 1.5), n) for k in (4.0, 20.0)]

    def pdf_all(w):
        p = np.abs(w[:, 2]) / np.pi * (w[:, 2] * sign < 0)
        for k in (4.0, 20.0):
            h = min(k * alpha, 1.5)
            p = p + (np.sum(w * axis, -1) >= np.cos(h)) / (2 * np.pi * (1 - np.cos(h)))
        return p

    total = 0.0
    for w, _ in strategies:
        keep = w[:, 2] * sign < 0
        f = microfacet_transmission(np.broadcast_to(wo, w.shape), w, alpha, alpha, ior, mode="importance")
        total += np.sum(np.where(keep, f * np.abs(w[:, 2]) / np.maximum(pdf_all(w), 1e-300), 0.0)) / n
    return total


@pytest.mark.parametrize("inside", [False, True])
@pytest.mark.parametrize("alpha,mu", [(0.05, 0.9), (0.05, 0.4), (0.3, 0.8), (0.3, 0.3), (0.6, 0.6)])
def test_transmitted_energy_matches_brute_force(alpha, mu, inside):
    _, T_mc = brute_force_split(mu, alpha, 1.5, inside)
    T = transmitted_energy(mu, alpha, 1.5, inside)
    assert abs(T - T_mc) < 3e-3, (T, T_mc)


@pytest.mark.parametrize("mu", [1.0, 0.8, 0.5, 0.2])
@pytest.mark.parametrize("alpha", [0.05, 0.3, 1.0])
def test_furnace_outside_at_most_one(mu, alpha):
    """From outside: R (the library's reflection albedo) + T (BTDF, importance) ≤ 1 and equal
    to the brute-force microfacet numbers."""
    m = glass(alpha=[alpha, alpha], base_color=[1.0, 1.0, 1.0])
    from cnlmc.bsdf import albedo

    R = albedo(m, mu)[0]
    T = transmitted_energy(mu, alpha, 1.5)
    R_mc, T_mc = brute_force_split(mu, alpha, 1.5)
    assert abs(R - R_mc) < 3e-3 and abs(T - T_mc) < 4e-3
    assert R + T <= 1.0 + 4e-3
    if alpha <= 0.05:
        assert R + T > 0.98


@pytest.mark.parametrize("mu,inside", [(0.8, False), (0.3, False), (0.95, True), (0.8, True), (0.5, True)])
def test_smooth_limit(mu, inside):
    """α → 0: R → F(μ), T → 1 − F(μ) (inside beyond the critical angle: R = 1, T = 0)."""
    eta = 1 / 1.5 if inside else 1.5
    F = fresnel_dielectric(mu, eta)
    R_mc, T_mc = brute_force_split(mu, 0.005, 1.5, inside)
    T = transmitted_energy(mu, 0.005, 1.5, inside)
    assert abs(R_mc - F) < 2e-3 and abs(T_mc - (1 - F)) < 2e-3 and abs(T - (1 - F)) < 3e-3


# ------------------------------------------------------------------ the full BSDF


def test_evaluate_bsdf_dispatch():
    m = glass()
    rng = np.random.default_rng(9)
    wo, wi = unit(rng.normal(size=(3000, 3))), unit(rng.normal(size=(3000, 3)))
    full = evaluate_bsdf(m, wo, wi)
    up = (wo[:, 2] > 0) & (wi[:, 2] > 0)
    opp = wo[:, 2] * wi[:, 2] < 0
    down = (wo[:, 2] < 0) & (wi[:, 2] < 0)
    np.testing.assert_allclose(full[up], evaluate(m, wo[up], wi[up]), rtol=1e-12)
    np.testing.assert_allclose(full[opp], evaluate_transmission(m, wo[opp], wi[opp]), rtol=1e-12)
    ax = float(np.asarray(m["params"]["roughness"]) ** 2)
    inner = dielectric_reflection(wo[down], wi[down], ax, ax, 1.5)
    np.testing.assert_allclose(full[down], inner[:, None] * np.ones(3), rtol=1e-9)
    # the interface is colourless: the glass's colour is absorbed inside (transmission.absorption)
    t = evaluate_transmission(m, wo[opp], wi[opp])
    assert np.all(t[:, 0] == t[:, 2]) and np.all(t[:, 1] == t[:, 2]) and t.max() > 0


# ------------------------------------------------------------------ Mitsuba 3


def _mitsuba():
    mi = pytest.importorskip("mitsuba")
    try:
        mi.set_variant("scalar_rgb")
    except Exception as exc:
        pytest.skip(f"mitsuba scalar_rgb variant unavailable: {exc}")
    return mi


def mitsuba_pairs(rng, n, ior, alpha):
    """Random pairs plus pairs near the smooth refraction direction (the peak)."""
    wo = unit(rng.normal(size=(n, 3)))
    wi = unit(rng.normal(size=(n, 3)))
    t, ok = refract(wo, ior)
    near = unit(t + rng.normal(size=(n, 3)) * 2 * alpha)
    wi = np.where((ok & (np.arange(n) % 2 == 0))[:, None], near, wi)
    return wo, wi


@pytest.mark.parametrize("alpha,ior", [(0.3, 1.5), (0.05, 1.33), (0.7, 2.4), (0.15, 1.5)])
@pytest.mark.parametrize("mode", ["radiance", "importance"])
def test_agrees_with_mitsuba_roughdielectric(alpha, ior, mode):
    """Mitsuba's eval(ctx, si, wo) with si.wi = our wo (towards the viewer / previous vertex)
    and its wo = our wi returns f · |cos θi| in its transport mode; Mitsuba 3's GGX uses the
    separable Smith G2 = G1 G1, so we compare g2="separable". Reflection and transmission."""
    mi = _mitsuba()
    bsdf = mi.load_dict(
        {"type": "roughdielectric", "distribution": "ggx", "alpha": alpha, "int_ior": ior, "ext_ior": 1.0}
    )
    ctx = mi.BSDFContext(mi.TransportMode.Radiance if mode == "radiance" else mi.TransportMode.Importance)
    rng = np.random.default_rng(11)
    wo, wi = mitsuba_pairs(rng, 600, ior, alpha)
    ours = (
        microfacet_transmission(wo, wi, alpha, alpha, ior, "separable", mode)
        + dielectric_reflection(wo, wi, alpha, alpha, ior, "separable")
    ) * np.abs(wi[:, 2])
    theirs = np.empty(len(wo))
    si = mi.SurfaceInteraction3f()
    si.n = mi.Normal3f(0, 0, 1)
    si.sh_frame = mi.Frame3f(si.n)
    for k in range(len(wo)):
        si.wi = mi.Vector3f(*wo[k])
        theirs[k] = bsdf.eval(ctx, si, mi.Vector3f(*wi[k]))[0]
    trans = wo[:, 2] * wi[:, 2] < 0
    assert np.count_nonzero(trans & (theirs > 1e-3)) > 100
    big = theirs > 1e-3
    rel = np.abs(ours - theirs)[big] / theirs[big]
    assert np.max(rel) < 5e-3, np.max(rel)  # Mitsuba evaluates in float32
    assert np.median(rel) < 1e-5
    assert np.all(np.abs(ours - theirs)[~big] < 2e-3)
