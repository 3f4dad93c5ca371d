"""Kulla–Conty energy compensation against brdf_accuracy_checks.json "kulla_conty"."""

from __future__ import annotations

import numpy as np
import pytest

from cnlmc.bsdf.evaluate import albedo
from cnlmc.bsdf.fresnel import fresnel_average, fresnel_conductor
from cnlmc.bsdf.integrate import albedo_at_mu
from cnlmc.bsdf.microfacet import microfacet_reflection
from cnlmc.bsdf.multiscatter import (
    TABLE_SIZE,
    albedo_lookup,
    albedo_table,
    average_albedo,
    fresnel_multiscatter,
    multiscatter_lobe,
)

# Tolerances: table E(μ, α) is a 32² QMC table (2048 samples/entry, ~5e-4) with
# bilinear interpolation (~3e-4 at these α); the listed values are rounded to 1e-4.
TOL = 2e-3


def _metal(metals, key):
    return next(m for m in metals if m["key"] == key)["primary"]


def test_table_is_small_cached_and_bounded():
    table = albedo_table()
    assert table.shape == (TABLE_SIZE, TABLE_SIZE) and albedo_table() is table
    assert np.all((table > 0) & (table <= 1.0 + 1e-9))
    assert albedo_lookup(1.0, 1.0) == pytest.approx(1 - np.log(2), abs=1e-3)


def test_white_furnace_after_compensation(accuracy_checks):
    for a_key, ref in accuracy_checks["kulla_conty"].items():
        alpha = float(a_key)
        assert average_albedo(alpha) == pytest.approx(ref["E_avg"], abs=TOL)
        for mu in [1.0, 0.7, 0.4, 0.1]:
            both = lambda o, i: microfacet_reflection(o, i, alpha, alpha) + multiscatter_lobe(o, i, alpha)
            total = albedo_at_mu(both, mu, alpha, alpha, n=1 << 12)
            assert total == pytest.approx(1.0, abs=3e-3), (alpha, mu)


def test_coloured_metals_reproduce_data(accuracy_checks, metals):
    for a_key, ref in accuracy_checks["kulla_conty"].items():
        alpha = float(a_key)
        for key in ("Au", "Cu", "Al", "Fe"):
            p = _metal(metals, key)
            eta, k = np.array(p["eta_rgb_fit"]), np.array(p["k_rgb_fit"])
            fres = lambda c: fresnel_conductor(np.asarray(c)[..., None], eta, k)
            f_avg = fresnel_average(fres)
            single = albedo_at_mu(
                lambda o, i: microfacet_reflection(o, i, alpha, alpha, fres), 1.0, alpha, alpha, n=1 << 12
            )
            added = albedo_at_mu(lambda o, i: multiscatter_lobe(o, i, alpha, f_avg), 1.0, n=1 << 12)
            for c, ch in enumerate("rgb"):
                want = ref[key][ch]
                assert f_avg[c] == pytest.approx(want["F_avg"], abs=2e-4)
                assert single[c] == pytest.approx(want["single_scatter_albedo_mu1"], abs=TOL)
                assert added[c] == pytest.approx(want["kulla_conty_added_mu1"], abs=TOL)
                assert single[c] + added[c] == pytest.approx(want["total_mu1"], abs=2 * TOL)


def test_fresnel_multiscatter_limits():
    assert fresnel_multiscatter(1.0, 0.4) == pytest.approx(1.0)
    assert fresnel_multiscatter(0.0, 0.4) == 0.0
    f = fresnel_multiscatter(np.linspace(0, 1, 11), 0.7)
    assert np.all(np.diff(f) > 0) and np.all(f <= 1.0)


def test_evaluate_multiscatter_flag_adds_energy_but_stays_bounded():
    mat = {
        "model": {"base": "conductor", "distribution": "ggx", "anisotropic": False, "coat": False, "diffuse": None},
        "params": {"base_color": [1, 1, 1], "roughness": 0.8, "eta": [1.0, 1.0, 1.0], "k": [1e6, 1e6, 1e6]},
    }
    for mu in [1.0, 0.3]:
        single = albedo(mat, mu, 1 << 12)
        multi = albedo(mat, mu, 1 << 12, multiscatter=True)
        assert np.all(multi > single + 0.05)
        np.testing.assert_allclose(multi, 1.0, atol=4e-3)
