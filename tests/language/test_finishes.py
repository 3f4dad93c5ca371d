"""Treatment and coating words by what they do to each class (issue #14, docs/language.md "Finishes"):
glass processes, coats that are real layers, diffuse surfaces that get their Oren-Nayar sigma from
the words. Phrases here are deliberately not those of everyday.toml."""

import pytest

from cnlmc.api import compile_source, lexicon_for

from .conftest import first

LEXICON = lexicon_for()


def material(text):
    return first(compile_source(text, "finishes.cnl", LEXICON))


def params(text):
    return material(text)["params"]


def luminance(rgb):
    r, g, b = rgb
    return 0.2126 * r + 0.7152 * g + 0.0722 * b


def warnings(text):
    return [d.code for d in compile_source(text, "finishes.cnl", LEXICON).diagnostics if d.severity == "warning"]


# ---- glass: what each process does to a pane


def test_smoked_glass_is_a_neutral_darker_absorber_than_tinted_glass():
    clear, tinted, smoked = (luminance(params(t)["base_color"]) for t in ("quartz", "tinted quartz", "smoked quartz"))
    assert clear > tinted > smoked > 0.1
    r, g, b = params("smoked quartz")["base_color"]
    assert max(r, g, b) - min(r, g, b) < 0.02


def test_heavier_smoke_is_darker_and_stays_grey():
    shades = [params(f"{a}smoked glass")["base_color"] for a in ("lightly ", "", "heavily ", "extremely ")]
    lum = [luminance(c) for c in shades]
    assert lum == sorted(lum, reverse=True) and lum[-1] > 0.0
    for r, g, b in shades:
        assert max(r, g, b) - min(r, g, b) < 0.02 * max(r, g, b) + 1e-6


def test_a_tint_colour_is_the_glass_colour_and_it_stays_glass():
    m = material("amber tinted glass")
    r, g, b = m["params"]["base_color"]
    assert m["model"]["base"] == "glass" and r > g > b


@pytest.mark.parametrize("word", ["frosted", "acid-etched", "sandblasted", "brushed"])
def test_abraded_or_etched_glass_scatters_what_it_transmits(word):
    m = material(f"{word} borosilicate glass")
    assert m["model"]["base"] == "glass" and m["params"]["roughness"] >= 0.25
    assert warnings(f"{word} borosilicate glass") == []


def test_brushed_glass_is_a_lighter_frosting_than_etching():
    assert params("brushed glass")["roughness"] < params("etched glass")["roughness"]


def test_etched_metal_is_matted_not_refused():
    assert warnings("etched pewter") == []
    assert params("etched pewter")["roughness"] > params("pewter")["roughness"]


def test_polished_cloth_has_a_sheen_not_a_gloss():
    rough = params("polished linen")["roughness"]
    assert 0.4 <= rough <= 0.7
