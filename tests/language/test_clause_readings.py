"""Lines whose material is said around other words (issue #14): a relative clause after the
material ('pine that has weathered over time'), describing words then a likeness that names the
material ('something pale, like ash'), a comparison's other side ('more like slate than
charcoal'), 'something' before describing words, an alloy grade before a metal ('316 stainless'),
a colour said with 'in' after laid tiles, and 'without any' as a negation.

The phrases are not the ones of the held-out sets: each category is tested on words of its own.
"""

import pytest


def material(result):
    assert result.ok, [d.message for d in result.diagnostics]
    return result.ir["materials"][-1]


@pytest.mark.parametrize(
    "phrase,same_as",
    [
        ("pine that has weathered over time", "weathered pine"),
        ("brass that's gone dull", "dull brass"),
        ("oak that has been limed", "limed oak"),
        ("walnut that has darkened with age", "darkened walnut"),
        ("marble which is polished", "polished marble"),
    ],
)
def test_a_relative_clause_describes_the_material_before_it(compile_text, phrase, same_as):
    result = compile_text(phrase)
    got, want = material(result), material(compile_text(same_as))
    assert (got["params"], got["maps"], got["model"]) == (want["params"], want["maps"], want["model"])
    assert any("describes it" in d.message for d in result.diagnostics)


@pytest.mark.parametrize(
    "phrase,same_as",
    [
        ("something pale, like ash", "pale ash"),
        ("something cool, like slate", "cool slate"),
        ("glossy, like a walnut", "glossy walnut"),
    ],
)
def test_describing_words_then_a_likeness_name_that_material(compile_text, phrase, same_as):
    got, want = material(compile_text(phrase)), material(compile_text(same_as))
    assert got["params"] == want["params"] and got["maps"] == want["maps"]


def test_a_likeness_after_a_material_is_still_read_past(compile_text):
    got = material(compile_text("copper, like an old kettle"))
    assert got["params"] == material(compile_text("copper"))["params"]


@pytest.mark.parametrize(
    "above,line,same_as",
    [
        (None, "more like slate than charcoal", "slate"),
        ("pale oak", "more like walnut than teak", "pale oak\nmore like walnut"),
    ],
)
def test_the_other_side_of_a_comparison_is_read_past(compile_text, above, line, same_as):
    text = f"{above}\n{line}" if above else line
    got, want = material(compile_text(text)), material(compile_text(same_as))
    assert got["params"] == want["params"]


@pytest.mark.parametrize(
    "phrase,same_as", [("something dark and matte", "dark matte paint"), ("something warm", "warm paint")]
)
def test_something_before_describing_words_is_read_past(compile_text, phrase, same_as):
    assert material(compile_text(phrase))["params"] == material(compile_text(same_as))["params"]


@pytest.mark.parametrize(
    "phrase,same_as", [("mirror-polished 316 stainless", "mirror-polished stainless"), ("7075 aluminium", "aluminium")]
)
def test_an_alloy_grade_before_a_metal_is_read_past(compile_text, phrase, same_as):
    result = compile_text(phrase)
    assert material(result)["params"] == material(compile_text(same_as))["params"]
    assert any("grade" in d.message for d in result.diagnostics)


def test_a_bare_number_elsewhere_keeps_its_error(compile_text):
    assert not compile_text("50 oak").ok


@pytest.mark.parametrize("phrase,colour", [("tiles in a pale blue", "pale blue"), ("subway tiles in sage", "sage")])
def test_laid_tiles_take_a_colour_said_with_in(compile_text, phrase, colour):
    got = material(compile_text(phrase))
    assert got["params"]["base_color"] == material(compile_text(f"{colour} tiles"))["params"]["base_color"]
    assert got["maps"], "the grout is still drawn"


@pytest.mark.parametrize("phrase", ["without any shine", "no shine whatsoever"])
def test_without_any_is_a_negation(compile_text, phrase):
    got = material(compile_text(phrase))
    assert got["params"]["roughness"] > material(compile_text("paint"))["params"]["roughness"]


@pytest.mark.parametrize(
    "phrase,same_as",
    [
        ("walnut, a bit darker", "a bit darker walnut"),
        ("red plastic, slightly glossier", "slightly glossier red plastic"),
        ("oak, a bit darker, much glossier", "oak\\na bit darker\\nmuch glossier"),
        ("sage green, maybe a touch lighter", "sage green paint\\na touch lighter"),
    ],
)
def test_a_material_then_comparative_parts_is_moved_by_them(compile_text, phrase, same_as):
    got, want = material(compile_text(phrase)), material(compile_text(same_as.replace("\\n", "\n")))
    assert got["params"] == want["params"] and got["maps"] == want["maps"]


