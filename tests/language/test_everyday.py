"""Phrases nobody tuned for compile to plausible materials."""

import colorsys
from pathlib import Path

import pytest

from cnlmc.colour import linear_to_srgb

from .conftest import first


def hue_deg(rgb):
    """Hue of a linear colour, measured on its sRGB encoding (as a person picks colours)."""
    return colorsys.rgb_to_hsv(*[linear_to_srgb(c) for c in rgb])[0] * 360


def material(compile_text, text):
    return first(compile_text(text))


@pytest.mark.parametrize(
    "text",
    [
        "brushed stainless steel",
        "polished brass",
        "hammered copper",
        "satin nickel",
        "raw aluminum",
        "tarnished silver",
        "polished chrome",
    ],
)
def test_metals_are_conductors_with_measured_f0(compile_text, text):
    m = material(compile_text, text)
    assert m["model"]["base"] == "conductor"
    assert m["model"]["diffuse"] is None
    f0 = m["params"]["f0"]
    assert all(0.3 < c <= 1.05 for c in f0)
    assert "eta" in m["params"] and "k" in m["params"]
    assert "ior" not in m["params"]


def test_matte_is_rough_and_polished_is_smooth(compile_text):
    assert material(compile_text, "matte black plastic")["params"]["roughness"] >= 0.7
    assert material(compile_text, "polished brass")["params"]["roughness"] <= 0.05
    assert material(compile_text, "glossy white porcelain")["params"]["roughness"] <= 0.1


@pytest.mark.parametrize(
    "text,hue",
    [
        ("glossy red plastic", 0),
        ("dark green paint", 120),
        ("navy blue velvet", 240),
        ("bright yellow plastic", 60),
        ("orange powder-coated steel", 39),
        ("teal ceramic", 180),
    ],
)
def test_colours_land_in_the_right_hue(compile_text, text, hue):
    rgb = material(compile_text, text)["params"]["base_color"]
    distance = abs((hue_deg(rgb) - hue + 180) % 360 - 180)
    assert distance < 15, (rgb, hue_deg(rgb))


def test_pale_is_lighter_and_dark_is_darker(compile_text):
    blue = material(compile_text, "blue plastic")["params"]["base_color"]
    pale = material(compile_text, "pale blue plastic")["params"]["base_color"]
    dark = material(compile_text, "dark blue plastic")["params"]["base_color"]
    assert sum(dark) < sum(blue) < sum(pale)


def test_model_is_no_more_than_needed(compile_text):
    assert material(compile_text, "weathered concrete")["model"]["base"] == "diffuse"
    assert material(compile_text, "red plastic")["model"] == {
        "base": "dielectric",
        "distribution": "ggx",
        "anisotropic": False,
        "coat": False,
        "diffuse": "lambert",
    }
    assert material(compile_text, "red plastic")["maps"] == {}
    assert material(compile_text, "glossy paper")["model"]["base"] == "dielectric"
    assert material(compile_text, "velvet")["model"]["diffuse"] == "oren_nayar"
    assert "roughness" not in material(compile_text, "velvet")["params"]


def test_coats(compile_text):
    oak = material(compile_text, "oak with a glossy white varnish")
    assert oak["model"]["coat"] and oak["params"]["coat"]["roughness"] < 0.1
    car = material(compile_text, "metallic red car paint")
    assert car["model"]["coat"] and car["params"]["coat"]["name"] == "clear coat"
    assert material(compile_text, "steel with a clear coat")["params"]["coat"]["ior"] == 1.5


def test_plating_and_galvanizing_take_the_metal_optics(compile_text, stdlib):
    gold = stdlib.entry("nouns", "gold")
    assert material(compile_text, "gold plated steel")["params"]["f0"] == gold.get("f0")
    assert material(compile_text, "galvanized steel")["params"]["eta"] == stdlib.entry("nouns", "zinc").get("eta")


def test_painting_a_metal_makes_it_a_dielectric(compile_text):
    m = material(compile_text, "red painted steel")
    assert m["model"]["base"] == "dielectric" and "eta" not in m["params"]
    assert m["params"]["base_color"] == [0.783538, 0.0, 0.0]  # the survey's red #e50000


def test_maps_only_where_the_surface_varies(compile_text):
    assert set(material(compile_text, "heavily rusted iron")["maps"]) == {"base_color", "roughness", "mask"}
    heavy = material(compile_text, "heavily rusted iron")["maps"]["mask"]["params"]["coverage"]
    assert material(compile_text, "rusty iron")["maps"]["mask"]["params"]["coverage"] == 0.7  # mostly rust
    assert 0.9 < heavy < 1.0  # more than 0.7, saturating below the range's top (issue #14: no clamp)
    assert material(compile_text, "hammered copper")["maps"]["normal"]["graph"] == "hammered"
    assert material(compile_text, "polished copper")["maps"] == {}


def test_or_gives_named_variants(compile_text):
    r = compile_text("hull: red or blue anodized aluminum")
    names = [(m["name"], m["variant"]["name"]) for m in r.materials]
    assert names == [("hull__red", "red"), ("hull__blue", "blue")]
    assert {m["variant"]["group"] for m in r.materials} == {"hull"}


def test_and_joins_treatments(compile_text):
    m = material(compile_text, "brushed and anodized aluminum")
    assert m["model"]["anisotropic"] and m["params"]["roughness"] == 0.3


def test_articles_case_and_spacing_are_tolerated(compile_text):
    a = material(compile_text, "A  Lightly BRUSHED ,  blue Anodized   aluminium")
    b = material(compile_text, "lightly brushed, blue anodized aluminum")
    assert a["params"] == b["params"]


PHRASES = (Path(__file__).parent / "fixtures" / "everyday_phrases.txt").read_text().splitlines()


@pytest.mark.parametrize("phrase", PHRASES)
def test_designer_phrases_compile_cleanly(compile_text, phrase):
    result = compile_text(phrase)
    assert result.ok and not result.diagnostics, [d.message for d in result.diagnostics]
    assert len(result.materials) == 1


@pytest.mark.parametrize(
    "text,same_as",
    [
        ("lightly rusty, iron", "lightly rusty iron"),  # a comma before the noun
        ("brushed, and anodized aluminum", "brushed and anodized aluminum"),  # ', and' between groups
        ("oak with a glossy, white varnish", "oak with a glossy white varnish"),
    ],
)
def test_extra_punctuation_is_tolerated(compile_text, text, same_as):
    a, b = material(compile_text, text), material(compile_text, same_as)
    assert a["params"] == b["params"] and a["model"] == b["model"]


@pytest.mark.parametrize(
    ("phrase", "noun"), [("floral white beech", "beech"), ("ugly yellow gold", "gold"), ("dull red wine", "red wine")]
)
def test_a_colour_keeps_its_words_unless_the_rest_is_a_word(compile_text, phrase, noun):
    """A multi-word colour gives way to a multi-word noun on its last word only when the words
    before that noun are a word themselves ('dull' in 'dull red wine'; 'floral' is not)."""
    m = material(compile_text, phrase)
    rules = {step["rule"] for steps in m["provenance"].values() for step in steps}
    assert f"nouns.{noun}" in rules, sorted(rules)
