"""Fresnel: exact dielectric/conductor edges, Schlick and F82 against the data."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from cnlmc.bsdf.fresnel import (
    MU_BAR,
    f0_conductor,
    f0_from_ior,
    f82_from_tint,
    fresnel_average,
    fresnel_conductor,
    fresnel_dielectric,
    fresnel_f82,
    fresnel_f82_tint,
    fresnel_schlick,
    fresnel_schlick_average,
    ior_from_f0,
)

MU = np.concatenate([np.linspace(0.0, 1.0, 1001), [1e-300, 1e-12, 1e-7]])


def test_dielectric_eta_one_is_exactly_zero():
    assert np.all(fresnel_dielectric(MU, 1.0) == 0.0)
    assert np.all(fresnel_conductor(MU, 1.0, 0.0) == 0.0)


@pytest.mark.parametrize("eta", [1.0001, 1.333, 1.5, 2.42, 4.0])
def test_dielectric_normal_incidence_and_grazing(eta):
    assert fresnel_dielectric(1.0, eta) == pytest.approx(f0_from_ior(eta), rel=1e-12)
    assert fresnel_dielectric(0.0, eta) == 1.0
    f = fresnel_dielectric(MU, eta)
    assert np.all(np.isfinite(f)) and np.all((f >= 0) & (f <= 1))


def test_dielectric_total_internal_reflection():
    eta = 1 / 1.5
    critical = np.sqrt(1 - eta**2)  # cos of the critical angle
    mu = np.linspace(0, 1, 2001)
    f = fresnel_dielectric(mu, eta)
    assert np.all(f[mu < critical - 1e-9] == 1.0)
    assert np.all(f[mu > critical + 1e-3] < 1.0)
    # η and 1/η give the same reflectance for corresponding angles (Stokes relations).
    mu_t = np.sqrt(1 - (1 - mu**2) / 1.5**2)
    np.testing.assert_allclose(fresnel_dielectric(mu, 1.5), fresnel_dielectric(mu_t, eta), atol=1e-12)


@given(eta=st.floats(0.2, 5.0), mu=st.floats(0.0, 1.0))
@settings(max_examples=300, deadline=None)
def test_conductor_with_k0_equals_dielectric(eta, mu):
    assert fresnel_conductor(mu, eta, 0.0) == pytest.approx(fresnel_dielectric(mu, eta), abs=1e-12)


@given(eta=st.floats(0.01, 6.0), k=st.floats(0.0, 25.0), mu=st.floats(0.0, 1.0))
@settings(max_examples=300, deadline=None)
def test_conductor_bounded_and_finite(eta, k, mu):
    f = fresnel_conductor(mu, eta, k)
    assert np.isfinite(f) and 0.0 <= f <= 1.0


def test_conductor_normal_incidence_and_grazing():
    eta, k = np.array([0.2, 1.1, 3.0]), np.array([3.5, 6.8, 2.9])
    np.testing.assert_allclose(fresnel_conductor(1.0, eta, k), f0_conductor(eta, k), rtol=1e-12)
    np.testing.assert_allclose(fresnel_conductor(0.0, eta, k), 1.0, atol=1e-15)
    np.testing.assert_allclose(fresnel_conductor(1e-9, eta, k), 1.0, atol=1e-7)


def test_schlick_and_f82_basics():
    f0 = np.array([0.9, 0.5, 0.04])
    np.testing.assert_allclose(fresnel_schlick(1.0, f0), f0)
    np.testing.assert_allclose(fresnel_schlick(0.0, f0), 1.0)
    f82 = np.array([0.8, 0.45, 0.1])
    np.testing.assert_allclose(fresnel_f82(MU_BAR, f0, f82), f82, atol=1e-12)
    np.testing.assert_allclose(fresnel_f82(1.0, f0, f82), f0, atol=1e-12)
    np.testing.assert_allclose(fresnel_f82(0.0, f0, f82), 1.0, atol=1e-12)
    mu = np.linspace(0, 1, 101)[:, None]
    np.testing.assert_allclose(fresnel_f82_tint(mu, f0, 1.0), fresnel_schlick(mu, f0), atol=1e-12)
    np.testing.assert_allclose(f82_from_tint(f0, 1.0), fresnel_schlick(MU_BAR, f0))


def test_ior_f0_round_trip_and_averages():
    ior = np.array([1.0, 1.33, 1.5, 2.4])
    np.testing.assert_allclose(ior_from_f0(f0_from_ior(ior)), ior, rtol=1e-9)
    f0 = np.array([0.04, 0.5, 0.95])
    np.testing.assert_allclose(
        fresnel_average(lambda m: fresnel_schlick(m[:, None], f0)), fresnel_schlick_average(f0), atol=1e-12
    )


def test_schlick_dielectric_errors_match_reference(accuracy_checks):
    """Reproduce schlick_dielectric_error: F0, max |Schlick − exact| and its angle,
    and the hemispherical averages. Tolerance: the JSON rounds to 4 decimals (±5e-5,
    we allow 1e-4) and samples θ at 0.05° (angle within 0.1°)."""
    theta = np.radians(np.arange(0.0, 90.0 + 1e-9, 0.01))
    mu = np.cos(theta)
    for ior_s, ref in accuracy_checks["schlick_dielectric_error"].items():
        ior = float(ior_s)
        f0 = f0_from_ior(ior)
        err = fresnel_schlick(mu, f0) - fresnel_dielectric(mu, ior)
        i = np.argmax(np.abs(err))
        assert f0 == pytest.approx(ref["F0"], abs=1e-4)
        assert abs(err[i]) == pytest.approx(ref["schlick_max_abs_err"], abs=1e-4)
        assert err[i] == pytest.approx(ref["signed"], abs=1e-4)
        assert np.degrees(theta[i]) == pytest.approx(ref["at_theta"], abs=0.1)
        avg_exact = fresnel_average(lambda m: fresnel_dielectric(m, ior), n=128)
        assert avg_exact == pytest.approx(ref["hemispherical_F_exact"], abs=1e-4)
        assert fresnel_schlick_average(f0) == pytest.approx(ref["hemispherical_F_schlick"], abs=1e-4)
