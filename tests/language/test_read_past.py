"""Nouns cnlmc does not know but English does, names said short, words spelt as heard, corrections
and second-language phrasing (issue #14, categories of held-out sets 48-54): cnlmc.read_past (W123),
the vowel reach of cnlmc.typos, cnlmc.corrections, teaching.toml [statements]."""

from __future__ import annotations

import pytest

from cnlmc.read_past import english_noun
from tests.language.meaning import compiled, material, reads_as, same_look


def _codes(result, severity: str) -> list[str]:
    return [d.code for d in result.diagnostics if d.severity.value == severity]


@pytest.mark.parametrize(
    "said, plain",
    [
        ("mirrored aviator lenses", "mirrored lenses"),
        ("wasteland scrap metal", "scrap metal"),
        ("galaxy black PLA", "black PLA"),
    ],
)
def test_an_english_noun_that_shows_nothing_is_read_past_with_a_warning_naming_it(said, plain):
    result = compiled(said)
    assert result.ok and _codes(result, "error") == []
    warned = [d for d in result.diagnostics if d.code == "W123"]
    assert len(warned) == 1 and "read past" in warned[0].message
    assert same_look(result.ir["materials"][0], material(plain))


@pytest.mark.parametrize(
    "said, why",
    [
        ("xyzzy oak", "no English word"),
        ("PETG", "no English word (a product name)"),
        ("heat staining on steel", "'heat' is a slip from lexicon words (hat, seat)"),
        ("springier foam", "a comparative is a change asked for"),
        ("gnarled yew", "an adjective likely says how it looks"),
        ("insufficiently polished steel", "an adverb changes the meaning"),
        ("lackluster oak", "an adjective: dull"),
        ("ghostly-white paint", "a hyphenated describing word"),
        ("glossy guitar", "the material would be implied, not named"),
        ("guitar", "nothing left to read"),
        ("zombie vampire werewolf oak", "three words read past are too many"),
        ("Eiche vergraut", "German reads no English words"),
    ],
)
def test_what_is_not_read_past_stays_an_error(said, why):
    lexicon = "de" if said.startswith("Eiche") else None
    from cnlmc.api import compile_source, lexicon_for

    result = compile_source(said, "t.cnl", lexicon_for([lexicon] if lexicon else []))
    assert not result.ok, why
    assert "E001" in _codes(result, "error") and "W123" not in _codes(result, "warning"), why


@pytest.mark.parametrize("word", ["aviator", "radiators", "galaxies", "wasteland", "blush"])
def test_english_nouns_and_their_plurals(word):
    assert english_noun(word)


@pytest.mark.parametrize("word", ["petg", "xyzzy", "worbla", "d2", "gnarled", "sickly", "patent", "mottled", "murky"])
def test_not_an_english_noun_alone(word):
    assert not english_noun(word)


@pytest.mark.parametrize(
    "short, whole",
    [
        ("black patent", "black patent leather"),
        ("barely tarnished sterling", "barely tarnished sterling silver"),
        ("patent shoes", "patent leather"),
        ("croc", "croc leather"),
    ],
)
def test_a_name_the_trade_says_short_is_its_material(short, whole):
    reads_as(short, whole)  # lexicon aliases: 'patent', 'sterling', 'croc'


@pytest.mark.parametrize("said", ["red plant", "steel, hot", "glossy black spring"])
def test_a_common_word_is_no_short_name(said):
    result = compiled(said)
    assert not any(m["model"]["base"] == "conductor" and "spring" in said for m in result.ir["materials"])
    assert not any("milk" in m.get("name", "") for m in result.ir["materials"])


@pytest.mark.parametrize(
    "said, meant", [("mahagony", "mahogany"), ("mahogony veneer", "mahogany veneer"), ("travertene", "travertine")]
)
def test_a_word_spelt_as_heard_is_read_as_the_word(said, meant):
    reads_as(said, meant, "slip of the keyboard")


@pytest.mark.parametrize(
    "said, meant",
    [("sterling siver", "sterling silver"), ("soft tuch black", "soft touch black"), ("spce grey", "space grey")],
)
def test_a_short_slip_inside_a_name_of_several_words_is_read_where_the_name_confirms_it(said, meant):
    reads_as(said, meant, "slip of the keyboard")


