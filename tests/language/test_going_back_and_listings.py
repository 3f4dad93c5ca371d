"""Meaning of everyday lines (issue #14), categories from held-out phrasing (sets 27-28): going back
a bit on the change above ('go back a bit', 'too dark, go back a bit'), a degree said after the
change ('rougher, a little'), listings with their marks ('Walnut (dark), matte', 'glass... frosted',
'marble: white, honed', 'European walnut, book-matched', 'walnut, satin'), a limit said of a colour
('not too yellow'), wear asked for on a material that shows none ('more worn'), and chat words
('tbh', 'kinda want it')."""

from __future__ import annotations

import pytest

from tests.language.meaning import compiled, lch, material, refined, same_look


def codes(text: str) -> list[str]:
    return [d.code for d in compiled(text).diagnostics if d.severity.value in ("error", "warning")]


def notes(text: str) -> list[str]:
    return [d.message for d in compiled(text).diagnostics if d.severity.value == "note"]


def lightness(session_or_material) -> float:
    m = session_or_material if isinstance(session_or_material, dict) else session_or_material.material
    return lch(m["params"]["base_color"])[0]


def look(session) -> dict:
    """What a session's material looks like: its model, parameters and maps (not where words stood)."""
    m = session.material
    return {key: m[key] for key in ("model", "params", "maps")}


def map_params(m: dict) -> dict:
    return {role: dict(ref.get("params", {})) for role, ref in (m.get("maps") or {}).items()}


# ---------------------------------------------------------------- going back a bit


@pytest.mark.parametrize(
    "line", ["go back a bit", "hmm, back a little", "ok, take it back a touch", "go back a bit please"]
)
def test_going_back_reverses_the_change_above_partly(line):
    before = lightness(refined("oak"))
    darker = lightness(refined("oak", "darker"))
    back = lightness(refined("oak", "darker", line))
    assert darker < back < before


def test_going_back_is_the_opposite_at_the_lines_degree():
    assert look(refined("red plastic", "less orange", "go back a bit")) == look(
        refined("red plastic", "less orange", "a bit more orange")
    )
    assert look(refined("oak", "rougher", "go back")) == look(refined("oak", "rougher", "smoother"))


def test_going_back_twice_goes_back_twice_from_the_same_change():
    once = lightness(refined("oak", "darker", "go back a bit"))
    twice = lightness(refined("oak", "darker", "go back a bit", "go back a bit"))
    assert once < twice < lightness(refined("oak"))


def test_going_back_says_how_it_was_read():
    said = notes("oak\ndarker\ngo back a bit")
    assert any("'go back a bit' as 'a bit lighter'" in n for n in said)


@pytest.mark.parametrize(
    ("lines", "why"), [(("go back a bit",), "no change above"), (("make it blue", "go back"), "only comparatives")]
)
def test_nothing_to_go_back_from_changes_nothing_and_says_why(lines, why):
    text = "\n".join(("oak", *lines))
    assert not codes(text)
    assert any("nothing to go back from" in n and why in n for n in notes(text))
    assert same_look(material(text), material("\n".join(("oak", *lines[:-1]))))


def test_going_back_after_a_change_on_the_same_line_is_read_past():
    session = refined("light oak", "a touch darker", "hmm too dark, go back a bit")  # a complaint: said in a session
    assert look(session) == look(refined("light oak", "a touch darker", "too dark"))
    assert any("read past 'go back a bit'" in d.message for d in session.result.diagnostics)
    assert look(refined("oak", "darker, go back a bit")) == look(refined("oak", "darker"))


def test_going_back_alone_needs_a_material_above():
    assert codes("go back a bit") == ["W104"]


# ---------------------------------------------------------------- a degree after the change


@pytest.mark.parametrize(
    ("said", "meant"),
    [
        ("rougher, a little", "a little rougher"),
        ("rougher again, a little", "a little rougher"),
        ("darker, but only slightly", "slightly darker"),
        ("darker, much", "much darker"),
    ],
)
def test_a_degree_after_the_change_is_its_degree(said, meant):
    assert look(refined("oak", said)) == look(refined("oak", meant))


# ---------------------------------------------------------------- listings and their marks


@pytest.mark.parametrize(
    ("said", "meant"),
    [
        ("Walnut (dark), matte", "dark matte walnut"),
        ("walnut, dark,, matte", "dark matte walnut"),
        ("glass... frosted", "frosted glass"),
        ("gold!!! polished", "polished gold"),
        ("oak. matte.", "matte oak"),
        ("marble: white, honed", "white honed marble"),
        ("Concrete: raw grey", "raw grey concrete"),
        ("European walnut, book-matched", "walnut"),
        ("walnut; dark; satin", "dark satin walnut"),
        ("walnut, satin", "satin walnut"),
        ("black checkered tiles", "black tiles"),
    ],
)
def test_a_listing_means_what_its_words_say(said, meant):
    assert not codes(said)
    assert same_look(material(said), material(meant))


def test_a_name_that_is_no_material_still_needs_one():
    assert codes("m1: white, honed") == ["E003"]


def test_a_material_named_first_says_how_the_ambiguous_word_was_read():
    assert any("'satin' as describing the walnut" in n for n in notes("walnut, satin"))
    assert not any("describing the oak" in n for n in notes("oak, satin"))  # no colour 'oak': nothing to say


# ---------------------------------------------------------------- a limit said of a colour


@pytest.mark.parametrize(
    ("said", "meant"),
    [("cream paint, not too yellow", "cream paint"), ("oak, not too dark", "oak"), ("not too dark oak", "oak")],
)
def test_not_too_a_colour_is_a_limit_that_keeps_the_colour(said, meant):
    assert not codes(said)
    assert same_look(material(said), material(meant))
    assert any("a limit, not a change" in n for n in notes(said))


@pytest.mark.parametrize("said", ["not too yellow", "not at all rusty"])
def test_a_line_whose_words_are_all_read_past_is_no_material(said):
    assert codes(said) == ["E003"]


# ---------------------------------------------------------------- wear asked for where none shows


def test_more_wear_on_a_material_without_any_is_a_little_of_it():
    before = material("tan leather")
    after = look(refined("tan leather", "more worn"))
    assert map_params(after) != map_params(before)
    assert same_look(after, material("slightly worn tan leather"))


def test_less_wear_on_weathered_bronze_is_less_of_its_patina():
    coverage = map_params(material("weathered bronze"))["mask"]["coverage"]
    less = map_params(look(refined("weathered bronze", "a bit less worn")))["mask"]["coverage"]
    more = map_params(look(refined("weathered bronze", "more weathered")))["mask"]["coverage"]
    assert less < coverage < more


def test_a_made_treatment_must_still_be_part_of_the_material():
    assert codes("steel\nstronger brushing") == ["W104"]
    assert codes("red plastic\nless worn") == ["W104"]


# ---------------------------------------------------------------- chat words


@pytest.mark.parametrize(
    ("phrase", "said", "meant"),
    [
        ("terracotta", "less orange tbh", "less orange"),
        ("brass", "kinda want it brushed", "make it brushed"),
        ("frosted glass", "rougher again", "rougher"),
    ],
)
def test_chat_words_are_read_past(phrase, said, meant):
    assert look(refined(phrase, said)) == look(refined(phrase, meant))
