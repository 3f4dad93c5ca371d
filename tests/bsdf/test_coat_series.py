"""The diffuse base under a coat (compiler/bsdf/layered.py): the classical inter-reflection
ρ / (η² (1 − ρ K)) with the Fresnel transmittances outside (Lekner & Dorf 1988)."""

from __future__ import annotations

import numpy as np
import pytest

from cnlmc.bsdf import albedo, evaluate
from cnlmc.bsdf.diffuse import lambert, oren_nayar
from cnlmc.bsdf.fresnel import fresnel_dielectric
from cnlmc.bsdf.geometry import dir_from_mu
from cnlmc.bsdf.integrate import albedo_mis
from cnlmc.bsdf.layered import (
    coat_specular,
    coated,
    diffuse_reflectance,
    fresnel_diffuse_reflectance,
    internal_reflectance,
)

MUS = np.array([0.02, 0.1, 0.3, 0.5, 0.7, 0.9, 1.0])
SAMPLES = 1 << 14


def lambert_base(rho):
    rho = np.broadcast_to(np.asarray(rho, float), (3,))

    def parts(o, i):
        diff = lambert(o, i, rho)
        return np.zeros_like(diff), diff

    return parts


def under_albedo(base, eta, rho=None, mus=MUS, color=(1.0, 1.0, 1.0), thickness=0.0, alpha=1e-3):
    """The albedo of the coated BRDF without the coat's own lobe (what comes up from the base)."""

    def f(o, i):
        return (
            coated(o, i, base, eta, (alpha, alpha), color, thickness, rho)
            - coat_specular(o, i, eta, alpha, alpha)[..., None]
        )

    return albedo_mis(f, dir_from_mu(mus), [], SAMPLES)


@pytest.mark.parametrize("eta", [1.0, 1.2, 1.5, 2.0, 3.0, 10.0])
def test_internal_reflectance_is_the_diffuse_identity(eta):
    """Without absorption K = 1 − (1 − F_dr_ext)/η² (quadrature over the two intervals)."""
    assert internal_reflectance(eta) == pytest.approx(1.0 - (1.0 - fresnel_diffuse_reflectance(eta)) / eta**2, abs=1e-9)


def test_fresnel_diffuse_reflectance_known_value():
    """F_dr for η 1.5 from outside: 0.0918 (the hemispherical Fresnel average)."""
    assert fresnel_diffuse_reflectance(1.5) == pytest.approx(0.0918, abs=2e-4)


def test_internal_reflectance_with_absorption():
    """A black coat returns nothing; a grey one less than a clear one; thickness 0 absorbs nothing."""
    assert np.all(internal_reflectance(1.5, (0.0, 0.0, 0.0), 1.0) < 1e-12)
    clear, grey = internal_reflectance(1.5), internal_reflectance(1.5, (0.5, 0.5, 0.5), 1.0)
    assert np.all(grey < clear) and np.all(grey > 0.0)
    assert np.all(internal_reflectance(1.5, (0.5, 0.5, 0.5), 0.0) == pytest.approx(clear))


@pytest.mark.parametrize("eta", [1.2, 1.5, 2.0, 3.0])
def test_white_limit_is_one_minus_fresnel(eta):
    """A white Lambert base: ∫ (the light through the coat) = 1 − F(cos θo), to 1e-3."""
    got = under_albedo(lambert_base(1.0), eta)[:, 0]
    assert got == pytest.approx(1.0 - fresnel_dielectric(MUS, eta), abs=1e-3)


def test_white_limit_with_the_reflectance_integrated():
    """The same with ρ integrated from the base (no ρ given)."""
    got = under_albedo(lambert_base(1.0), 1.5, rho=None)[:, 0]
    assert got == pytest.approx(1.0 - fresnel_dielectric(MUS, 1.5), abs=1e-3)


@pytest.mark.parametrize("eta", [1.5, 2.0])
def test_dark_base_slope_is_the_single_pass(eta):
    """ρ → 0: A / ρ tends to the single pass (1 − F(μo)) (1 − F_dr_ext) / η²."""
    rho = 1e-4
    got = under_albedo(lambert_base(rho), eta)[:, 0] / rho
    single = (1.0 - fresnel_dielectric(MUS, eta)) * (1.0 - fresnel_diffuse_reflectance(eta)) / eta**2
    assert got == pytest.approx(single, rel=2e-3)


def test_series_is_the_closed_form():
    """At any ρ: (1 − F(μo)) (1 − F_dr_ext) ρ / (η² (1 − ρ K))."""
    eta, rho = 1.5, np.array([0.2, 0.5, 0.9])
    got = under_albedo(lambert_base(rho), eta)
    k = internal_reflectance(eta)
    want = (
        (1.0 - fresnel_dielectric(MUS, eta))[:, None]
        * (1.0 - fresnel_diffuse_reflectance(eta))
        * rho
        / (eta**2 * (1.0 - rho * k))
    )
    assert got == pytest.approx(want, rel=2e-3)