@pytest.mark.parametrize("said", ["blck steel", "shny paint"])
def test_a_short_slip_alone_stays_an_error(said):
    assert not compiled(said).ok


@pytest.mark.parametrize(
    "said, plain",
    [
        ("the knife is from steel", "steel"),
        ("a door from wood", "wood"),
        ("the handle is made with brass", "brass"),
        ("the floor is wood, the color is brown", "brown wood"),
    ],
)
def test_what_second_language_speakers_say_for_made_of(said, plain):
    reads_as(said, plain)


@pytest.mark.parametrize("said", ["m: more yellow than white plastic", "whit oak"])
def test_a_function_word_or_a_real_word_is_never_a_slip_inside_a_name(said):
    assert not any("slip of the keyboard" in d.message for d in compiled(said).diagnostics)


@pytest.mark.parametrize(
    "change, key, sign",
    [
        ("the colour should be lighter", "base_color", 1),
        ("the color must be more red", "base_color", 0),
        ("the finish must be more matte", "roughness", 1),
        ("make more shiny please", "roughness", -1),
        ("make darker", "base_color", -1),
    ],
)
def test_a_change_with_its_property_named_or_without_it_is_the_change(change, key, sign):
    from tests.language.meaning import refined

    before = material("oak")["params"][key]
    after = refined("oak", change).material["params"][key]
    assert after != before
    if sign and key == "roughness":
        assert (after - before) * sign > 0
    elif sign:
        assert (sum(after) - sum(before)) * sign > 0


@pytest.mark.parametrize(
    "said, plain",
    [
        ("the red chair is plastic", "red plastic"),
        ("the dark red sofa was velvet", "dark red velvet"),
        ("the big table was dark oak", "dark oak"),
        ("the old radio was bakelite", "bakelite"),
    ],
)
def test_a_statement_keeps_the_colour_said_of_the_thing(said, plain):
    reads_as(said, plain)


@pytest.mark.parametrize(
    "said, plain",
    [
        ("oak matt no wait satin", "satin oak"),
        ("red, sorry, blue velvet", "blue velvet"),
        ("brushed steel i mean brass", "brushed brass"),
    ],
)
def test_a_correction_said_mid_line_keeps_the_word_after_it(said, plain):
    reads_as(said, plain, "a correction")


def test_a_correction_said_first_on_a_change_line_is_read_past():
    from tests.language.meaning import refined

    plain = refined("grey linen", "a lot lighter").material
    corrected = refined("grey linen", "no actually a lot lighter").material
    assert corrected["params"] == plain["params"]


def test_a_correction_marker_between_words_of_different_kinds_drops_nothing():
    assert not any("a correction" in d.message for d in compiled("matt sorry oak").diagnostics)


@pytest.mark.parametrize("said", ["concrete with a satin sealer", "stone with a clear sealant"])
def test_a_sealer_is_a_clear_coat(said):
    assert material(said)["model"]["coat"]


@pytest.mark.parametrize("change, finer", [("a tighter weave", True), ("finer weave", True), ("a looser weave", False)])
def test_a_weave_said_tighter_or_looser_scales_the_pattern(change, finer):
    from tests.language.meaning import refined

    before = material("grey tweed")["maps"]["normal"]["params"].get("scale", 1.0)
    after = refined("grey tweed", change).material["maps"]["normal"]["params"]["scale"]
    assert (after > before) == finer and after != before


@pytest.mark.parametrize("said", ["the bottle has a cork", "the toy is made in China", "the table has four legs"])
def test_a_part_or_a_place_is_no_material_of_a_statement(said):
    assert not compiled(said).ok  # 'has' and 'made in' say no more what it is made of


@pytest.mark.parametrize("said, plain", [("the black chair is oak", "oak"), ("the green door is painted red", "red")])
def test_a_subject_colour_that_would_name_a_species_or_a_second_colour_is_left_out(said, plain):
    assert same_look(material(said), material(plain))


@pytest.mark.parametrize(
    "said, plain", [("dark sorry light oak", "light oak"), ("rusty sorry polished iron", "polished iron")]
)
def test_a_correction_is_read_before_any_word_is_read_past(said, plain):
    reads_as(said, plain, "a correction")
