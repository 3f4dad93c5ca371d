"""Mitsuba's Russian roulette in a bright medium (backends/exchange/mitsuba_subsurface.py,
VOLUME_RR_DEPTH_MAX): the exported and preview scenes start it after the events a path takes, so a
white body renders as a white body, not as speckle darker than it is."""

from __future__ import annotations

import numpy as np
import pytest

from cnlmc.api import compile_source, emit
from cnlmc.backends.exchange.mitsuba_subsurface import (
    MITSUBA_RR_DEPTH,
    VOLUME_RR_DEPTH_MAX,
    medium_entry,
    roulette_depth,
    scattering_events,
)
from tests.helpers import require


def _material(phrase: str):
    result = compile_source(phrase)
    assert result.ok, result.diagnostics
    return result.document.materials[0]


def _depth(phrase: str) -> int:
    entry = medium_entry(_material(phrase), "m")
    return roulette_depth([entry] if entry is not None else [])


def test_a_bright_medium_plays_roulette_only_after_its_paths_events():
    jade, wax, milk = _depth("jade"), _depth("candle wax"), _depth("whole milk")
    assert 500 < milk < VOLUME_RR_DEPTH_MAX  # albedo 0.9996: ~900 events a path
    assert MITSUBA_RR_DEPTH <= jade < wax < milk  # a darker medium needs fewer
    assert _depth("white porcelain") == VOLUME_RR_DEPTH_MAX  # Rd 0.99: 130,000 events, the cost bound


def test_an_absorbing_glass_keeps_mitsubas_default():
    assert _depth("red wine") == MITSUBA_RR_DEPTH
    assert roulette_depth([]) == MITSUBA_RR_DEPTH


@pytest.mark.parametrize("albedo, g", [(1.0, 0.0), (1.0, 0.9), (0.0, -0.5), (0.999999, 0.99)])
def test_the_depth_is_finite_where_the_formula_is_not(albedo, g):
    depth = roulette_depth([{"events": scattering_events([albedo] * 3, g)}])
    assert MITSUBA_RR_DEPTH <= depth <= VOLUME_RR_DEPTH_MAX


def test_the_exported_scene_carries_the_depth_as_an_override():
    result = compile_source("whole milk")
    xml = emit(result.ir, "mitsuba", {}).artifacts[0].content
    assert f'<default name="rr_depth" value="{_depth("whole milk")}"/>' in xml
    assert '<integer name="rr_depth" value="$rr_depth"/>' in xml


@pytest.mark.mitsuba
def test_white_porcelain_in_a_white_furnace_is_bright_and_smooth(tmp_path):
    """Measured at the old default (rr_depth 5): mean 0.45, pixels up to 23; lit by a white world a
    medium returns at most what it gets, and with the roulette late no pixel is a firefly."""
    require("mitsuba", "mitsuba")
    from cnlmc.backends.preview.environment import ENV_HEIGHT, ENV_WIDTH, Environment, KeyLight
    from cnlmc.backends.preview.mitsuba_scene import render_scene
    from cnlmc.backends.preview.render import default_scene
    from cnlmc.backends.preview.subsurface_reference import export_subsurface_scene

    env = Environment("white", np.ones((ENV_HEIGHT, ENV_WIDTH, 3), np.float32), KeyLight(irradiance=0.0))
    scene = default_scene("sphere", env, (24, 24))
    scene.background = "transparent"
    path = export_subsurface_scene(_material("white porcelain"), scene, tmp_path, 24, 24, spp=32)
    image, _ = render_scene(path, spp=32, variant="vectorized")
    inside = image[..., 3] > 0.999
    luminance = (image[..., :3] / image[..., 3:].clip(1e-6))[inside] @ [0.2126, 0.7152, 0.0722]
    assert 0.6 < float(luminance.mean()) <= 1.02
    assert float(luminance.max()) < 5.0
