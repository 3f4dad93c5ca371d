"""Words people type around a material (issue #14, session 28's held-out phrasing): smileys, a
name before a colon with a clause, what it is without, fillers after a comma, a treatment 'on' a
material, a place 'of' a thing, a coating named alone, everyday objects, a colour said before a
finish word with a coat word after it, a metal's name with '-ish'.

Phrases here are deliberately not the ones of tests/language/everyday.toml.
"""

import pytest

from .conftest import first


def look(material):
    return material["model"], material["params"], material.get("maps")


def warnings(result):
    return [d.code for d in result.diagnostics if d.severity.value != "note"]


@pytest.mark.parametrize(
    "said,plain",
    [
        ("walnut veneer :)", "walnut veneer"),
        ("satin brass ;-)", "satin brass"),
        ("polished concrete :D", "polished concrete"),
        ("cork xD", "cork"),
        ("red velvet <3", "red velvet"),
        ("green glass 👍", "green glass"),
    ],
)
def test_a_smiley_at_the_end_is_dropped(compile_text, said, plain):
    result = compile_text(said)
    assert result.ok and not warnings(result), [d.message for d in result.diagnostics]
    assert look(first(result)) == look(first(compile_text(plain)))


def test_a_smiley_alone_is_still_an_error(compile_text):
    assert not compile_text(":)").ok


def test_a_material_named_before_a_colon_goes_before_the_clause(compile_text):
    got = compile_text("terrazzo: grey w/ white chips")
    assert got.ok
    assert look(first(got)) == look(first(compile_text("grey terrazzo with white chips")))
    assert any("'grey terrazzo w/ white chips'" in d.message for d in got.diagnostics)


@pytest.mark.parametrize(
    "said,plain",
    [
        ("polished brass without any scratches", "polished brass"),
        ("walnut with no knots", "walnut"),
        ("chrome free of scratches", "chrome"),
        ("brass, with no scratches", "brass"),
    ],
)
def test_what_a_first_line_says_it_is_without_is_a_note(compile_text, said, plain):
    result = compile_text(said)
    assert result.ok and not warnings(result), [d.message for d in result.diagnostics]
    assert first(result)["params"] == first(compile_text(plain))["params"]
    assert any("none to take off" in d.message for d in result.diagnostics)


def test_without_takes_off_what_the_material_has(compile_text):
    got = first(compile_text("black granite without speckles"))
    assert got["params"] != first(compile_text("black granite"))["params"] or got.get("maps") != first(
        compile_text("black granite")
    ).get("maps")


def test_a_change_line_still_warns_of_what_is_not_there(compile_text):
    assert "W106" in warnings(compile_text("chrome\nless grain"))


def test_a_colour_before_a_finish_word_goes_with_the_coat_word_wherever_it_stands(compile_text):
    for one, other in (
        ("black glossy lacquered birch plywood", "glossy black lacquered birch plywood"),
        ("green brushed anodized aluminum", "brushed green anodized aluminum"),
    ):
        assert look(first(compile_text(one))) == look(first(compile_text(other))), one


@pytest.mark.parametrize(
    "said,model,transmissive",
    [
        ("frosted shower screen", "glass", True),
        ("rusty spade", "conductor", False),
        ("terracotta plant pot", "dielectric", False),
        ("upright piano", "dielectric", False),
        ("chrome towel rail", "conductor", False),
    ],
)
def test_everyday_objects_name_their_material(compile_text, said, model, transmissive):
    result = compile_text(said)
    assert result.ok, [d.message for d in result.diagnostics]
    assert first(result)["model"]["base"] == model
    assert (first(result)["model"]["base"] == "glass") is transmissive


def test_a_piano_alone_is_dark_and_glossy(compile_text):
    piano = first(compile_text("baby grand"))
    assert max(piano["params"]["base_color"]) < 0.05 and piano["params"]["roughness"] < 0.1


def test_a_place_of_a_thing_after_the_material_is_read_past(compile_text):
    got = compile_text("the satin nickel of an old tap")
    assert got.ok and look(first(got)) == look(first(compile_text("satin nickel")))


