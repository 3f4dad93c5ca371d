"""The numpy reference for a medium (cnlmc.bsdf.subsurface): the albedo inversion round-trips, gives
back the dataset's measured media, and nothing it describes returns more light than it gets."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from cnlmc.api import compile_source
from cnlmc.bsdf.subsurface import (
    Medium,
    appearance,
    diffusion_profile,
    dipole_albedo,
    medium_of,
    reduced_albedo_of,
    slab,
)

DATA = Path(__file__).resolve().parents[3] / "shared" / "data" / "physicallybased_materials.json"
unit = st.floats(0.01, 0.99)
radius = st.floats(1e-4, 0.05)


@settings(max_examples=60, deadline=None, derandomize=True, suppress_health_check=[HealthCheck.too_slow])
@given(color=st.tuples(unit, unit, unit), radii=st.tuples(radius, radius, radius), g=st.floats(-0.9, 0.9))
def test_the_inversion_round_trips(color, radii, g):
    """(color, radius, g) -> sigma_a, sigma_s -> (color, radius): the same to 1e-9."""
    medium = medium_of(color, radii, g, 1.4)
    back_colour, back_radius = appearance(medium, 1.4)
    assert back_colour == pytest.approx(color, abs=1e-9)
    assert back_radius == pytest.approx(radii, rel=1e-9)
    assert (medium.sigma_a >= 0).all() and (medium.single_albedo < 1).all()


def test_the_dipole_albedo_rises_from_zero_to_one():
    alphas = np.linspace(0, 1, 201)
    albedo = dipole_albedo(alphas, 1.5)
    assert albedo[0] == 0 and albedo[-1] == pytest.approx(1.0) and (np.diff(albedo) > 0).all()
    colours = np.linspace(0.05, 0.95, 19)
    assert (reduced_albedo_of(colours, 1.5) > colours).all()  # a body scatters more than its surface shows


@pytest.mark.parametrize(
    ("name", "colour_tol"), [("Marble", 0.002), ("Ketchup", 0.002), ("Cream", 0.02), ("Milk", 0.02)]
)
def test_the_datasets_measured_media_give_back_its_colour_and_radius(name, colour_tol):
    """physicallybased.info's coefficients (per cm, Jensen et al. 2001) -> its colour and its
    subsurfaceRadius (cm): the dataset's radius is 1/sigma_tr and its colour the dipole's albedo."""
    if not DATA.exists():
        pytest.skip("../shared/data is not beside this checkout")
    entry = next(e for e in json.loads(DATA.read_text())["data"] if e["name"] == name)
    coefficients = entry["volumeCoefficients"]
    medium = Medium(
        np.array(coefficients["absorption"][0]["color"]), np.array(coefficients["scattering"][0]["color"]), 0.0
    )
    colour, radius_cm = appearance(medium, entry["ior"])
    assert colour == pytest.approx(entry["color"][0]["color"], abs=colour_tol)
    assert radius_cm == pytest.approx(entry["subsurfaceRadius"], abs=0.002)


@pytest.mark.parametrize("albedo", [0.05, 0.5, 0.8, 0.99])
def test_the_diffusion_profile_returns_the_albedo_and_no_more(albedo):
    """∫ R(r) 2πr dr = albedo <= 1 (Christensen-Burley's normalisation), by quadrature in log r."""
    mfp = 0.004
    r = np.geomspace(1e-9, 1.0, 200_001)
    integrand = diffusion_profile(r, albedo, mfp) * 2 * np.pi * r * r  # d(ln r) = dr / r
    total = float(np.sum((integrand[1:] + integrand[:-1]) / 2 * np.diff(np.log(r))))
    assert total == pytest.approx(albedo, rel=1e-3)
    assert total <= 1.0


@settings(max_examples=40, deadline=None, derandomize=True, suppress_health_check=[HealthCheck.too_slow])
@given(color=st.tuples(unit, unit, unit), radii=st.tuples(radius, radius, radius), t=st.floats(1e-5, 0.1))
def test_a_sheet_returns_no_more_light_than_it_gets(color, radii, t):
    reflectance, transmittance = slab(medium_of(color, radii, 0.0, 1.45), t)
    assert (reflectance >= 0).all() and (transmittance >= 0).all()
    assert (reflectance + transmittance <= 1 + 1e-9).all()


def test_a_thin_leaf_lets_light_through_and_a_thick_block_of_it_does_not():
    leaf = compile_source("leaf").ir["materials"][0]["params"]
    medium = medium_of(leaf["subsurface"]["color"], leaf["subsurface"]["radius"], 0.0, leaf["ior"])
    _, through_sheet = slab(medium, leaf["subsurface"]["thickness"])
    _, through_block = slab(medium, 0.02)
    assert through_sheet[1] > 0.3 and through_sheet[1] > through_sheet[2]
    assert through_block.max() < 1e-6
