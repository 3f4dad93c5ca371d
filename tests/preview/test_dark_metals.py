"""Dark metals still shine (issue #15 item 2, docs/bsdf.md "Finishes and layers").

A dyed oxide or a tinted film is a clear dielectric over the metal: its surface reflection is a
white highlight whatever the colour under it. In the preview (studio environment, the split-sum
tier) black anodized aluminium's brightest 1 % of pixels reach at least half of a white glossy
dielectric's highlight (its brightest 1 % above its white body), over a dark body; the same for
the other glossy dark metals of the issue. 'matte black metal' spreads its highlight (a rough
film): it shines like matte black plastic, not a black disc. The same metal with the colour as a
bare tint (no layer) is the flat black disc the issue describes, so the check can fail.
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest

from .conftest import material_of

WHITE_DIELECTRIC = "glossy white plastic"
DARK_METALS = ["black anodized aluminium", "gunmetal steel", "blue anodized aluminum"]


def luminance(rgb: np.ndarray) -> np.ndarray:
    return rgb @ np.array([0.2126, 0.7152, 0.0722])


def sphere_pixels(renderer, scene, material) -> np.ndarray:
    frame = renderer.render(material, tier="splitsum", scene=scene, hdr=True)
    covered = frame.rgba[..., 3] > 0
    return luminance(frame.hdr[..., :3][covered])


def highlight(pixels: np.ndarray) -> float:
    return float(np.percentile(pixels, 99))


@pytest.fixture(scope="module")
def white_highlight(renderer, scene) -> float:
    """The white dielectric's highlight: its brightest 1 % above its white body (the median)."""
    pixels = sphere_pixels(renderer, scene, material_of(WHITE_DIELECTRIC))
    return highlight(pixels) - float(np.median(pixels))


@pytest.mark.parametrize("phrase", DARK_METALS)
def test_a_dark_metal_has_a_white_highlight(renderer, scene, white_highlight, phrase):
    pixels = sphere_pixels(renderer, scene, material_of(phrase))
    assert highlight(pixels) >= 0.5 * white_highlight, (phrase, highlight(pixels), white_highlight)


@pytest.mark.parametrize("phrase", ["black anodized aluminium", "matte black metal"])
def test_a_black_metal_keeps_a_dark_body(renderer, scene, white_highlight, phrase):
    pixels = sphere_pixels(renderer, scene, material_of(phrase))
    assert np.median(pixels) < 0.1 * white_highlight, (phrase, np.median(pixels))


def test_matte_black_metal_shines_like_matte_black_plastic(renderer, scene):
    metal = sphere_pixels(renderer, scene, material_of("matte black metal"))
    plastic = sphere_pixels(renderer, scene, material_of("matte black plastic"))
    assert metal.mean() > 0.5 * plastic.mean(), (metal.mean(), plastic.mean())


def test_the_highlight_is_white_over_a_blue_body(renderer, scene):
    frame = renderer.render(material_of("blue anodized aluminum"), tier="splitsum", scene=scene, hdr=True)
    rgb = frame.hdr[..., :3][frame.rgba[..., 3] > 0]
    body = np.median(rgb, axis=0)
    peak = rgb[np.argmax(luminance(rgb))]
    assert body[2] > 4 * body[0]  # a blue body (the red is the oxide reflecting the grey studio)
    # the oxide's white reflection in the highlight (red and green), over the metal's own blue one
    assert peak[0] > 0.25 * peak[2] and peak[1] > 0.25 * peak[2], peak


def test_without_the_layer_black_aluminium_is_a_black_disc(renderer, scene, white_highlight):
    """The check is live: the bare tinted conductor (the old reading) has no highlight."""
    m = material_of("black anodized aluminium")
    bare = replace(m, model=replace(m.model, coat=False), params=replace(m.params, coat=None))
    assert highlight(sphere_pixels(renderer, scene, bare)) < 0.05 * white_highlight
