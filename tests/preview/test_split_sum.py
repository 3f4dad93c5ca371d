"""The specialized split-sum tier: its albedo tables are the material's own BSDF integrated,
and its image stays close to the tier that integrates the environment by brute force."""
from __future__ import annotations

import numpy as np
import pytest

from cnlmc.backends.preview.albedo_tables import MU_SIZE, ROWS, albedo_tables
from cnlmc.bsdf.evaluate import albedo

from .conftest import material_of


def with_colour(material: dict, colour) -> dict:
    return {**material, "params": {**material["params"], "base_color": list(colour)}}


@pytest.mark.parametrize("phrase", ["terracotta", "gold", "clear-coated red car paint", "glossy blue plastic"])
def test_black_plus_colour_times_tint_is_the_albedo_of_that_colour(phrase):
    """f is affine in the base colour, so black + rho * tint reproduces any rho's albedo."""
    m = material_of(phrase)
    black, tint = albedo_tables(m)
    assert black.shape == tint.shape == (1, MU_SIZE, 4)
    column = 20
    mu = (column + 0.5) / MU_SIZE
    rho = np.array([0.7, 0.3, 0.1])
    want = albedo(with_colour(m, rho), mu, 512)
    np.testing.assert_allclose(black[0, column, :3] + rho * tint[0, column, :3], want, rtol=1e-4, atol=1e-5)


def test_an_uncoated_conductor_is_all_tint_and_a_diffuse_one_has_no_specular_part():
    black, tint = albedo_tables(material_of("gold"))
    assert np.all(black[..., :3] == 0) and tint[..., :3].max() > 0.9
    black, tint = albedo_tables(material_of("suede"))
    assert np.all(black[..., :3] == 0) and 0.5 < tint[0, -1, 0] < 1.0      # Oren-Nayar at normal view


def test_lobes_lean_where_their_first_moment_points():
    """A: 1 = the mirror direction (smooth lobes), towards the normal for rough lobes (more at
    grazing), negative = towards the viewer (Oren-Nayar's back-scattering), 0 for Lambert."""
    black, _ = albedo_tables(material_of("glossy blue plastic"))
    assert np.all(np.abs(black[0, :, 3] - 1) < 0.02)
    _, plastic_tint = albedo_tables(material_of("glossy blue plastic"))
    assert np.all(np.abs(plastic_tint[0, :, 3]) < 0.01)
    _, rough = albedo_tables(material_of("rough iron"))
    assert 0.2 < rough[0, 0, 3] < rough[0, -1, 3] < 0.95
    _, suede = albedo_tables(material_of("suede"))
    assert np.all(suede[0, :, 3] < -0.05)


def test_the_dielectric_diffuse_part_sees_the_interface_twice():
    """(1 - F(view)) (1 - F(light)) weighting: at normal view about 0.96 x 0.91 for ior 1.5,
    well under the 1 - E_spec a generic split-sum uses."""
    black, tint = albedo_tables(material_of("glossy blue plastic"))
    assert 0.84 < tint[0, -1, 0] < 0.90
    assert tint[0, -1, 0] < 1.0 - black[0, -1, 0] - 0.05


def test_a_roughness_map_gets_one_row_per_alpha_and_rougher_rows_reflect_less_at_grazing():
    oak = material_of("oak")
    assert "roughness" in oak["maps"]
    black, _ = albedo_tables(oak, mapped_roughness=True)
    assert black.shape == (ROWS, MU_SIZE, 4)
    assert black[0, 0, 0] > black[-1, 0, 0]
    assert np.all(np.isfinite(black)) and black[..., :3].min() >= 0 and black[..., :3].max() <= 1


def test_fresnel_option_changes_the_table():
    _, exact = albedo_tables(material_of("gold"), "exact")
    _, schlick = albedo_tables(material_of("gold"), "schlick")
    assert np.abs(exact - schlick).max() > 1e-3


@pytest.mark.parametrize("phrase", ["gold", "glossy blue plastic", "clear-coated red car paint", "terracotta"])
def test_split_sum_stays_close_to_brute_force_integration(renderer, scene, phrase):
    """Mean absolute difference of the linear image (object pixels) to mc1024: a few percent."""
    m = material_of(phrase)
    split = renderer.render(m, tier="splitsum", scene=scene, hdr=True).hdr
    brute = renderer.render(m, tier="mc1024", scene=scene, hdr=True).hdr
    inside = brute[..., 3] > 0.99
    error = np.abs(split[inside, :3] - brute[inside, :3]).mean() / brute[inside, :3].mean()
    assert error < 0.05, f"{phrase}: relative mean error {error:.3f}"
