"""A material printed with the look of another (issue #14): 'marble-effect laminate', 'wood-look
vinyl'. The material keeps its own model and gloss; it takes the look's colour (the nearest named
colour, unless the line names one) and the feature that draws the look's pattern (marble veins,
wood grain), each said in a note."""

import pytest


def material(result):
    assert result.ok, [d.message for d in result.diagnostics]
    return result.ir["materials"][-1]


@pytest.mark.parametrize("phrase,graph", [("marble-effect laminate", "marble"), ("oak-look vinyl", "wood")])
def test_a_look_draws_the_pattern_of_its_noun(compile_text, phrase, graph):
    result = compile_text(phrase)
    got = material(result)
    plain = material(compile_text(phrase.split()[-1]))
    assert got["maps"]["base_color"]["graph"] == graph
    assert got["model"] == plain["model"] and got["params"]["roughness"] == plain["params"]["roughness"]
    assert any("the look of" in d.message for d in result.diagnostics)


def test_a_colour_the_line_names_wins_over_the_looks(compile_text):
    got = material(compile_text("black marble-effect laminate"))  # black as marble's pattern carries it
    assert got["params"]["base_color"] == material(compile_text("black marble"))["params"]["base_color"]
    assert got["maps"]["base_color"]["graph"] == "marble"


def test_a_look_without_a_pattern_lends_its_colour(compile_text):
    got = material(compile_text("leather-look vinyl"))
    assert got["maps"] == {}
    assert got["params"]["base_color"] != material(compile_text("vinyl"))["params"]["base_color"]


@pytest.mark.parametrize(
    "phrase,graph", [("laminate with a marble effect", "marble"), ("vinyl with an oak look", "wood")]
)
def test_a_look_said_in_a_clause_draws_the_same(compile_text, phrase, graph):
    result = compile_text(phrase)
    got = material(result)
    assert got["maps"]["base_color"]["graph"] == graph
    noun = phrase.split()[3]
    assert got["params"]["base_color"] == material(compile_text(noun))["params"]["base_color"]
    assert any("the look of" in d.message for d in result.diagnostics)


def test_a_dark_named_colour_keeps_the_looks_pattern_visible(compile_text):
    """'black marble-effect laminate' draws pale veins on black, as 'black marble' does."""
    look = material(compile_text("black marble-effect laminate"))["maps"]["base_color"]["params"]
    plain = material(compile_text("black marble"))["maps"]["base_color"]["params"]
    assert look.get("color_amount", 0) > 0.5 and look.get("color_amount") == plain.get("color_amount")
