"""Everyday vocabulary that generalises (#14, package E2): food, drink and wood words as colours
before a material, fibre-and-fabric and substance-and-product pairs, garment and glass words, the
completions a phrase without a noun is offered, and politeness at the edges of a phrase.

Every phrase here is outside tests/language/everyday.toml (checked below): the held-out set is of
the same kind, so these test the categories, not the listed phrases."""

import tomllib
from pathlib import Path

import pytest

from cnlmc import api

EVERYDAY = Path(__file__).with_name("everyday.toml")

COLOUR_BEFORE_MATERIAL = [
    ("espresso leather", "leather", "espresso"),
    ("dark chocolate leather", "leather", None),
    ("ebony plastic", "plastic", "ebony"),
    ("toffee suede", "suede", "toffee"),
    ("latte linen", "linen", "latte"),
    ("graphite wool", "wool", "graphite"),
    ("walnut paint", "paint", "walnut"),
    ("honey velvet", "velvet", "honey"),
    ("brick linen", "linen", "brick"),
    ("cobalt velvet", "velvet", "cobalt"),
    ("granite grey leather", "leather", "granite grey"),
    ("onyx suede", "suede", "onyx"),
    ("pewter velvet", "velvet", "pewter"),
    ("greige paint", "paint", "greige"),
    ("cream suede", "suede", "cream"),  # a translucent medium (#19) and still a colour before a material
    ("leaf plastic", "plastic", "leaf"),
]

OTHER_PHRASES = [
    "cotton canvas", "wool tweed", "polyester fleece", "pine plywood", "jeans", "khakis", "grey hoodie",
    "white t-shirt", "wool hoodie", "tempered glass", "safety glass", "laminated glass", "wired glass",
    "low-e glass", "reeded glass", "knitted wool", "hand-knitted cashmere", "woven cotton", "stretch denim",
    "expanded metal", "beadboard", "glulam", "glossy magenta", "glossy beige", "shiny navy", "pale sage",
    "lightly frosted", "please polished copper", "polished copper please", "I'd like polished copper",
]  # fmt: skip


def compiled(text, lexicon=None):
    return api.compile_source(text, "<test>", lexicon or api.lexicon_for([]))


def material(text):
    result = compiled(text)
    assert result.ok, [d.message for d in result.diagnostics]
    return result.materials[0]


def notes(text):
    return [d.message for d in compiled(text).diagnostics if d.severity.value == "note"]


def luminance(rgb):
    return 0.2126 * rgb[0] + 0.7152 * rgb[1] + 0.0722 * rgb[2]


def test_the_phrases_here_are_not_in_the_everyday_set():
    data = tomllib.loads(EVERYDAY.read_text("utf-8"))
    listed = {row["text"].lower() for row in data["phrase"]}
    mine = {p for p, _n, _c in COLOUR_BEFORE_MATERIAL} | set(OTHER_PHRASES)
    assert not listed & mine


@pytest.mark.parametrize(("text", "noun", "colour"), COLOUR_BEFORE_MATERIAL)
def test_a_food_or_wood_word_before_a_material_is_its_colour(text, noun, colour):
    plain, coloured = material(noun), material(text)
    assert coloured["params"]["base_color"] != plain["params"]["base_color"]
    assert coloured["model"] == plain["model"]  # still the material, not 'a second material'


def test_espresso_is_darker_than_latte():
    dark, light = material("espresso leather"), material("latte leather")
    assert luminance(dark["params"]["base_color"]) < luminance(light["params"]["base_color"])


def test_a_wood_alone_or_before_its_class_stays_the_wood():
    assert material("walnut")["model"]["base"] == "dielectric"
    assert material("ebony")["params"]["base_color"] == material("ebony wood")["params"]["base_color"]


@pytest.mark.parametrize(
    ("text", "head"),
    [("cotton canvas", "canvas"), ("wool tweed", "tweed"), ("polyester fleece", "fleece"), ("pine plywood", "plywood")],
)
def test_a_fibre_or_species_before_a_noun_of_its_class_is_the_second_noun(text, head):
    assert material(text)["params"] == material(head)["params"]
    assert any("made of" in n for n in notes(text))


@pytest.mark.parametrize("text", ["steel aluminum", "marble granite"])
def test_two_metals_or_two_stones_stay_two_materials(text):
    assert not compiled(text).ok


@pytest.mark.parametrize(
    ("text", "fabric"),
    [("jeans", "denim"), ("khakis", "twill"), ("grey hoodie", "grey fleece"), ("white t-shirt", "white jersey")],
)
def test_a_garment_reads_as_the_fabric_it_is_made_of(text, fabric):
    assert material(text)["params"] == material(fabric)["params"]
    assert any("usual material" in n for n in notes(text))


def test_a_fabric_before_a_garment_is_that_fabric():
    assert material("wool hoodie")["params"] == material("wool")["params"]


@pytest.mark.parametrize("text", ["tempered glass", "safety glass", "laminated glass", "wired glass", "low-e glass"])
def test_a_glass_process_that_does_not_change_the_look_reads_as_glass_with_no_warning(text):
    result = compiled(text)
    assert result.ok
    assert not [d for d in result.diagnostics if d.severity.value == "warning"]
    assert result.materials[0]["params"] == material("glass")["params"]


