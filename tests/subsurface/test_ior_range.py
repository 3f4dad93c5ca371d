"""The medium's numpy reference over the IR's whole IOR range [1, 5] (docs/subsurface.md, "The boundary"):
every function is finite, an albedo stays in [0, 1] and the inversion round-trips, also where the
Egan–Hilgeman fit alone would pass Fdr = 1 (η ≈ 3.88) and turn a translucent body black."""

from __future__ import annotations

import copy
import re
import warnings

import numpy as np
import pytest
from hypothesis import Phase, given, settings
from hypothesis import strategies as st

from cnlmc.api import compile_source, emit
from cnlmc.bsdf.subsurface import (
    appearance,
    boundary_a,
    diffuse_fresnel,
    diffusion_profile,
    dipole_albedo,
    medium_of,
    profile_shape,
    reduced_albedo_of,
    slab,
)

IORS = st.one_of(st.sampled_from([1.0, 2.0, 3.88, 3.9, 4.5, 5.0]), st.floats(1.0, 5.0))
unit = st.floats(0.01, 0.99)
radius = st.floats(1e-4, 0.05)
CHECK = settings(max_examples=40, deadline=None, derandomize=True, phases=[Phase.explicit, Phase.generate])


@pytest.fixture(autouse=True)
def overflow_is_an_error():
    with warnings.catch_warnings():
        warnings.simplefilter("error", RuntimeWarning)
        with np.errstate(over="raise", invalid="raise", divide="raise", under="ignore"):
            yield


@CHECK
@given(eta=IORS)
def test_the_boundary_reflects_less_than_all_diffuse_light(eta):
    fdr = diffuse_fresnel(eta)
    assert 0.0 <= fdr < 1.0
    assert np.isfinite(boundary_a(eta)) and boundary_a(eta) >= 1.0 - 1e-2  # A ≥ 1 (Fdr ≥ 0; the fit's 0.0016 at 1)


def test_the_fit_meets_the_exact_integral_where_it_hands_over():
    """Continuous at η = 2 (the switch) and exact at η = 1: no reflection at a matched boundary."""
    assert diffuse_fresnel(2.0) == pytest.approx(diffuse_fresnel(2.0 + 1e-9), abs=1e-4)
    assert diffuse_fresnel(1.0) == pytest.approx(0.0, abs=2e-3)
    values = [diffuse_fresnel(e) for e in np.linspace(1.0, 5.0, 81)]
    assert np.all(np.diff(values) > 0)  # a denser body traps more light, never less


@CHECK
@given(eta=IORS, alpha=st.floats(0.0, 1.0))
def test_the_dipole_albedo_is_an_albedo(eta, alpha):
    value = float(dipole_albedo(alpha, eta))
    assert 0.0 <= value <= 1.0


@CHECK
@given(eta=IORS, color=st.tuples(unit, unit, unit), radii=st.tuples(radius, radius, radius), g=st.floats(-0.9, 0.9))
def test_the_inversion_round_trips_at_every_ior(eta, color, radii, g):
    alpha = reduced_albedo_of(color, eta)
    assert np.all((alpha >= 0.0) & (alpha < 1.0))
    assert dipole_albedo(alpha, eta) == pytest.approx(color, abs=1e-9)
    medium = medium_of(color, radii, g, eta)
    assert np.all(np.isfinite(medium.sigma_a)) and np.all(medium.sigma_a >= 0.0)
    assert np.all((medium.single_albedo >= 0.0) & (medium.single_albedo < 1.0))
    back_colour, back_radius = appearance(medium, eta)
    assert back_colour == pytest.approx(color, abs=1e-9)
    # α' of a 0.99 colour under a dense boundary is 1 − 1e-5: 1 − α' keeps ~11 digits
    assert back_radius == pytest.approx(radii, rel=1e-7)
    reflectance, transmittance = slab(medium, 0.001)
    assert np.all(np.isfinite(reflectance + transmittance)) and np.all(reflectance + transmittance <= 1.0 + 1e-12)


@CHECK
@given(albedo=st.floats(0.0, 1.0), mfp=st.one_of(st.just(0.0), radius), r=st.floats(0.0, 0.1))
def test_the_diffusion_profile_is_finite_and_not_negative(albedo, mfp, r):
    assert np.isfinite(profile_shape(albedo)) and profile_shape(albedo) > 0.0
    value = float(diffusion_profile(r, albedo, mfp))
    assert np.isfinite(value) and value >= 0.0


def test_a_zero_radius_profile_is_no_light_away_from_the_entry_point():
    """d = 0 used to give NaN: no path inside means nothing leaves at r > 0."""
    profile = diffusion_profile(np.array([0.0, 1e-3, 0.01]), 0.8, 0.0)
    assert np.array_equal(profile, np.zeros(3))


@pytest.mark.parametrize("ior", [3.9, 4.5, 5.0])
def test_a_dense_wax_stays_translucent_in_the_mitsuba_export(ior):
    """Wax with the IR's highest IORs: a scattering medium, not a black absorber (was albedo 4e-19)."""
    result = compile_source("wax\n")
    assert result.ok
    ir = copy.deepcopy(result.ir)
    ir["materials"][0]["params"]["ior"] = ior
    scene = emit(ir, "mitsuba", {}).artifacts[0].content
    albedo = re.search(r'<rgb name="albedo" value="([^"]+)"', scene)
    assert albedo is not None
    values = [float(v) for v in albedo.group(1).split(",")]
    assert all(0.9 < v < 1.0 for v in values), values
