"""Indoor ageing tarnishes copper alloys and silver (issue #14 'like an old penny', #15 colour and
texture): 'aged', 'old' and 'tarnished' draw the tarnish graph's brown film over the metal's own
colour, which stays a metal; outdoor 'weathered' keeps the green patina; iron still rusts."""

from __future__ import annotations

import numpy as np
import pytest

from cnlmc.backends.maps.bake import bake
from tests.language.meaning import lch, material, refined

METALS = ("copper", "brass", "bronze", "silver")


def seen_colour(m: dict) -> np.ndarray:
    """The mean colour of the metal's baked colour map over its own tint, times its measured F0."""
    tint = bake({"base_color": m["maps"]["base_color"]}, m["params"], size=64)["base_color"]
    return tint.reshape(-1, 3).mean(axis=0) * np.asarray(m["params"]["f0"])


@pytest.mark.parametrize("metal", METALS)
@pytest.mark.parametrize("word", ("aged", "old", "tarnished"))
def test_indoor_ageing_tarnishes_copper_alloys_and_silver_as_a_metal(word, metal):
    m = material(f"{word} {metal}")
    assert m["model"]["base"] == "conductor"
    assert m["maps"]["base_color"]["graph"] == m["maps"]["roughness"]["graph"] == "tarnish"
    assert "mask" not in m["maps"]  # a film, not a Lambert crust: the highlight stays metallic
    clean = np.asarray(material(metal)["params"]["f0"]) * np.asarray(material(metal)["params"]["base_color"])
    seen = seen_colour(m)
    assert lch(list(seen))[0] < lch(list(clean))[0] - 0.1  # darker
    assert seen[0] > seen[1] > seen[2]  # browner: the film absorbs blue most


def test_an_old_penny_reads_brown_and_weathered_copper_green():
    L, C, h = lch(list(seen_colour(material("an old penny"))))
    assert 40 <= h <= 80 and C > 0.04 and L < 0.65
    weathered = material("weathered copper")
    assert weathered["maps"]["base_color"]["graph"] == "patina" and "mask" in weathered["maps"]


def test_old_iron_still_rusts():
    assert material("old iron")["maps"]["base_color"]["graph"] == "rust"


def test_slightly_tarnished_covers_less():
    light = material("slightly tarnished silver")["maps"]["base_color"]["params"]["coverage"]
    full = material("tarnished silver")["maps"]["base_color"]["params"]["coverage"]
    assert 0 < light < full


def test_ageing_is_a_visible_change_and_darker_still_darkens_the_tarnished_metal():
    session = refined("copper")
    before = session.material.get("maps") or {}
    aged = session.refine("age it a bit")
    assert aged["maps"] != before and aged["maps"]["base_color"]["graph"] == "tarnish"
    darker = session.refine("darker")
    assert lch(list(seen_colour(darker)))[0] < lch(list(seen_colour(aged)))[0]