def test_a_coating_named_alone_is_on_steel_and_a_finish_alone_stays_paint(compile_text):
    coating = first(compile_text("matte grey coating"))
    assert coating["model"]["base"] == "conductor" and coating["model"]["coat"]
    assert first(compile_text("satin finish"))["model"]["base"] == "dielectric"


def test_fillers_and_an_article_after_a_comma_are_read_past(compile_text):
    got = compile_text("not shiny, just a plain white plastic")
    assert got.ok and not warnings(got)
    assert look(first(got)) == look(first(compile_text("not shiny, plain white plastic")))


def test_a_treatment_on_a_material_is_that_treatment(compile_text):
    got = compile_text("wax on pine")
    assert got.ok
    assert look(first(compile_text("oil on walnut"))) == look(first(compile_text("oiled walnut")))


def test_a_metal_ish_alone_is_that_metal(compile_text):
    got = first(compile_text("bronze-ish"))
    assert got["model"]["base"] == "conductor"
    assert got["params"]["f0"] == first(compile_text("bronze"))["params"]["f0"]


@pytest.mark.parametrize(
    "said,plain",
    [
        ("uh so like satin nickel you know", "satin nickel"),
        ("white, um, off-white linen", "off-white linen"),
        ("its like uh rough slate I guess", "rough slate"),
    ],
)
def test_fillers_of_speech_anywhere_are_read_past(compile_text, said, plain):
    result = compile_text(said)
    assert result.ok, [d.message for d in result.diagnostics]
    assert first(result)["params"]["base_color"] == first(compile_text(plain))["params"]["base_color"]
    assert any("words of speech" in d.message for d in result.diagnostics)


def test_a_bare_like_before_a_material_keeps_its_error(compile_text):
    assert not compile_text("steel, like brass").ok


@pytest.mark.parametrize("stone", ["blue pearl granite", "ubatuba", "black galaxy granite", "kashmir white granite"])
def test_granites_by_trade_name_are_speckled_stone(compile_text, stone):
    material = first(compile_text(stone))
    assert material["model"]["base"] == "dielectric" and material["maps"]["base_color"]["graph"] == "granite"


def test_blue_pearl_is_a_dark_blue_grey_and_kashmir_white_a_pale_one(compile_text):
    blue = first(compile_text("Blue Pearl granite"))["params"]["base_color"]
    white = first(compile_text("kashmir white granite"))["params"]["base_color"]
    assert max(blue) < 0.1 and blue[2] > blue[0] and min(white) > 0.5


def test_a_material_it_is_not_is_read_past(compile_text):
    got = compile_text("a satin brass knob, not gold")
    assert got.ok and not warnings(got)
    assert look(first(got)) == look(first(compile_text("satin brass knob")))
    assert [d.code for d in compile_text("walnut, not oak").diagnostics] == ["N101"]


def test_a_likeness_said_with_as_as_is_the_degree(compile_text):
    got = compile_text("as smooth as glass")
    assert got.ok and first(got)["params"]["roughness"] < first(compile_text("smooth paint"))["params"]["roughness"]
    assert (
        first(compile_text("slate, as rough as a rock"))["params"] == first(compile_text("very rough slate"))["params"]
    )


def test_a_look_stays_when_its_material_is_named_by_a_thing(compile_text):
    got = first(compile_text("ash effect vinyl flooring"))
    assert got["maps"]["base_color"]["graph"] == "wood"
    assert got["params"]["base_color"] == first(compile_text("ash effect vinyl"))["params"]["base_color"]


@pytest.mark.parametrize(
    "said,noun",
    [
        ("green oak frame", "white oak"),
        ("navy suede brogues", "suede"),
        ("gunmetal grey alloys", "aluminum"),
        ("grey lambswool", "wool"),
    ],
)
def test_trade_and_shop_words_name_their_material(compile_text, said, noun):
    result = compile_text(said)
    assert result.ok, [d.message for d in result.diagnostics]
    assert any(noun in d.message for d in result.diagnostics) or first(result)["name"].endswith(noun.replace(" ", "_"))


def test_a_comparison_for_a_thing_lands_on_paint(compile_text):
    got = compile_text("a shinier red for the door")
    assert got.ok and not warnings(got), [d.message for d in got.diagnostics]
    assert first(got)["params"] == first(compile_text("a shinier red"))["params"]
    assert not compile_text("brass on the walnut").ok  # a second material, not a place
