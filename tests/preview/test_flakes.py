"""Flakes in the preview (issue #15 item 5, docs/preview.md "Flakes"): a metallic paint sparkles
(isolated pixels far brighter than their neighbours, which the same paint without flakes does not
have), is brighter where the key light's highlight is, deterministic, and every tier draws it."""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest

from .conftest import material_of

SIZE = 128  # at 64 px a pixel holds hundreds of paint flakes: the sparkle averages out, as it should


@pytest.fixture(scope="module")
def renderer(gl_available):
    from cnlmc.backends.preview.render import Renderer

    with Renderer(SIZE, msaa=4) as made:
        yield made


@pytest.fixture(scope="module")
def scene():
    from cnlmc.backends.preview.render import default_scene

    made = default_scene("sphere", "studio", (SIZE, SIZE))
    made.background = "transparent"
    return made


def luminance(rgb: np.ndarray) -> np.ndarray:
    return rgb @ np.array([0.2126, 0.7152, 0.0722])


def without_flakes(material):
    return replace(material, params=replace(material.params, flake_color=None, flake_density=0.0))


def render(renderer, scene, material, tier: str = "splitsum") -> tuple[np.ndarray, np.ndarray]:
    """(luminance image, coverage mask)."""
    frame = renderer.render(material, tier=tier, scene=scene, hdr=True)
    return luminance(frame.hdr[..., :3]), frame.rgba[..., 3] > 0.99


def sparkles(lum: np.ndarray, covered: np.ndarray) -> int:
    """Pixels more than twice as bright as the median of their 3x3 neighbourhood (inside the disc)."""
    pad = np.pad(lum, 1, mode="edge")  # measured at 128 px: 41-146 for the paint, 2 without flakes
    windows = np.stack([pad[y : y + lum.shape[0], x : x + lum.shape[1]] for y in range(3) for x in range(3)])
    inside = covered & np.pad(covered[1:-1, 1:-1], 1)
    return int((inside & (lum > 2.0 * np.median(windows, axis=0) + 0.05)).sum())


@pytest.mark.parametrize("tier", ["splitsum", "fis16", "analytic"])
def test_metallic_paint_sparkles_where_plain_paint_does_not(renderer, scene, tier):
    paint = material_of("metallic car paint")
    flaked = sparkles(*render(renderer, scene, paint, tier))
    plain = sparkles(*render(renderer, scene, without_flakes(paint), tier))
    assert flaked >= 20 and plain <= 5, (tier, flaked, plain)


def test_flakes_brighten_the_paint_and_are_deterministic(renderer, scene):
    paint = material_of("metallic car paint")
    lum, covered = render(renderer, scene, paint)
    again, _ = render(renderer, scene, paint)
    plain, _ = render(renderer, scene, without_flakes(paint))
    assert np.array_equal(lum, again)
    assert lum[covered].mean() > 1.3 * plain[covered].mean()
