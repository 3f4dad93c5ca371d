"""Errors that teach (#14): a 'did you mean' fits the word's slot, is a typo and never the word's
opposite; a known word in the wrong role says what it is and offers a phrase that compiles.

Every phrase here is outside tests/language/everyday.toml (checked below)."""

import tomllib
from pathlib import Path

import pytest

from tests.helpers import run_cnlmc

EVERYDAY = Path(__file__).with_name("everyday.toml")
PHRASES = [
    "pewtr",
    "mahagony",
    "brushed alumnium",
    "tinn glass",
    "clear tinn",
    "periwinkle",
    "khaki",
    "very hammered",
    "shellac",
    "tin periwinkle",
    "tin hammered",
    "aluminum brushed",
    "gneis",
    "very",
    "very, lightly",
]


def errors(compile_text, text):
    return [d for d in compile_text(text).diagnostics if d.is_error]


def test_the_phrases_here_are_not_in_the_everyday_set():
    data = tomllib.loads(EVERYDAY.read_text("utf-8"))
    listed = {row["text"].lower() for row in data["phrase"]}
    assert not listed & {p.lower() for p in PHRASES}


@pytest.mark.parametrize(
    "text,word,expected",
    [("mahgonay", "mahgonay", "mahogany"), ("brushed alumimun", "alumimun", "aluminum")],
)
def test_a_typo_gets_its_word(compile_text, text, word, expected):
    """Typos beyond the reach of a slip read as its word (cnlmc.typos) are offered."""
    (e,) = [d for d in errors(compile_text, text) if d.code == "E001"]
    assert e.message == f"unknown word '{word}'"
    assert e.suggestions[0] == expected
    assert e.hints[0].startswith(f"did you mean '{expected}'")


def test_a_noun_slot_suggests_nouns_and_a_modifier_slot_modifiers(compile_text, stdlib):
    noun_slot = errors(compile_text, "clear tinn")
    modifier_slot = errors(compile_text, "tinn glass")
    assert [d.code for d in noun_slot] == ["E001"]
    assert [d.code for d in modifier_slot] == ["E001"]  # no second error from a guess that does not fit
    for s in noun_slot[0].suggestions:
        assert any(e.category == "nouns" for e in stdlib.lookup(tuple(s.split()))), s
    assert "tin" in noun_slot[0].suggestions
    for s in modifier_slot[0].suggestions:
        assert all(e.category != "nouns" for e in stdlib.lookup(tuple(s.split()))), s
    assert modifier_slot[0].suggestions


@pytest.mark.parametrize(
    "word,never",
    [
        ("unglazed", "glazed"),
        ("non-metallic", "metallic"),
        ("unwaxed", "waxed"),
        ("non-anodized", "anodized"),
        ("unbrushed", "brushed"),
    ],
)
def test_a_prefixed_word_never_gets_its_opposite(stdlib, word, never):
    assert never not in stdlib.suggest(word)


@pytest.mark.parametrize(
    "word,far",
    [("pewter", ("fewer", "water")), ("beech", ("bleach",)), ("cedar", ("clear",)), ("hickory", ("thickly",))],
)
def test_far_fetched_look_alikes_are_not_offered(stdlib, word, far):
    for slot in (None, ("nouns",), ("adjectives", "adverbs", "colours", "shades")):
        assert not set(far) & set(stdlib.suggest(word, slot))


def test_the_first_word_of_a_known_form_offers_the_form(stdlib):
    assert stdlib.suggest("stainless", ("nouns",))[0] == "stainless steel"


@pytest.mark.parametrize(
    "text,role,phrase",
    [
        ("periwinkle", "a colour", "periwinkle paint"),
        ("very hammered", "a describing word", "very hammered copper"),
        ("khaki", "a colour", "khaki fabric"),  # WordNet: khaki is a kind of fabric
    ],
)
def test_a_phrase_without_a_noun_is_read_as_the_first_phrase_offered_with_a_note(compile_text, text, role, phrase):
    result = compile_text(text)
    assert result.ok, role
    (note,) = [d for d in result.diagnostics if d.message.startswith("no material named")]
    assert note.message == f"no material named: read '{text}' as '{phrase}'"
    assert note.hints[0].startswith("name the material to choose another: '")
    assert result.materials[0]["params"] == compile_text(phrase).materials[0]["params"]


