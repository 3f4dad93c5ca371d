"""The Löw 2012 Cook–Torrance of the MERL fits (bench/merl_model.py): finite, reciprocal, and the
value bbm's definition gives at normal incidence."""

from pathlib import Path

import numpy as np
import pytest

from tests.helpers import bench_modules

ROOT = Path(__file__).resolve().parents[2]
FITS = ROOT.parent / "shared" / "data" / "merl_fits" / "low_cooktorrance_E2.fit"


@pytest.fixture(scope="module")
def merl_model():
    (module,) = bench_modules("merl_model")
    return module


@pytest.fixture(scope="module")
def glossy(merl_model):
    # blue-acrylic's line of low_cooktorrance_E2.fit, typed in (so this runs without the data folder)
    return merl_model.LowCookTorrance((0.0162, 0.0399, 0.109), (0.06877, 0.06156, 0.05938), 0.01082, 1.29353)


def directions(n: int, seed: int = 7) -> np.ndarray:
    v = np.random.default_rng(seed).normal(size=(n, 3))
    v[:, 2] = np.abs(v[:, 2])
    return v / np.linalg.norm(v, axis=-1, keepdims=True)


def test_normal_incidence_is_kd_over_pi_plus_ks_f0_over_pi_m2(merl_model):
    # h = n: D = 1/m² (Beckmann without 1/π), G = 1, Cook's F(1) = ((η − 1)/(η + 1))², Cook normalisation π
    fit = merl_model.LowCookTorrance((0.2, 0.3, 0.4), (0.5, 0.6, 0.7), 0.3, 1.5)
    n = np.array([0.0, 0.0, 1.0])
    f0 = (0.5 / 2.5) ** 2
    expected = np.array([0.2, 0.3, 0.4]) / np.pi + np.array([0.5, 0.6, 0.7]) * f0 / (np.pi * 0.09)
    np.testing.assert_allclose(fit.evaluate(n, n), expected, rtol=1e-12)


def test_cook_fresnel_matches_the_exact_dielectric_fresnel(merl_model):
    from cnlmc.bsdf import fresnel_dielectric

    c = np.linspace(0.01, 1.0, 50)
    np.testing.assert_allclose(merl_model.fresnel_cook(c, 1.5), fresnel_dielectric(c, 1.5), rtol=1e-9, atol=1e-12)


def test_reciprocal(glossy):
    wo, wi = directions(500, 1), directions(500, 2)
    np.testing.assert_allclose(glossy.evaluate(wo, wi), glossy.evaluate(wi, wo), rtol=1e-10)


@pytest.mark.parametrize("mu", [0.0, 1e-12, 1e-6, 1e-3])
def test_finite_and_non_negative_at_grazing(glossy, mu):
    grazing = np.array([np.sqrt(1.0 - mu * mu), 0.0, mu])
    others = directions(400, 3)
    for f in (glossy.evaluate(grazing, others), glossy.evaluate(others, grazing), glossy.evaluate(grazing, grazing)):
        assert np.all(np.isfinite(f)) and np.all(f >= 0.0)


def test_zero_below_the_horizon(glossy):
    below = np.array([0.0, 0.6, -0.8])
    assert np.all(glossy.evaluate(below, directions(10)) == 0.0)


@pytest.mark.skipif(not FITS.is_file(), reason="../shared/data is not beside this checkout")
def test_the_fit_file_gives_fifty_materials(merl_model):
    fits = merl_model.parse_low_fits(FITS)
    assert len(fits) == 50
    assert fits["blue-acrylic"].roughness == pytest.approx(0.01082) and fits["blue-acrylic"].eta == pytest.approx(
        1.29353
    )
