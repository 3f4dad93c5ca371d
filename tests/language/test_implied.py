"""Describing words alone (cnlmc.implied): a line that only describes names its material by the
first phrase the teaching offers ('matte black' = matte black paint), with a note; a line that
starts with a change phrase ('make it blue', 'turn it green') changes the material above; 'add'
starts a clause line ('add some scratches'). The phrases here are not in tests/language/everyday.toml."""

from __future__ import annotations

import tomllib
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from cnlmc.api import compile_source, lexicon_for
from tests.helpers import run_cnlmc

LEX = lexicon_for()
PHRASES = [
    "glossy teal",
    "very pale lavender",
    "satin charcoal",
    "turn it teal",
    "paint it lavender",
    "add fine scratches",
]


def compiled(text: str):
    return compile_source(text, "t.cnl", LEX)


def notes(result) -> list[str]:
    return [d.message for d in result.diagnostics if d.severity.name == "NOTE"]


def params(text: str) -> list[dict]:
    result = compiled(text)
    assert result.ok, [d.message for d in result.diagnostics]
    return [m["params"] for m in result.materials]


def test_the_phrases_here_are_not_in_the_everyday_set():
    data = tomllib.loads(Path(__file__).with_name("everyday.toml").read_text("utf-8"))
    assert not {row["text"].lower() for row in data["phrase"]} & {p.lower() for p in PHRASES}


@pytest.mark.parametrize(
    ("text", "reading"),
    [
        ("glossy teal", "glossy teal paint"),
        ("very pale lavender", "very pale lavender paint"),
        ("satin charcoal", None),
    ],
)
def test_describing_words_alone_are_the_first_offer_with_a_note(text, reading):
    result = compiled(text)
    assert result.ok
    said = [n for n in notes(result) if n.startswith("no material named")]
    if reading is None:  # 'charcoal' is a material too: the line names it
        assert not said
        return
    assert said == [f"no material named: read '{text}' as '{reading}'"]
    assert params(text) == params(reading)


def test_the_implied_material_keeps_the_words_in_its_name_and_phrase():
    (material,) = compiled("glossy teal").materials
    assert material["phrase"] == "glossy teal"
    assert material["name"].startswith("glossy_teal")


def test_a_change_line_applies_its_words_to_the_material_above():
    (before,) = params("red leather")
    (after,) = params("red leather\nturn it teal")
    (teal,) = params("teal leather")
    assert after["base_color"] == teal["base_color"] != before["base_color"]
    result = compiled("red leather\npaint it lavender")
    assert "read 'lavender' as a change of the material above: its words apply to it" in notes(result)
    assert not [d for d in result.diagnostics if d.code == "W105"]  # a change, not a second colour
    assert len(result.materials) == 1


def test_a_change_line_of_gloss_words_moves_the_roughness():
    (matte,) = params("matte red plastic")
    (changed,) = params("matte red plastic\nmake it glossy")
    assert changed["roughness"] < matte["roughness"]


def test_a_change_line_alone_is_its_words_alone():
    result = compiled("turn it teal")  # no material above: teal, its material implied
    assert [m["params"] for m in result.materials] == [m["params"] for m in compiled("teal").materials]
    assert not [d.code for d in result.diagnostics if d.severity.name == "WARNING"]
    result = compiled("turn it darker")  # nothing to change
    assert not result.materials
    assert [d.code for d in result.diagnostics if d.severity.name == "WARNING"] == ["W104"]


def test_add_starts_a_clause_line():
    plain = compiled("polished steel").materials[0]
    added = compiled("polished steel\nadd fine scratches").materials[0]
    assert added["maps"] != plain["maps"]
    assert added["maps"] == compiled("polished steel\nwith fine scratches").materials[0]["maps"]


def test_a_second_colour_in_one_phrase_still_warns():
    result = compiled("red blue leather")
    assert [d.code for d in result.diagnostics if d.code == "W105"] == ["W105"]


COLOURS = ["teal", "lavender", "navy", "mint", "rose", "maroon", "ochre", "periwinkle"]
FINISHES = ["", "glossy ", "matte ", "shiny ", "very glossy ", "slightly matte "]  # not "satin": a fabric too


@settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(st.sampled_from(FINISHES), st.sampled_from(COLOURS))
def test_any_finish_and_colour_alone_compiles_as_paint_without_a_warning(finish, colour):
    text = f"{finish}{colour}"
    result = compiled(text)
    assert result.ok and not [d for d in result.diagnostics if d.severity.name in ("WARNING", "ERROR")]
    assert result.materials[0]["params"] == compiled(f"{text} paint").materials[0]["params"]


def test_through_the_cli():
    done = run_cnlmc("compile", "-", "--target", "ir", "-o", "-", stdin="glossy teal\nmake it darker\n")
    assert done.returncode == 0, done.stderr
    assert "note[N101]: no material named: read 'glossy teal' as 'glossy teal paint'" in done.stderr


# ---------------------------------------------------------------- conversational change lines

CONVERSATION = ["walnut\ndial down the gloss", "bronze\ngive it a patina", "white ceramic\nok now make it teal"]


def test_the_conversation_here_is_not_in_the_everyday_set():
    data = tomllib.loads(Path(__file__).with_name("everyday.toml").read_text("utf-8"))
    said = {line.lower() for text in CONVERSATION for line in text.split("\n")[1:]}
    assert not {row["text"].lower() for row in data["phrase"]} & said


def test_a_rewritten_opening_is_the_word_it_stands_for():
    (walnut,) = params("walnut")
    (duller,) = params("walnut\ndial down the gloss")
    assert duller["roughness"] > walnut["roughness"]
    result = compiled("bronze\ngive it a patina")
    assert "read 'give it' as 'with'" in notes(result)
    assert result.materials[0]["maps"] == compiled("bronze\nwith a patina").materials[0]["maps"] != {}


def test_politeness_before_a_change_phrase_keeps_it_a_change():
    result = compiled("white ceramic\nok now make it teal")
    assert len(result.materials) == 1
    assert result.materials[0]["params"]["base_color"] == params("teal ceramic")[0]["base_color"]


def test_a_change_does_not_contradict_the_words_of_the_line_above():
    result = compiled("glossy teal plastic\ngo matte")
    assert not [d for d in result.diagnostics if d.code == "W101"]
    assert result.materials[0]["params"]["roughness"] > params("glossy teal plastic")[0]["roughness"]


def test_german_politeness_before_a_refinement():
    de = lexicon_for(("de",))
    result = compile_source("grauer Granit\nbitte heller", "t.cnl", de)
    plain = compile_source("grauer Granit", "t.cnl", de)
    assert result.ok
    lighter, grey = result.materials[0]["params"]["base_color"], plain.materials[0]["params"]["base_color"]
    assert sum(lighter) > sum(grey)


@pytest.mark.parametrize(
    ("text", "plain"),
    [("a slightly paler teal", "teal paint"), ("a much darker lavender", "lavender paint")],
)
def test_an_inline_comparative_before_a_colour_alone_implies_the_material_too(text, plain):
    result = compiled(text)
    assert result.ok
    assert [n for n in notes(result) if n.startswith("no material named")] == [
        f"no material named: read '{text}' as '{text} paint' (a comparison as the first line)"
    ]
    assert result.materials[0]["params"] == compiled(f"{text} paint").materials[0]["params"]
    assert result.materials[0]["params"] != compiled(plain).materials[0]["params"]


def test_a_comparison_with_nothing_compared_keeps_its_error():
    result = compiled("paler than")
    assert not result.ok and [d.code for d in result.diagnostics if d.is_error] == ["E003"]


def test_a_comparison_with_a_colour_is_that_colour_a_step_further():
    """'paler than teal' (session 14): a paler teal, on the everyday noun, as 'paler teal'."""
    result = compiled("paler than teal")
    assert result.ok and result.materials[0]["params"] == compiled("paler teal").materials[0]["params"]


@pytest.mark.parametrize(("text", "reading"), [("zero shine", "dull"), ("no gloss", "matte")])
def test_no_and_zero_negate_and_a_gloss_word_alone_is_read_on_paint(text, reading):
    result = compiled(text)
    assert result.ok
    assert f"read '{text}' as '{reading}' (the declared opposite of " in " ".join(notes(result))
    assert [n for n in notes(result) if n.startswith("no material named")] == [
        f"no material named: read '{text}' as '{text} paint'"
    ]


