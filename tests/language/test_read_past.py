"""Words cnlmc does not know but English does, names said short, and words spelt as heard (issue
#14, categories of held-out sets 48-52): cnlmc.read_past (W123), WordFormation._clipped, the vowel
reach of cnlmc.typos."""

from __future__ import annotations

import pytest

from cnlmc.read_past import english
from tests.language.meaning import compiled, material, reads_as, same_look


def _codes(result, severity: str) -> list[str]:
    return [d.code for d in result.diagnostics if d.severity.value == severity]


@pytest.mark.parametrize(
    "said, plain",
    [
        ("a sickly chartreuse green paint", "chartreuse green paint"),
        ("a wizard's staff of gnarled yew", "yew"),
        ("moonlit marble", "marble"),
        ("honest oak", "oak"),
        ("mirrored aviator lenses", "mirrored lenses"),
    ],
)
def test_an_english_word_that_shows_nothing_is_read_past_with_a_warning_naming_it(said, plain):
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


@pytest.mark.parametrize("word", ["gnarled", "sides", "retaining", "chipped", "saddle-like", "moth-eaten", "sickly"])
def test_english_words_and_their_inflections(word):
    assert english(word)


@pytest.mark.parametrize("word", ["petg", "xyzzy", "worbla", "d2"])
def test_not_english(word):
    assert not english(word)


@pytest.mark.parametrize(
    "short, whole",
    [
        ("black patent", "black patent leather"),
        ("barely tarnished sterling", "barely tarnished sterling silver"),
        ("cherry red patent", "cherry red patent leather"),
        ("croc", "croc leather"),
    ],
)
def test_a_name_said_short_is_the_material_it_starts(short, whole):
    reads_as(short, whole, "said short")


@pytest.mark.parametrize("said", ["patent shoes", "oak kitchen", "medium grey"])
def test_a_name_is_said_short_only_where_the_noun_stands(said):
    assert not any("said short" in d.message for d in compiled(said).diagnostics)


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
        ("the table has a dark oak finish", "dark oak"),
        ("the floor is wood, the color is brown", "brown wood"),
    ],
)
def test_what_second_language_speakers_say_for_made_of_and_has(said, plain):
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