@pytest.mark.parametrize(("text", "role"), [("very", "an adverb"), ("very, lightly", "an adverb")])
def test_a_phrase_with_nothing_that_describes_a_surface_still_names_no_material(compile_text, text, role):
    (e,) = errors(compile_text, text)
    assert (e.code, e.message) == ("E003", "this phrase names no material: end it with a noun")
    word = text.split()[-1]
    assert e.hints[0].startswith(f"'{word}' is {role} here — did you mean '")
    assert compile_text(e.suggestions[0]).ok


def test_a_coat_alone_is_offered_on_a_material(compile_text, stdlib):
    only_coats = ("coats", "objects")  # an object alone keeps its other reading ('coat': the garment, or a coat)
    coats = [
        k for k in stdlib.all_of("coats") if " " not in k and all(e.category in only_coats for e in stdlib.lookup((k,)))
    ]
    (e,) = errors(compile_text, coats[0])
    assert e.hints[0].startswith(f"'{coats[0]}' is a coat here")
    assert f" with a {coats[0]}" in e.suggestions[0]
    assert compile_text(e.suggestions[0]).ok


def test_a_colour_after_the_noun_is_read_before_it(compile_text):
    """No longer an error: 'tin periwinkle' is periwinkle tin, with a note (cnlmc.noun_first)."""
    result = compile_text("tin periwinkle")
    assert result.ok and result.materials[0]["params"] == compile_text("periwinkle tin").materials[0]["params"]


def test_a_word_after_the_noun_that_cannot_describe_it_is_offered_before_it(compile_text):
    (e,) = errors(compile_text, "steel lightly")
    assert e.hints == ("'lightly' is an adverb: it comes before the noun — did you mean 'lightly steel'?",)


def test_teaching_errors_through_the_cli():
    proc = run_cnlmc("compile", "-", stdin="very\nclear tinn\nperiwinkle\n")
    assert proc.returncode != 0
    assert "<stdin>:1:1: error[E003]: this phrase names no material: end it with a noun" in proc.stderr
    assert "= 'very' is an adverb here — did you mean 'very glossy plastic'" in proc.stderr
    assert "<stdin>:3:1: note[N101]: no material named: read 'periwinkle' as 'periwinkle paint'" in proc.stderr
    assert "<stdin>:2:7: error[E001]: unknown word 'tinn'" in proc.stderr
    assert "= did you mean 'tin'?" in proc.stderr


@pytest.mark.parametrize(
    "text", ["brass with a clear varnish", "zinc with a clear lacquer", "tin with a tinted lacquer"]
)
def test_a_coat_word_describes_the_coat_not_the_metal(compile_text, text):
    result = compile_text(text)
    assert result.ok
    assert not [d.code for d in result.diagnostics if d.code == "W102"]
    assert result.materials[0]["params"]["coat"]["name"] in ("varnish", "lacquer")


def test_the_same_word_on_the_metal_itself_still_warns(compile_text):
    codes = [d.code for d in compile_text("clear zinc").diagnostics]
    assert codes == ["W102"]


@pytest.mark.parametrize(
    "text,kept", [("coffee brown velvet", "coffee"), ("ivory white plaster", "ivory"), ("ruby red acrylic", "ruby")]
)
def test_a_particular_colour_before_its_basic_term_is_one_colour(compile_text, stdlib, text, kept):
    result = compile_text(text)
    assert result.ok
    assert not [d for d in result.diagnostics if d.code == "W105"]
    notes = [d for d in result.diagnostics if d.code == "N131"]
    assert len(notes) == 1 and notes[0].severity.value == "note"
    steps = result.materials[0]["provenance"]["base_color"]
    assert steps[-1]["rule"] == f"colours: {kept}"


@pytest.mark.parametrize("text", ["green orange plastic", "black white velvet", "lime purple paint"])
def test_two_colours_that_disagree_still_warn(compile_text, text):
    assert "W105" in [d.code for d in compile_text(text).diagnostics]