def test_a_describing_word_then_a_pronoun_changes_the_material_above():
    (walnut,) = params("walnut")
    result = compiled("walnut\nsand it")  # 'sand' reads as sanded: the pronoun is the walnut
    assert "read 'it' as the material above" in notes(result)
    assert len(result.materials) == 1
    (frosted,) = params("clear acrylic\nfrost them")
    assert frosted["roughness"] > params("clear acrylic")[0]["roughness"]
    assert walnut != result.materials[0]["params"]


@pytest.mark.parametrize(
    ("text", "step_from"), [("paler teal", "teal paint"), ("a bit warmer lavender", "lavender paint")]
)
def test_a_first_line_comparison_of_a_colour_is_its_own_material(text, step_from):
    result = compiled(text)
    assert result.ok and len(result.materials) == 1
    assert [n for n in notes(result) if "first line" in n] == [
        f"no material named: read '{text}' as '{text} paint' (a comparison as the first line)"
    ]
    assert result.materials[0]["params"] == compiled(f"{text} paint").materials[0]["params"]
    assert result.materials[0]["params"] != compiled(step_from).materials[0]["params"]


def test_a_comparison_below_a_material_still_refines_it_and_one_with_nothing_to_compare_warns():
    assert len(compiled("red leather\npaler teal").materials) == 1
    result = compiled("glossier")
    assert not result.materials and [d.code for d in result.diagnostics] == ["W104"]


def test_a_first_line_comparison_compiles_the_same_in_two_workers():
    text = "paler teal\nglossier\n" + "red leather\npaler teal\n" * 700
    one = compile_source(text, "t.cnl", LEX, keep_stages=False)
    from cnlmc.api import compile_stream

    two = compile_stream(text, "t.cnl", LEX, workers=2)
    names = [m["name"] for m in two.materials]
    assert names == [m["name"] for m in one.materials] and len(names) == 701
    assert two.sorted_diagnostics() == one.diagnostics


@pytest.mark.parametrize("text", ["copper-plated", "silver plated", "Chrome Plated", "brass-clad"])
def test_a_plating_alone_is_on_its_examples_surface(text):
    result = compiled(text)
    assert result.ok
    written = " ".join(text.replace("-", " ").split())
    assert any(n == f"no material named: read '{written}' as '{written} steel'" for n in notes(result)), notes(result)
    assert result.materials[0]["params"] == compiled(f"{written} steel").materials[0]["params"]


def test_a_plating_word_after_a_noun_that_is_not_a_metal_keeps_its_warning():
    """'walnut plated' reads as 'plated walnut' (cnlmc.noun_first), which says plating is for metal."""
    assert "W102" in [d.code for d in compiled("walnut plated").diagnostics]


@pytest.mark.parametrize("text", ["satin navy", "terracotta red", "ivory white"])
def test_a_word_that_is_a_noun_and_a_colour_or_finish_then_colours_describes_paint(text):
    result = compiled(text)
    assert result.ok
    assert f"no material named: read '{text}' as '{text} paint'" in notes(result)
    assert len(result.materials) == 1 and result.materials[0]["model"]["base"] != "conductor"


def test_describing_words_with_a_colour_that_is_also_a_noun_describe_paint_after_a_negation():
    result = compiled("glossy, certainly not metallic, silver-grey")
    assert result.ok and len(result.materials) == 1
    assert result.materials[0]["model"]["base"] != "conductor"
    assert any(n.startswith("read 'silver grey' as the colour 'silver'") for n in notes(result))


def test_the_colour_compound_note_says_an_before_a_vowel():
    assert "read 'terracotta orange' as the colour 'terracotta' (an orange), not two colours" in notes(
        compiled("terracotta orange paint")
    )


def test_marbled_is_the_veins_feature_and_the_note_names_it_so():
    result = compiled("marbled white paper")
    assert result.ok
    assert "read 'marbled white paper' as 'white paper with veins' (a feature named before the material)" in notes(
        result
    )
    assert {ref["graph"] for ref in result.materials[0]["maps"].values()} == {"marble"}