def test_patterned_glass_is_rougher_than_clear_and_smoother_than_frosted():
    rough = [material(t)["params"]["roughness"] for t in ("glass", "reeded glass", "frosted glass")]
    assert rough == sorted(rough) and len(set(rough)) == 3


@pytest.mark.parametrize("text", ["knitted wool", "hand-knitted cashmere", "woven cotton", "stretch denim"])
def test_a_fabric_construction_keeps_the_fabric(text):
    noun = text.split()[-1]
    assert material(text)["params"] == material(noun)["params"]


@pytest.mark.parametrize(("text", "noun"), [("expanded metal", "zinc"), ("beadboard", "pine"), ("glulam", "spruce")])
def test_a_building_product_alone_is_its_usual_material(text, noun):
    assert material(text)["params"] == material(noun)["params"]


@pytest.mark.parametrize(
    "text", ["glossy magenta", "glossy beige", "shiny navy", "pale sage"]
)  # cream is a material too (#19)
def test_a_phrase_with_no_noun_is_read_on_an_everyday_noun_not_a_noun_that_starts_with_its_colour(text):
    result = compiled(text)
    assert result.ok
    (note,) = [d for d in result.diagnostics if "no material named" in d.message]
    assert note.message == f"no material named: read '{text}' as '{text} paint'"
    assert note.hints == (f"name the material to choose another: '{text} plastic', '{text} leather'",)
    assert result.materials[0]["params"] == compiled(f"{text} paint").materials[0]["params"]


def test_the_everyday_nouns_offered_fit_the_describing_words():
    result = compiled("lightly frosted")
    (note,) = [d for d in result.diagnostics if d.message.startswith("no material named")]
    assert note.message == "no material named: read 'lightly frosted' as 'lightly frosted glass'"
    assert not [p for p in note.hints[0].split("'")[1::2] if p.endswith(("paint", "leather", "fabric"))]


@pytest.mark.parametrize(
    "text",
    [
        "please polished copper",
        "polished copper please",
        "polished copper, thank you",
        "I'd like polished copper",
        "make it polished copper",
        "something like polished copper",
        "Hi, I want polished copper, thanks",
        "Hello! could you do polished copper",
        "polished copper would be nice",
    ],
)
def test_politeness_at_the_edges_is_read_past_with_a_note(text):
    result = compiled(text)
    assert result.ok, [d.message for d in result.diagnostics]
    assert result.materials[0]["params"] == material("polished copper")["params"]
    assert any(n.startswith("read past") for n in notes(text))
    assert not [d for d in result.diagnostics if d.severity.value == "warning"]


def test_a_courtesy_word_inside_a_phrase_is_read_past_with_a_note():
    """'please' carries no meaning wherever it stands (teaching.toml [politeness] anywhere); a phrase
    of courtesy ('thank you') inside a line is still an unknown word."""
    result = compiled("polished please copper")
    assert not [d for d in result.diagnostics if d.is_error]
    assert "read past 'please': a phrase names the material only, so politeness is left out" in [
        d.message for d in result.diagnostics
    ]
    assert "E001" in [d.code for d in compiled("polished thank you copper").diagnostics if d.is_error]


def test_politeness_alone_is_still_an_error():
    """'thanks' alone approves a material there is not: E003 (cnlmc.kept, cnlmc.analyze)."""
    codes = [d.code for d in compiled("thanks").diagnostics if d.is_error]
    assert codes == ["E003"]


@pytest.mark.parametrize(("text", "noun"), [("solid walnut", "walnut"), ("exposed brick", "brick")])
def test_solid_and_exposed_say_the_material_is_itself(text, noun):
    result = compiled(text)
    assert result.ok and not [d for d in result.diagnostics if d.severity.value == "warning"]
    assert result.materials[0]["params"] == material(noun)["params"]


def test_a_hide_word_before_leather_is_that_leather():
    assert material("lambskin leather")["params"] == material("nappa leather")["params"]


def test_a_wool_coat_is_wool_and_a_clear_coat_is_still_a_coat():
    assert material("camel wool coat")["params"]["base_color"] == material("camel wool")["params"]["base_color"]
    assert material("walnut with a clear coat")["model"]["coat"] is True


def test_petrol_blue_is_one_colour():
    result = compiled("petrol blue linen")
    assert result.ok and not [d for d in result.diagnostics if d.severity.value == "warning"]


@pytest.mark.parametrize(("text", "noun"), [("basket", "rattan"), ("teapot", "porcelain"), ("lampshade", "linen")])
def test_a_household_thing_alone_is_its_usual_material(text, noun):
    assert material(text)["params"] == material(noun)["params"]


@pytest.mark.parametrize("colour", ["blue", "green", "brown"])
def test_metallic_before_a_colour_is_the_flakes_and_the_colour(colour):
    """The survey's 'metallic blue' is a swatch; before a paint a person means blue paint with
    metallic flakes (colour_rules.toml describing_first)."""
    said = material(f"metallic {colour} car paint")
    assert said["params"]["flake_density"] > 0
    assert said["params"]["base_color"] == material(f"{colour} metallic car paint")["params"]["base_color"]