@pytest.mark.parametrize("rho", [0.0, 0.3, 1.0])
def test_no_coat_is_the_base(rho):
    """η = 1: the coat is no interface, so the coated BRDF is the base's exactly."""
    o, i = dir_from_mu(MUS), dir_from_mu(MUS[::-1], 2.0)
    base = lambert_base(rho)
    assert coated(o, i, base, 1.0, (1e-3, 1e-3)) == pytest.approx(base(o, i)[1], abs=1e-12)


def test_reflectance_of_lambert_and_oren_nayar():
    """ρ of Lambert is its colour; Oren–Nayar's (which loses light) the mean of its albedo curve."""
    assert diffuse_reflectance(lambda o, i: lambert(o, i, np.ones(3))) == pytest.approx(np.ones(3), abs=1e-12)
    on = lambda o, i: oren_nayar(o, i, np.ones(3), 0.7)
    x, w = np.polynomial.legendre.leggauss(16)
    mu = 0.5 * (x + 1.0)
    mean = 0.5 * (w * mu) @ albedo_mis(on, dir_from_mu(mu), [], SAMPLES) * 2.0
    assert diffuse_reflectance(on) == pytest.approx(mean, abs=2e-3)


@pytest.mark.parametrize("eta", [1.0, 1.5, 3.0])
@pytest.mark.parametrize("coat_alpha", [1e-3, 1.0])
@pytest.mark.parametrize("sigma", [0.0, 1.0])
def test_white_furnace_at_most_one(eta, coat_alpha, sigma):
    """Coat lobe + base through it ≤ 1 at every angle: smooth and rough coat, Lambert and a rough
    Oren–Nayar base, no coat (η 1) to the IR's largest coat index (3)."""

    def parts(o, i):
        diff = oren_nayar(o, i, np.ones(3), sigma)
        return np.zeros_like(diff), diff

    mus = np.linspace(0.02, 1.0, 12)
    f = lambda o, i: coated(o, i, parts, eta, (coat_alpha, coat_alpha))
    a = albedo_mis(f, dir_from_mu(mus), [(np.asarray(coat_alpha), np.asarray(coat_alpha))], SAMPLES)
    assert np.all(a <= 1.0 + 2e-3)


@pytest.mark.parametrize("eta", [10.0, 100.0])
def test_white_furnace_huge_index_smooth_coat(eta):
    """A huge index: the smooth coat reflects F, the base sends back 1 − F: the sum stays ≤ 1."""
    mus = np.linspace(0.02, 1.0, 12)
    f = lambda o, i: coated(o, i, lambert_base(1.0), eta, (1e-3, 1e-3))
    a = albedo_mis(f, dir_from_mu(mus), [(np.asarray(1e-3), np.asarray(1e-3))], SAMPLES)
    assert np.all(a <= 1.0 + 2e-3)
    assert np.all(a >= 1.0 - 5e-3)  # and nothing is lost: what the coat does not reflect comes back


def material(base_color, coat_ior=1.5, base="dielectric"):
    return {
        "model": {"base": base, "distribution": "ggx", "anisotropic": False, "coat": True, "diffuse": "lambert"},
        "params": {
            "base_color": list(base_color),
            "roughness": 0.5,
            "ior": coat_ior,
            "alpha_convention": "squared",
            "coat": {"ior": coat_ior, "roughness": 0.0, "color": [1.0, 1.0, 1.0], "thickness": 0.0},
        },
    }


def test_evaluate_white_coated_plastic_keeps_the_light():
    """A white plastic under a coat of its own index: the whole albedo is ~1 (it was 1 − F_avg)."""
    a = albedo(material((1.0, 1.0, 1.0)), np.array([0.3, 0.7, 1.0]), 8192)
    assert np.all(a <= 1.0 + 2e-3) and np.all(a > 0.98)


def test_evaluate_dark_base_keeps_the_single_pass():
    """A dark base under the coat: about the single pass ρ (1 − F)(1 − F_avg)/η², not η² times it."""
    rho = 0.02
    a = albedo(material((rho, rho, rho)), np.array([1.0]), 8192)[0, 0]
    black = albedo(material((0.0, 0.0, 0.0)), np.array([1.0]), 8192)[0, 0]
    single = (1.0 - fresnel_dielectric(1.0, 1.5)) * (1.0 - fresnel_diffuse_reflectance(1.5)) * rho / 1.5**2
    assert a - black == pytest.approx(single / (1.0 - rho * internal_reflectance(1.5)[0]), rel=2e-2)


def test_evaluate_per_lane_alpha():
    """A renderer's per-lane α (a roughness map) still evaluates under a coat."""
    from cnlmc.bsdf.inputs import as_material

    m = as_material(material((0.5, 0.5, 0.5)))
    import dataclasses

    lanes = np.array([0.1, 0.3, 0.5])
    m = dataclasses.replace(m, params=dataclasses.replace(m.params, alpha=(lanes, lanes)))
    o, i = dir_from_mu(np.array([0.5, 0.6, 0.7])), dir_from_mu(np.array([0.8, 0.4, 0.9]), 1.0)
    assert np.all(np.isfinite(evaluate(m, o, i)))
