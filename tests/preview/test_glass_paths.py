"""What a rough glass ball keeps inside after its first exit (#15): the traced table
(backends/preview/glass_paths.py) against the physics it must reproduce, and the preview that
uses it conserving energy in a white furnace (real renders on llvmpipe)."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from cnlmc.backends.preview import glass_paths
from cnlmc.backends.preview.glass import PATH_ROWS, internal_paths

from .conftest import material_of

SIZE = 64


def test_a_nearly_smooth_ball_keeps_the_far_sides_fresnel_reflection():
    """Through the centre of a smooth ball the light meets the far side at normal incidence:
    ((ior - 1) / (ior + 1))^2 of it reflects back (4.3 % at 1.52) and leaves later, towards the
    viewer, after two more chords."""
    values = glass_paths.trace(1.52, 0.005, 0.999, 20000, np.random.default_rng(3))
    assert values["more"] == pytest.approx(((1.52 - 1) / 2.52) ** 2, abs=0.004)
    assert values["angle"] == pytest.approx(np.pi, abs=0.15)  # back towards the viewer
    assert values["length"] == pytest.approx(4.0, abs=0.2)


@pytest.mark.parametrize("mu", [0.9, 0.6, 0.3])
def test_a_nearly_smooth_ball_bends_the_first_exit_as_a_lens(mu):
    """Snell at both interfaces of a smooth ball: the ray leaves deviated by 2 (theta_i - theta_t)
    towards the centre (negative: away from the entry's side)."""
    values = glass_paths.trace(1.52, 0.005, mu, 4000, np.random.default_rng(5))
    theta_i = np.arccos(mu)
    theta_t = np.arcsin(np.sin(theta_i) / 1.52)
    assert values["first_angle"] == pytest.approx(-2.0 * (theta_i - theta_t), abs=0.02)
    assert values["first_spread"] < 0.05 and values["first_mean_cos"] > 0.99


def test_roughness_and_grazing_entry_keep_more_light_inside():
    """Tilted facets reach total internal reflection long before the macro angle does: through
    the centre the share that leaves late grows with roughness; entering towards the silhouette
    more stays inside than through the centre (until very rough facets let grazing light out)."""
    t = glass_paths.table()
    i = list(t["iors"]).index(1.52)
    more = t["more"][i]
    centre = more[:, -1]
    assert (np.diff(centre) > -0.02).all() and centre[0] < 0.06 and centre[-1] > 0.4
    moderate = np.asarray(t["alphas"]) <= 0.5
    assert (more[moderate, 0] > more[moderate, -1] + 0.2).all()
    assert (np.diff(more[moderate], axis=1) < 0.02).all()  # less towards the centre


@settings(max_examples=4, deadline=None)
@given(ior=st.sampled_from([1.31, 1.52, 2.0]), alpha=st.sampled_from([0.1, 0.25, 0.5]), k=st.integers(0, 15))
def test_the_stored_table_is_what_the_tracer_measures(ior, alpha, k):
    """The data file is the tracer's output (regenerate: python -m cnlmc.backends.preview.glass_paths)."""
    t = glass_paths.table()
    i, j = list(t["iors"]).index(ior), list(t["alphas"]).index(alpha)
    fresh = glass_paths.trace(ior, alpha, float(t["cosines"][k]), 4096, np.random.default_rng(k))
    assert fresh["more"] == pytest.approx(float(t["more"][i, j, k]), abs=0.03)
    assert fresh["length"] == pytest.approx(float(t["length"][i, j, k]), rel=0.15)


def test_the_texture_rows_follow_sqrt_alpha_and_stay_in_range():
    rows = internal_paths(1.5)
    assert rows.shape == (2 * PATH_ROWS, glass_paths.COSINES, 4) and np.isfinite(rows).all()
    assert ((rows[:PATH_ROWS, :, 0] >= 0) & (rows[:PATH_ROWS, :, 0] <= 1)).all()  # a share
    assert ((rows[:PATH_ROWS, :, 2] > 0) & (rows[:PATH_ROWS, :, 2] <= 1)).all()  # prefilter alphas
    assert ((rows[PATH_ROWS:, :, 2] > 0) & (rows[PATH_ROWS:, :, 2] <= 1)).all()
    assert (np.abs(rows[PATH_ROWS:, :, [0, 3]]) <= 1).all()  # mean cosines
    row = PATH_ROWS // 2
    expected = glass_paths.rows_for(1.5, (row / (PATH_ROWS - 1)) ** 2)
    assert rows[row, :, 0] == pytest.approx(expected[:, glass_paths.KEYS.index("more")].astype(np.float32), abs=1e-6)


@pytest.fixture(scope="module")
def white(gl_available):
    from cnlmc.backends.preview.environment import ENV_HEIGHT, ENV_WIDTH, Environment, KeyLight
    from cnlmc.backends.preview.render import Renderer

    env = Environment("white", np.ones((ENV_HEIGHT, ENV_WIDTH, 3), np.float32), KeyLight(irradiance=0.0))
    with Renderer(SIZE) as renderer:
        scene = renderer.scene("sphere", env)
        scene.background = "transparent"
        yield renderer, scene


@pytest.mark.parametrize("phrase", ["frosted glass", "sandblasted glass", "clear glass", "water"])
def test_glass_returns_no_more_than_the_white_furnace_gives(white, phrase):
    """A nearly clear ball in a uniform white environment, the default tier: nothing may come out
    brighter than the light around it (energy <= 1), and a rough one loses little (what it
    keeps inside leaves later, it is not dropped). (`analytic` lights its reflection with
    pi f(v, n) times the mean radiance, above 1 at a lobe's peak by design: docs/preview.md.)"""
    renderer, scene = white
    frame = renderer.render(material_of(phrase), tier="splitsum", scene=scene, hdr=True)
    inside = frame.rgba[..., 3] > 250
    values = frame.hdr[inside, :3]
    assert np.isfinite(values).all()
    assert values.max() <= 1.02, (phrase, values.max())
    assert values.mean() > 0.85, (phrase, values.mean())
