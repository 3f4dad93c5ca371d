"""Velvet in the preview (issue #15 item 5, docs/bsdf.md "Sheen"): a bright grazing rim over a
darker facing centre, not a flat disc; the same colour without the sheen is another picture, and
it has no such rim (so the rim check can fail). Every tier draws the sheen (its own include)."""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest

from .conftest import material_of, stdlib_nouns

VELVETS = ["velvet", "navy blue velvet", "dusty pink velvet"]


def luminance(rgb: np.ndarray) -> np.ndarray:
    return rgb @ np.array([0.2126, 0.7152, 0.0722])


def rings(renderer, scene, material, tier: str = "splitsum") -> tuple[float, float, np.ndarray]:
    """(mean luminance of the outer ring, of the inner disc, the covered pixels' RGB): the disc is the
    sphere's pixels within 0.5 of its radius from its centre, the ring those beyond 0.85."""
    frame = renderer.render(material, tier=tier, scene=scene, hdr=True)
    covered = frame.rgba[..., 3] > 0.99
    ys, xs = np.nonzero(covered)
    cy, cx = ys.mean(), xs.mean()
    radius = np.sqrt(covered.sum() / np.pi)
    r = np.hypot(ys - cy, xs - cx) / radius
    lum = luminance(frame.hdr[..., :3][covered])
    return float(lum[r > 0.85].mean()), float(lum[r < 0.5].mean()), frame.hdr[..., :3][covered]


def without_sheen(material):
    return replace(material, params=replace(material.params, sheen_color=None))


@pytest.mark.parametrize("phrase", ["velvet", "navy blue velvet"])
def test_velvet_has_a_brighter_rim_than_centre(renderer, scene, phrase):
    ring, disc, _ = rings(renderer, scene, material_of(phrase))
    assert ring > 1.15 * disc, (phrase, ring, disc)


def test_a_pale_velvet_gains_a_rim(renderer, scene):
    """A pale body ('dusty pink', albedo 0.67 in red) outshines the sheen facing the viewer, so its
    rim is not brighter than its centre (0.85 of it); the sheen still lifts the rim against the
    centre by a quarter over the same body without it (0.69)."""
    m = material_of("dusty pink velvet")
    ring, disc, _ = rings(renderer, scene, m)
    bare_ring, bare_disc, _ = rings(renderer, scene, without_sheen(m))
    assert ring / disc > 1.15 * bare_ring / bare_disc, (ring / disc, bare_ring / bare_disc)


@pytest.mark.parametrize("phrase", ["velvet", "navy blue velvet"])
def test_without_the_sheen_there_is_no_rim(renderer, scene, phrase):
    """The check is live: the same body without its sheen is darker at the rim than facing."""
    ring, disc, _ = rings(renderer, scene, without_sheen(material_of(phrase)))
    assert ring < disc, (phrase, ring, disc)


@pytest.mark.parametrize("phrase", VELVETS)
def test_the_sheen_changes_the_picture(renderer, scene, phrase):
    m = material_of(phrase)
    _, _, with_it = rings(renderer, scene, m)
    _, _, without = rings(renderer, scene, without_sheen(m))
    assert with_it.shape == without.shape
    assert np.abs(with_it - without).mean() > 0.02 * without.mean(), phrase


def test_navy_velvet_is_blue_at_the_rim_and_in_the_centre(renderer, scene):
    _, _, rgb = rings(renderer, scene, material_of("navy blue velvet"))
    mean = rgb.mean(axis=0)
    assert mean[2] > 2.0 * mean[0] and mean[2] > 1.5 * mean[1], mean


@pytest.mark.parametrize("tier", ["analytic", "mc16"])
def test_every_tier_draws_the_rim(renderer, scene, tier):
    ring, disc, _ = rings(renderer, scene, material_of("navy blue velvet"), tier)
    assert ring > 1.15 * disc, (tier, ring, disc)


def test_every_noun_with_a_sheen_renders_finite(renderer, scene):
    """Each fibre noun of the stdlib that carries a sheen: finite, and not darker than without it
    at the rim (the sheen only adds at grazing what it takes from the body)."""
    nouns = [n for n in stdlib_nouns() if material_of(n).params.sheen_color is not None]
    assert len(nouns) >= 10, nouns
    for noun in nouns:
        frame = renderer.render(material_of(noun), tier="splitsum", scene=scene, hdr=True)
        assert np.isfinite(frame.hdr).all(), noun
        ring, _, _ = rings(renderer, scene, material_of(noun))
        bare_ring, _, _ = rings(renderer, scene, without_sheen(material_of(noun)))
        assert ring > bare_ring, (noun, ring, bare_ring)
