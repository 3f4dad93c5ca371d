"""The words of CMF (colour, material, finish) notes for consumer products (issue #14, categories
of held-out set 47): technical plastics and fabrics, trade colour names, PVD, bead blasting, 3D
printing, spec-sheet abbreviations, and two names of one material side by side."""

from __future__ import annotations

import pytest

from tests.language.meaning import compiled, lch, material, same_look


@pytest.mark.parametrize(
    "phrase, noun",
    [
        ("black tpu overmould", "tpu"),
        ("polished white zirconia ceramic", "zirconia"),
        ("matte forged carbon", "forged carbon"),
        ("grey composite decking", "composite decking"),
        ("black ballistic nylon", "nylon fabric"),
        ("ripstop nylon", "nylon fabric"),
        ("cool grey nylon PA12", "nylon"),
        ("ss brushed", "stainless steel"),
    ],
)
def test_cmf_nouns_name_their_material(phrase, noun):
    result = compiled(phrase)
    assert result.ok, [d.message for d in result.diagnostics]
    rules = {step["rule"] for steps in material(phrase)["provenance"].values() for step in steps}
    assert f"nouns.{noun}" in rules, rules


def test_forged_carbon_is_black_coated_and_marbled():
    m = material("forged carbon")
    assert m["model"]["coat"] and lch(m["params"]["base_color"])[0] < 0.35 and "base_color" in m["maps"]


@pytest.mark.parametrize(
    "colour, lightness, hue",
    [
        ("space grey", (0.45, 0.6), None),
        ("signal red", (0.35, 0.6), (0, 40)),
        ("safety orange", (0.65, 0.8), (40, 75)),
        ("hi-vis yellow", (0.85, 1.0), (100, 130)),
        ("traffic white", (0.9, 1.0), None),
        ("anthracite", (0.25, 0.45), None),
    ],
)
def test_trade_colour_names(colour, lightness, hue):
    l, c, h = lch(material(f"{colour} plastic")["params"]["base_color"])
    assert lightness[0] <= l <= lightness[1], l
    assert (c < 0.04) if hue is None else (hue[0] <= h <= hue[1] and c > 0.08), (c, h)


def test_anthracite_alone_is_still_the_coal():
    assert material("anthracite")["model"]["base"] == "dielectric" and "maps" in material("anthracite")


@pytest.mark.parametrize(
    "said, meant",
    [
        ("matt blk powder coat", "matte black powder coat"),
        ("wht gloss paint", "white glossy paint"),
        ("PVD coated brass", "plated brass"),
        ("bead blast aluminium", "sandblasted aluminium"),
        ("open-pore walnut", "matte walnut"),
        ("ash, white pigmented oil", "white oiled ash"),
        ("HPL laminate", "laminate"),
    ],
)
def test_cmf_words_read_as_the_everyday_words(said, meant):
    assert compiled(said).ok
    assert same_look(material(said), material(meant))


@pytest.mark.parametrize(
    "said", ["3d printed white nylon", "3D printed nylon", "3d-printed nylon", "SLS printed nylon"]
)
def test_a_3d_printed_part_is_fully_matte(said):
    result = compiled(said)
    assert result.ok, [d.message for d in result.diagnostics]
    m = material(said)
    assert m["model"]["base"] == "diffuse" or m["params"]["roughness"] >= 0.8  # so matte it has no highlight


def test_two_names_of_one_material_side_by_side_are_one():
    result = compiled("inox stainless steel")
    assert result.ok and any("both words name it" in d.message for d in result.diagnostics)
    assert same_look(material("inox stainless steel"), material("stainless steel"))


def test_no_before_a_two_word_coat_takes_the_coat_off_not_the_first_word():
    result = compiled("raw alu, no clear coat")
    assert not material("raw alu, no clear coat")["model"]["coat"]
    assert any("taking 'clear coat' off" in d.message for d in result.diagnostics)
    assert material("not clear glass")["params"] == material("frosted glass")["params"]  # 'not X' alone still negates X


@pytest.mark.parametrize("phrase, hue", [("blued steel", (225, 300)), ("oil rubbed bronze", (40, 100))])
def test_dark_metal_finishes_keep_their_hue(phrase, hue):
    m = material(phrase)
    l, c, h = lch([b * f for b, f in zip(m["params"]["base_color"], m["params"]["f0"])])
    assert l < 0.45 and c >= 0.04 and hue[0] <= h <= hue[1], (l, c, h)


def test_piano_black_is_a_black_mirror_gloss_and_still_a_colour_before_a_noun():
    assert material("piano black")["params"]["roughness"] <= 0.05
    assert lch(material("piano black")["params"]["base_color"])[0] < 0.25
    leather = material("piano black leather")
    assert "leather" in leather["name"] and lch(leather["params"]["base_color"])[0] < 0.25


def test_carbon_fibre_twill_is_carbon_fibre():
    assert same_look(material("carbon fibre twill, clear coat"), material("carbon fibre with a clear coat"))


@pytest.mark.parametrize("noun", ["leather", "oak", "walnut", "pine"])
def test_old_organic_materials_stay_brown_where_weathered_ones_grey(noun):
    old, weathered, plain = (
        lch(material(p)["params"]["base_color"]) for p in (f"old {noun}", f"weathered {noun}", noun)
    )
    assert old[1] >= 0.04 and abs(old[2] - plain[2]) < 15, old  # aged indoors: amber, the hue kept
    assert weathered[1] < old[1]  # outdoors: greyer