@pytest.mark.parametrize(
    "text,name",
    [
        ("walnut with a satin red lacquer", "walnut_with_satin_red_lacquer"),
        ("gently sandblasted zinc", "gently_sandblasted_zinc"),
        ("very dark grey felt", "very_dark_grey_felt"),
    ],
)
def test_the_default_name_keeps_every_word(compile_text, text, name):
    result = compile_text(text)
    assert result.ok
    assert result.materials[0]["name"] == name


def test_a_written_name_still_wins(compile_text):
    assert compile_text("deck: walnut with a satin red lacquer").materials[0]["name"] == "deck"


def test_the_default_name_keeps_the_with_clauses_in_phrase_order(compile_text):
    result = compile_text("bronze with fine scratches and a wax")
    assert result.materials[0]["name"] == "bronze_with_fine_scratches_and_wax"


SPECIES = ["white beech", "black birch", "pin oak", "red alder", "yellow cedar", "silver maple", "white walnut"]


@pytest.mark.parametrize("text", SPECIES)
def test_a_colour_word_in_a_species_name_names_the_species(compile_text, stdlib, text):
    result = compile_text(text)
    assert result.ok and not [d for d in result.diagnostics if d.severity.value != "note"]
    material = result.materials[0]
    red, green, blue = material["params"]["base_color"]
    assert 0.005 < blue < green < red < 0.9  # a wood's warm brown, not white, black, red, yellow or silver paint
    assert "base_color" in material["maps"] and material["maps"]["base_color"]["graph"] == "wood"
    (step,) = material["provenance"]["base_color"][:1]
    assert step["rule"].startswith("nouns.") and "dielectrics.json" in step["source"]


def test_the_colour_word_still_colours_a_wood_that_is_not_a_species_of_it(compile_text):
    species = compile_text("white oak").materials[0]["params"]["base_color"]
    painted = compile_text("white teak").materials[0]["params"]["base_color"]
    assert min(painted) > max(species)  # 'white teak' is teak made white, 'white oak' is a species


def test_a_refinement_line_typo_gets_its_refinement(compile_text):
    result = compile_text("copper\nroughr\n")  # one slip: read, with its note
    assert result.ok and any("as 'rougher'" in d.message for d in result.diagnostics)
    (e,) = errors(compile_text, "copper\nrougherrr\n")  # two slips in 9 letters: offered
    assert e.code == "E001" and e.suggestions[0] == "rougher"


@pytest.mark.parametrize(
    "text,phrase",
    [
        ("gently", "gently brushed brass"),  # an adverb's alias finishes as its entry's example does
        ("very with a wax", "very glossy plastic with a wax"),  # the 'with' clause stays in the offer
    ],
)
def test_the_offer_finishes_the_phrase_as_written(compile_text, text, phrase):
    (e,) = errors(compile_text, text)
    assert e.suggestions[0] == phrase
    assert compile_text(phrase).ok


def test_an_implied_material_keeps_the_with_clause(compile_text):
    result = compile_text("glossy with a wax")
    assert result.ok
    assert result.materials[0]["params"] == compile_text("glossy paint with a wax").materials[0]["params"]


def test_a_describing_word_after_the_noun_moves_before_it(compile_text):
    result = compile_text("bronze satin hammered")
    assert result.ok
    assert result.materials[0]["params"] == compile_text("satin hammered bronze").materials[0]["params"]


@pytest.mark.parametrize("text", ["stainles steel", "stainls steel", "stanless steel"])
def test_a_typo_in_the_first_word_of_a_two_word_noun_reads_the_noun(compile_text, text):
    """One slip, or two where the entry's second word confirms it (cnlmc.typos)."""
    result = compile_text(text)
    assert result.ok and result.materials[0]["params"] == compile_text("stainless steel").materials[0]["params"]
    assert any("as 'stainless' (a slip of the keyboard)" in d.message for d in result.diagnostics)


def test_crude_survey_names_are_never_offered(compile_text, stdlib):
    (e,) = errors(compile_text, "whit oak")
    assert e.suggestions[0] == "white oak" and "shit" not in e.suggestions
    assert "shit" not in stdlib.suggest("whit") and "snot" not in stdlib.suggest("snott")


def test_a_known_colour_in_the_noun_slot_offers_the_noun_it_is_a_typo_of(compile_text):
    (e,) = errors(compile_text, "terracota")
    assert e.suggestions[0] == "terracotta"