def test_a_colour_code_says_to_name_the_colour(compile_text):
    result = compile_text("powder-coated aluminium, RAL 7016")
    assert not result.ok
    first = next(d for d in result.diagnostics if d.is_error)
    assert first.code == "E001" and "colour code" in first.message and first.span.col == 26


@pytest.mark.parametrize(
    "phrase,same_as", [("a soft putty colour", "soft putty paint"), ("a warm grey colour", "warm grey paint")]
)
def test_colour_after_a_colour_is_read_past(compile_text, phrase, same_as):
    result = compile_text(phrase)
    assert material(result)["params"] == material(compile_text(same_as))["params"]
    assert any("colour" in d.message for d in result.diagnostics)  # read past, or read with its colour


def test_more_colour_keeps_its_meaning(compile_text):
    plain = material(compile_text("terracotta paint"))
    more = material(compile_text("terracotta paint\nmore colour"))
    assert more["params"]["base_color"] != plain["params"]["base_color"]


@pytest.mark.parametrize(
    "phrase",
    ["paint, like navy", "oak, like walnut", "white paint in flat", "honest oak", "1950 oak"],
)
def test_readings_that_must_not_swallow_words(compile_text, phrase):
    """A bare 'like' after a material, a place word without its article, '-est' on a word that only
    ends so, a number before a non-metal: each stays an error rather than being read past (review of session
    14; a colour step after a comma, 'walnut, more red', reads as the change line since session 24:
    tests/language/test_notes_phrasing.py; an unknown noun of English is read past with a warning
    since session 25, an adjective such as 'honest' is not: tests/language/test_read_past.py)."""
    assert not compile_text(phrase).ok


def test_a_relative_clause_after_an_article(compile_text):
    result = compile_text("a brass that has gone dull")
    assert material(result)["params"] == material(compile_text("dull brass"))["params"]
    assert not any("'that' as the material above" in d.message for d in result.diagnostics)


@pytest.mark.parametrize(
    "phrase,same_as",
    [
        ("oak painted white", "white painted oak"),
        ("steel powder-coated in black", "black powder-coated steel"),
        ("the door painted sage green", "sage green painted door"),
    ],
)
def test_a_colour_after_a_describing_word_after_the_material(compile_text, phrase, same_as):
    result = compile_text(phrase)
    assert material(result)["params"] == material(compile_text(same_as))["params"]
    assert any("the colour after the describing word" in d.message for d in result.diagnostics)


@pytest.mark.parametrize(
    "phrase,same_as",
    [
        ("paint with no gloss", "matte paint"),
        ("plastic with no shine", "dull plastic"),
        ("paint without any gloss", "matte paint"),
    ],
)
def test_a_negated_word_after_the_material_describes_it(compile_text, phrase, same_as):
    assert material(compile_text(phrase))["params"] == material(compile_text(same_as))["params"]


def test_a_plain_describing_word_after_the_material_keeps_its_error(compile_text):
    """Without a comma it is read as before the noun (tests/language/test_noun_first.py); an adverb
    left with nothing to modify keeps the error."""
    result = compile_text("aluminum lightly")
    assert not result.ok and any("comes after the noun" in d.message for d in result.diagnostics)


@pytest.mark.parametrize(
    "phrase,same_as",
    [
        ("a matte white stoneware glaze", "stoneware with a matte white glaze"),
        ("glossy oak varnish", "oak with a glossy varnish"),
    ],
)
def test_a_clause_word_after_the_material_takes_the_describing_words(compile_text, phrase, same_as):
    got, want = material(compile_text(phrase)), material(compile_text(same_as))
    assert (got["params"], got["maps"]) == (want["params"], want["maps"])


def test_a_matte_glaze_is_glazed_then_matte(compile_text):
    matte = material(compile_text("stoneware with a matte glaze"))["params"]["roughness"]
    glazed = material(compile_text("stoneware with a glaze"))["params"]["roughness"]
    assert matte > glazed


@pytest.mark.parametrize("phrase,same_as", [("oak kitchen", "oak"), ("brass trim", "brass")])
def test_a_use_after_the_material_is_its_object(compile_text, phrase, same_as):
    assert material(compile_text(phrase))["params"] == material(compile_text(same_as))["params"]
