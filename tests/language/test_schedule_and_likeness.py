"""Specification and dictation phrasing (issue #14, categories of held-out sets 42 and 43): a
finish schedule's code names the material, a specification's tail is read past, and a likeness
said without a comma ('like its been stained', German 'wie im Hotelbad') is read past."""

from __future__ import annotations

import pytest

from cnlmc.api import compile_source, lexicon_for
from tests.language.meaning import compiled, lch, material, refined, same_look


@pytest.mark.parametrize(
    "said, code, phrase",
    [
        ("PT-02 matt emulsion, off-white", "PT-02", "matt emulsion, off-white"),
        ("FIN-07 jet black satin", "FIN-07", "jet black satin"),
        ("MT-02 polished chrome", "MT-02", "polished chrome"),
    ],
)
def test_a_schedule_code_first_names_the_material(said, code, phrase):
    named = material(said)
    assert named["label"] == code and named["phrase"] == phrase
    assert same_look(named, material(f"{code}: {phrase}"))
    assert any("schedule code" in d.message for d in compiled(said).diagnostics)


def test_a_known_word_first_is_no_code():
    assert "label" not in material("oak")  # no digits: never a code
    assert compiled("PT-02").ir["materials"] == []  # a code alone names nothing


@pytest.mark.parametrize(
    "said, meant",
    [
        ("travertine, tumbled, to match sample", "tumbled travertine"),
        ("dark wood, walnut or similar", "dark wood, walnut"),
    ],
)
def test_a_specifications_tail_is_read_past(said, meant):
    assert same_look(material(said), material(meant))


@pytest.mark.parametrize(
    "first, line, meant",
    [
        ("pine boards", "darker like its been stained", "darker"),
        ("shiny gold", "duller like its old", "duller"),
        ("brown leather", "make it shinier like its been polished", "shinier"),
    ],
)
def test_a_likeness_said_without_its_apostrophe_is_read_past(first, line, meant):
    assert same_look(refined(first, line).material, refined(first, meant).material)


@pytest.mark.parametrize(
    "said, meant",
    [
        ("Eiche hell wie unser Esstisch", "helle Eiche"),
        ("Edelstahl gebürstet wie beim Kühlschrank", "gebürsteter Edelstahl"),
        ("dunkelgrüner Samt wie Omas Sofa", "dunkelgrüner Samt"),
    ],
)
def test_german_likeness_is_read_past(said, meant):
    de = lexicon_for(["de"])
    got, want = (compile_source(t + "\n", "t.cnl", de) for t in (said, meant))
    assert got.ok and same_look(got.ir["materials"][0], want.ir["materials"][0])
    assert any("read past 'wie" in d.message for d in got.diagnostics)


def test_a_size_between_two_commas_takes_one_of_them():
    assert same_look(material("porcelain, 300x600, matt, grey"), material("matt grey porcelain"))
    assert same_look(material("Tile: porcelain, 300x600, matt, grey"), material("matt grey porcelain"))


@pytest.mark.parametrize(
    "said, meant",
    [
        ("black semi aniline leather", "black semi-aniline leather"),
        ("oxblood leather, aniline", "oxblood aniline leather"),
        ("glass - clear, low iron, 12mm", "low-iron clear glass"),
    ],
)
def test_trade_finish_words(said, meant):
    assert same_look(material(said), material(meant))


def test_aniline_leather_is_smoother_than_pigmented_leather_and_low_iron_glass_loses_its_tint():
    assert material("semi-aniline leather")["params"]["roughness"] < material("leather")["params"]["roughness"]
    clear = material("low-iron glass")["params"]["base_color"]
    float_glass = material("glass")["params"]["base_color"]
    assert max(clear) - min(clear) < max(float_glass) - min(float_glass)


@pytest.mark.parametrize(
    "said, meant",
    [
        ("copper darker than a penny", "darker copper"),
        ("concrete rougher than sandpaper", "rougher concrete"),
        ("brushed nickel less shiny than a normal faucet", "less shiny brushed nickel"),
        ("oak a bit lighter than my table", "a bit lighter oak"),
    ],
)
def test_a_material_compared_with_a_thing_is_one_step_that_way(said, meant):
    assert same_look(material(said), material(meant))
    result = compiled(said)
    assert result.ok and any("not measured against" in d.message for d in result.diagnostics)


@pytest.mark.parametrize(
    "said, meant",
    [
        ("brown swayed jacket", "brown suede jacket"),
        ("would floor", "wood floor"),
        ("shiny but also totally matte black paint", "shiny but totally matte black paint"),
    ],
)
def test_dictation_words(said, meant):
    assert same_look(material(said), material(meant))


def test_more_green_than_blue_moves_teal_toward_green():
    teal, greener = material("teal paint"), material("teal paint more green than blue")
    assert lch(greener["params"]["base_color"])[2] < lch(teal["params"]["base_color"])[2]  # hue angle toward green
