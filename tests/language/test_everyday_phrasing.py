"""Everyday phrasing categories (issue #14, package LANG): a comparative against a named material
("lighter than oak"), negation without an opposite inside a comma list ("shiny, not rusty, iron"),
the physicallybased.info materials people name (lemon, eggshell, blood), a coat named as the whole
material ("satin varnish") and a noun that says where the material is used ("guitar varnish").
None of these phrases is in tests/language/everyday.toml's held-out twin; each rule is tested on
wording of its own, through cnlmc.api and the command line."""

from __future__ import annotations

import json
import re
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from cnlmc.api import compile_source, lexicon_for
from tests.helpers import run_cnlmc

from .conftest import look

LEX = lexicon_for()
DE = lexicon_for(("de",))
DATA = Path(__file__).resolve().parents[3] / "shared" / "data" / "physicallybased_materials.json"


def notes(result) -> list[str]:
    return [d.message for d in result.diagnostics if d.severity.name == "NOTE"]


def codes(result) -> list[str]:
    return sorted(d.code for d in result.diagnostics if d.severity.name in ("ERROR", "WARNING"))


def meaning(result) -> list[dict]:
    return [{k: m[k] for k in ("model", "params", "maps")} for m in result.ir["materials"]]


# ---------------------------------------------------------------- 1. "lighter than oak"


@pytest.mark.parametrize(
    ("phrase", "material", "line"),
    [
        ("lighter than oak", "oak", "lighter"),
        ("a bit shinier than brushed steel", "brushed steel", "a bit shinier"),
        ("much darker than walnut veneer", "walnut veneer", "much darker"),
        ("rougher than the concrete", "concrete", "rougher"),
        ("slightly warmer than white marble", "white marble", "slightly warmer"),
        ("far glossier than a satin black plastic", "satin black plastic", "far glossier"),
        ("less glossy than glass", "glass", "less glossy"),
        ("a lot more grain than pine", "pine", "a lot more grain"),
        ("slightly more matte than the white ceramic", "white ceramic", "slightly more matte"),
    ],
)
def test_a_comparative_than_a_material_is_that_material_moved_as_a_refinement_line(phrase, material, line):
    result, said = look(LEX, phrase)
    _, refined = look(LEX, f"{material}\n{line}")
    assert said == refined
    assert any("than" in n and "refinement line" in n for n in notes(result)), notes(result)


def test_german_als_after_a_comparative_is_the_same():
    result, said = look(DE, "dunkler als Eiche")
    _, refined = look(DE, "Eiche\ndunkler")
    assert said == refined
    assert any("'als'" in n for n in notes(result))
    _, duller = look(DE, "weniger glänzend als Glas")
    assert duller == look(DE, "Glas\nweniger glänzend")[1]
    _, brighter = look(DE, "etwas heller als gebürsteter Stahl")
    _, steel = look(DE, "gebürsteter Stahl\netwas heller")
    assert brighter == steel


def test_than_moves_the_material_the_comparative_way():
    """Not a no-op: lighter than oak is lighter than oak, darker than walnut darker than walnut."""
    from cnlmc.colour import linear_to_oklab

    def lightness(text: str) -> float:
        return linear_to_oklab(look(LEX, text)[1]["params"]["base_color"])[0]

    assert lightness("lighter than oak") > lightness("oak") + 0.02
    assert lightness("darker than walnut") < lightness("walnut") - 0.01
    assert (
        look(LEX, "rougher than polished steel")[1]["params"]["roughness"]
        > look(LEX, "polished steel")[1]["params"]["roughness"]
    )


@pytest.mark.parametrize("phrase", ["oak than steel", "than oak", "oak, lighter than"])
def test_than_without_a_comparative_before_it_is_still_an_error(phrase):
    result = compile_source(phrase, "t.cnl", LEX)
    assert not result.ok
    assert "E001" in codes(result) or "E002" in codes(result)


COMPARATIVES = (
    "lighter",
    "darker",
    "shinier",
    "rougher",
    "a bit duller",
    "much warmer",
    "less glossy",
    "more matte",
    "more grain",
)
SOME_NOUNS = sorted(LEX.all_of("nouns"))[::37]


@settings(max_examples=25, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.sampled_from(COMPARATIVES), st.sampled_from(SOME_NOUNS))
def test_than_is_always_the_refinement_line(comparative, noun):
    """For any noun and comparative: 'C than N' compiles to what 'N' refined by the line 'C' does,
    with the same errors and warnings (a comparative that cannot move N warns in both)."""
    said = compile_source(f"{comparative} than {noun}", "t.cnl", LEX)
    refined = compile_source(f"{noun}\n{comparative}", "t.cnl", LEX)
    assert codes(said) == codes(refined)
    if said.ok:
        assert meaning(said) == meaning(refined)


def test_than_on_the_command_line_prints_the_note():
    done = run_cnlmc("compile", "-", "--target", "ir", "-o", "-", stdin="a touch lighter than cherry\n")
    assert done.returncode == 0, done.stderr
    assert "note[N101]" in done.stderr and "'lighter than'" in done.stderr
    assert json.loads(done.stdout)["materials"][0]["params"]["base_color"]


COLOUR_COMPARATIVES = ("more yellow", "less red", "more blue", "bluer", "lighter", "a bit darker", "warmer")
SOME_COLOURED = ("white plastic", "blue plastic", "red ceramic", "green glass", "black rubber", "plastic", "oak")


@settings(max_examples=25, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.sampled_from(COLOUR_COMPARATIVES), st.sampled_from(SOME_COLOURED))
def test_a_colour_comparative_than_a_coloured_material_is_the_refinement_line(comparative, material):
    """'more yellow than white plastic' is white plastic moved by the line 'more yellow': the colour
    before 'than' is what changes, not a second colour of the material (no W105)."""
    said = compile_source(f"{comparative} than {material}", "t.cnl", LEX)
    refined = compile_source(f"{material}\n{comparative}", "t.cnl", LEX)
    assert codes(said) == codes(refined)
    assert meaning(said) == meaning(refined)


def test_more_yellow_than_white_plastic_is_white_plastic_made_more_yellow():
    said = compile_source("m: more yellow than white plastic", "t.cnl", LEX)
    assert "W105" not in codes(said)
    red, green, blue = said.ir["materials"][0]["params"]["base_color"]
    assert blue > 0.5 and min(red, green) > blue  # a yellowish white, not pure yellow
    red, green, blue = compile_source("more red than blue plastic", "t.cnl", LEX).ir["materials"][0]["params"][
        "base_color"
    ]
    assert blue > red  # still blue plastic, a step towards red


@pytest.mark.parametrize(
    ("phrase", "lexicon"),
    [
        ("lighter than", LEX),
        ("a bit darker than the", LEX),
        ("dunkler als", DE),
    ],
)
def test_a_comparison_word_with_nothing_after_it_is_an_error_with_a_caret(phrase, lexicon):
    result = compile_source(phrase, "t.cnl", lexicon)
    assert not result.ok
    (error,) = [d for d in result.diagnostics if d.code == "E003"]
    than = "als" if lexicon is DE else "than"
    assert error.span.col == phrase.index(than) + 1 and error.hints
    overlay = ("-L", "de") if lexicon is DE else ()
    done = run_cnlmc("compile", *overlay, "-", "-o", "-", stdin=f"{phrase}\n")
    assert done.returncode != 0 and "^" in done.stderr and "error[E003]" in done.stderr


@pytest.mark.parametrize(
    ("phrase", "same_as", "lexicon"),
    [
        ("lighter than satin varnish", "wood with a satin varnish\nlighter", LEX),
        ("a bit lighter than glossy varnish", "wood with a glossy varnish\na bit lighter", LEX),
        ("lighter than guitar varnish", "wood with a varnish\nlighter", LEX),
        ("darker than red powder coating", "red powder coating\ndarker", LEX),
        ("dunkler als Klarlack", "Stahl mit Klarlack\ndunkler", DE),
    ],
)
def test_a_comparative_than_a_coat_alone_is_the_coat_on_its_substrate_refined(phrase, same_as, lexicon):
    said = compile_source(phrase, "t.cnl", lexicon)
    assert said.ok, [d.message for d in said.diagnostics]
    assert meaning(said) == meaning(compile_source(same_as, "t.cnl", lexicon))


@pytest.mark.parametrize(
    ("phrase", "lexicon", "word"), [("lighter than than oak", LEX, "than"), ("dunkler als als Eiche", DE, "als")]
)
def test_a_comparison_word_twice_is_an_error_on_the_second(phrase, lexicon, word):
    result = compile_source(phrase, "t.cnl", lexicon)
    assert not result.ok
    (error,) = [d for d in result.diagnostics if d.code == "E002"]
    assert error.span.col == phrase.index(f"{word} {word}") + len(word) + 2


# ---------------------------------------------------------------- 4. "shiny, not rusty, iron"


@pytest.mark.parametrize(
    ("phrase", "same_as"),
    [
        ("shiny, not rusty, iron", "shiny iron"),
        ("matte, not rusty, dark grey steel", "matte dark grey steel"),
        ("not weathered, grey slate", "grey slate"),
        ("polished and not tarnished silver", "polished silver"),
        ("copper, not patinated", "copper"),
        ("glossy, not scratched, red plastic", "glossy red plastic"),
        ("walnut; not worn; oiled", "oiled walnut"),
        ("white, not yellowed, plastic", "white plastic"),
        ("grey, not red, slate", "grey slate"),
        ("black, not grungy, rubber", "black rubber"),
        ("shiny, but not rusty, iron", "shiny iron"),
    ],
)
def test_a_negation_with_no_opposite_in_a_list_takes_its_separator_with_it(phrase, same_as):
    result, said = look(LEX, phrase)
    _, plain = look(LEX, same_as)
    assert said == plain
    assert any(n.startswith("read '") and "not " in n and "no effect" in n for n in notes(result)), notes(result)


def test_a_negation_with_a_declared_opposite_in_a_list_is_still_the_opposite():
    _, said = look(LEX, "satin, not textured, plastic")
    _, opposite = look(LEX, "satin, smooth, plastic")
    assert said == opposite
    assert look(LEX, "smooth, but not glossy, marble")[1] == look(LEX, "smooth, matte, marble")[1]
    assert look(LEX, "grey but not shiny steel")[1] == look(LEX, "grey dull steel")[1]


def test_a_negation_in_a_german_list():
    assert look(DE, "glänzend, nicht rostig, Eisen")[1] == look(DE, "glänzendes Eisen")[1]
    assert look(DE, "matt, aber nicht rau, Kunststoff")[1] == look(LEX, "matte, smooth, plastic")[1]


@pytest.mark.parametrize(("phrase", "lexicon"), [("but not", LEX), ("oak, yet not", LEX), ("gar nicht", DE)])
def test_a_conjunction_and_not_with_nothing_after_is_an_error_not_a_traceback(phrase, lexicon):
    result = compile_source(phrase, "t.cnl", lexicon)
    assert not result.ok and all(d.span is not None for d in result.diagnostics if d.severity.name == "ERROR")


def test_not_before_an_unknown_word_outside_a_list_is_still_an_error():
    """'not yellowed plastic' (no comma): 'not' has nothing it can negate, E002 as before; in a list
    the unknown word is noted with its spelling suggestions."""
    assert "E002" in codes(compile_source("not yellowed plastic", "t.cnl", LEX))
    result, _ = look(LEX, "white, not grungy, tiles")
    assert any("a word the lexicon does not know" in n for n in notes(result))


def test_a_dropped_negation_never_eats_a_word_that_is_not_a_separator():
    """'hull: not rusty, iron': the name's colon stays; the material is iron."""
    result = compile_source("hull: not rusty, iron", "t.cnl", LEX)
    assert result.ok, [d.message for d in result.diagnostics]
    assert result.ir["materials"][0]["name"] == "hull"
    assert result.ir["materials"][0]["params"] == look(LEX, "iron")[1]["params"]


# ---------------------------------------------------------------- 5. physicallybased.info nouns

#: Rows that are not a material people name: parts of the eye (anatomy; out of scope).
NOT_EVERYDAY = {"Eye (Cornea)", "Eye (Lens)", "Eye (Sclera)"}


def _forms(name: str) -> list[str]:
    """A dataset name in the forms people type: 'Egg Shell (Brown)' -> 'brown egg shell', 'egg shell'."""
    low = name.lower()
    qualified = re.fullmatch(r"(.*) \((.*)\)", low)
    if qualified is None:
        return [low]
    head, quality = qualified.groups()
    return [f"{quality} {head}", head]


@pytest.mark.skipif(not DATA.exists(), reason="../shared/data is not beside the checkout")
def test_every_everyday_physicallybased_material_is_a_noun():
    """Its name compiles (plain or qualified), or a noun cites its row ('Orange': 'orange peel', since
    plain 'orange' is the colour)."""
    rows = json.loads(DATA.read_text("utf-8"))["data"]
    cited = " ".join(str(LEX.require("nouns", key).get("source")) for key in LEX.all_of("nouns"))
    missing = []
    for row in rows:
        if row["name"] in NOT_EVERYDAY or f"physicallybased_materials.json '{row['name']}'" in cited:
            continue
        if not any(compile_source(f, "t.cnl", LEX).ok for f in _forms(row["name"])):
            missing.append(row["name"])
    assert not missing


@pytest.mark.parametrize(
    ("phrase", "row"),
    [
        ("lemon", "Lemon"),
        ("orange peel", "Orange"),
        ("egg shell", "Egg Shell (White)"),
        ("brown eggshell", "Egg Shell (Brown)"),
        ("blood", "Blood (Oxygenated)"),
        ("venous blood", "Blood (Deoxygenated)"),
        ("wine", "Wine (Red)"),
    ],
)
def test_the_new_nouns_carry_the_dataset_row(phrase, row):
    result, said = look(LEX, phrase)
    material = result.ir["materials"][0]
    sources = [s.get("source", "") for steps in material["provenance"].values() for s in steps]
    assert any(f"physicallybased_materials.json '{row}'" in s for s in sources), sources
    if DATA.exists():
        data = {m["name"]: m for m in json.loads(DATA.read_text("utf-8"))["data"]}[row]
        linear = next(c["color"] for c in data["color"] if c["colorSpace"] == "srgb-linear")
        assert said["params"]["base_color"] == pytest.approx(linear, abs=5e-4)


@pytest.mark.parametrize("colour", ["orange", "lemon", "blood"])  # 'orange' alone is the colour only
def test_a_fruit_or_egg_before_a_material_is_still_its_colour(colour):
    """'orange plastic' is plastic in the colour orange, not two materials."""
    result, said = look(LEX, f"{colour} plastic")
    _, plastic = look(LEX, "plastic")
    assert said["params"]["base_color"] != plastic["params"]["base_color"]
    assert result.ir["materials"][0]["provenance"]["base_color"][-1]["words"] == [colour]


@pytest.mark.parametrize("said", ["eggshell paint", "eggshell wall paint", "grey eggshell interior paint"])
def test_eggshell_before_a_paint_is_its_sheen(said):
    """Paint is sold by sheen: eggshell is a low sheen (satin's alias), not the survey's #ffffd4."""
    _, got = look(LEX, said)
    _, satin = look(LEX, said.replace("eggshell wall", "satin").replace("eggshell", "satin"))
    assert got["params"] == satin["params"]


@pytest.mark.parametrize(("german", "english"), [("Zitrone", "lemon"), ("Eierschale", "eggshell"), ("Blut", "blood")])
def test_the_new_nouns_in_german(german, english):
    assert look(DE, german)[1] == look(LEX, english)[1]


# ---------------------------------------------------------------- 3. a coat named as the whole material


@pytest.mark.parametrize(
    ("phrase", "same_as"),
    [
        ("satin varnish", "wood with a satin varnish"),
        ("a matte clear lacquer", "wood with a matte lacquer"),
        ("glossy clear coat", "steel with a glossy clear coat"),
        ("clear wax", "wood with a wax"),
        ("blue powder coating", "blue powder-coated steel"),
        ("a satin, dark green powder coat", "satin dark green powder-coated steel"),
        ("glossy white enamel coat", "glossy white enameled steel"),
        ("red gelcoat", "fiberglass with a red gel coat"),
        ("spar varnish", "wood with a varnish"),
        ("satin shellac", "wood with a satin varnish"),
        ("a coat of varnish", "wood with a varnish"),
        ("a coat of satin varnish", "wood with a satin varnish"),
        ("two coats of spar varnish", "wood with a varnish"),
        ("a thick layer of red powder coating", "red powder-coated steel"),
        ("fine grain powder coating", "powder-coated steel with fine grain"),
        ("speckled powder coat", "powder-coated steel with speckles"),
    ],
)
def test_a_coat_named_alone_is_that_coat_on_its_usual_substrate(phrase, same_as):
    result, said = look(LEX, phrase)
    _, spelled = look(LEX, same_as)
    assert said == spelled
    assert any("a coat named alone" in n for n in notes(result)), notes(result)


def test_every_substrate_is_a_noun_and_every_coat_adjective_an_adjective():
    for key in LEX.all_of("coats"):
        entry = LEX.require("coats", key)
        if entry.get("substrate") is not None:
            assert LEX.entry("nouns", entry.get("substrate")) is not None, key
        if entry.get("adjective") is not None:
            assert LEX.entry("adjectives", entry.get("adjective")) is not None, key


def test_a_pigmented_coat_alone_is_opaque_paint_not_a_tint_over_metal():
    """'red powder coating': the pigment is the surface (a red dielectric), not bare steel under a red film."""
    material = look(LEX, "red powder coating")[0].ir["materials"][0]
    assert material["model"]["base"] == "dielectric"
    red, green, blue = material["params"]["base_color"]
    assert red > 4 * max(green, blue, 0.01)


def test_a_coat_of_a_coat_after_with_is_that_coat():
    assert look(LEX, "oak with a coat of glossy lacquer")[1] == look(LEX, "oak with a glossy lacquer")[1]
    assert look(LEX, "a coat of red paint")[1] == look(LEX, "red paint")[1]  # paint: a material, as before


def test_a_name_before_a_coat_alone_stays_the_name():
    result = compile_source("deck: glossy varnish", "t.cnl", LEX)
    assert result.ok, [d.message for d in result.diagnostics]
    assert result.ir["materials"][0]["name"] == "deck"
    assert meaning(result) == meaning(compile_source("wood with a glossy varnish", "t.cnl", LEX))


@pytest.mark.parametrize("phrase", ["glossy coat", "oak with a varnish", "wax", "lacquer"])
def test_what_is_not_a_coat_alone_reads_as_before(phrase):
    """The generic coat names no substrate; a 'with' clause has its material; wax and lacquer are nouns."""
    result = compile_source(phrase, "t.cnl", LEX)
    assert not any("a coat named alone" in n for n in notes(result))


@pytest.mark.parametrize("phrase", ["floor, varnish", "floor and varnish"])
def test_an_object_then_a_separator_is_not_the_coat_s_substrate(phrase):
    """'floor, varnish' was varnish_floor (the floor's wood, varnished) before the coat-alone rule:
    an object is what a coat is on only when a describing word or the coat itself follows it; since
    session 15 a listing's finish after its material names it floor_with_varnish (the same IR)."""
    result = compile_source(phrase, "t.cnl", LEX)
    assert not any("with ," in n or "with and" in n for n in notes(result)), notes(result)
    if phrase == "floor, varnish":
        assert result.ok, [d.message for d in result.diagnostics]
        assert result.ir["materials"][0]["name"] == "floor_with_varnish"


@pytest.mark.parametrize("phrase", ["varnish varnish", "satin varnish varnish", "lacquer varnish"])
def test_a_coat_before_a_coat_alone_is_not_its_describing_word(phrase):
    result = compile_source(phrase, "t.cnl", LEX)
    assert not any("a coat named alone" in n for n in notes(result)), notes(result)
    assert "W102" not in codes(result)


IMPLYING = [
    "satin varnish",
    "red powder coating",
    "fine grain powder coating",
    "floor varnish",
    "lighter than satin varnish",
]


@pytest.mark.parametrize("phrase", [*IMPLYING, "speckled granite with a polished finish"])
def test_every_provenance_span_covers_whole_typed_words(phrase):
    """A word the rules add ('wood' in 'satin varnish') is credited to the word that implies it, so
    every span in the IR starts and ends on a word boundary of what the user typed."""
    result = compile_source(phrase, "t.cnl", LEX)
    assert result.ok, [d.message for d in result.diagnostics]
    for steps in result.ir["materials"][0]["provenance"].values():
        for step in steps:
            for (_line, col, end), word in zip(step["spans"], step["words"]):
                assert col == 1 or phrase[col - 2] == " ", (phrase, word, col)
                assert end - 1 == len(phrase) or phrase[end - 1] in " ,", (phrase, word, end)


def test_an_implied_word_has_the_span_of_the_word_implying_it():
    material = compile_source("satin varnish", "t.cnl", LEX).ir["materials"][0]
    (wood,) = [s for s in material["provenance"]["base_color"] if s["words"] == ["wood"]]
    assert wood["spans"] == [[1, 7, 14]]  # 'varnish'
    (coat,) = material["provenance"]["coat"]
    assert coat["words"] == ["varnish"] and coat["spans"] == [[1, 7, 14]]
    done = run_cnlmc("compile", "-", "--emit", "tokens", stdin="satin varnish\n")
    assert "1:7\tNOUN\twood\t(implied)" in done.stdout.splitlines()
    explained = run_cnlmc("explain", "-", stdin="satin varnish\n")
    assert explained.returncode == 0, explained.stderr
    (coat_row,) = [line.split() for line in explained.stdout.splitlines() if line.split()[:1] == ["coat"]]
    assert coat_row[2] == "varnish"  # set by the word typed, not the substrate it implies


ENGLISH_READINGS = {"steel", "wood", "with", "matte", "glossy", "powder-coated"}


@pytest.mark.parametrize(
    ("phrase", "reading"),
    [
        ("rote Pulverbeschichtung", "rote pulverbeschichtet Stahl"),
        ("Klarlack", "Stahl mit Klarlack"),
        ("Boden Klarlack", "Holz mit Klarlack"),
        ("Stahl, aber nicht glänzender", "matt"),
        ("Dielen", "Holz"),
    ],
)
def test_german_notes_quote_the_german_lexicon_s_words(phrase, reading):
    """A note's readings are in the document's language: the German lexicon's own nouns, adjectives
    and 'mit' (stdlib/overlays/de), not the entries' English keys."""
    said = notes(compile_source(phrase, "t.cnl", DE))
    assert any(f"as '{reading}'" in n for n in said), said
    quoted = {w for n in said for q in re.findall(r"'([^']*)'", n) for w in q.split()}
    assert not quoted & ENGLISH_READINGS, said


@pytest.mark.parametrize(("phrase", "lexicon"), [(p, LEX) for p in IMPLYING] + [("rote Pulverbeschichtung", DE)])
def test_a_note_reads_only_what_the_user_typed(phrase, lexicon):
    """'read X as Y': X is always words of the line ('fine grain powder coating' is never quoted as
    'fine grain powder coating steel')."""
    for note in notes(compile_source(phrase, "t.cnl", lexicon)):
        said = re.match(r"read '([^']*)'", note)
        assert said is None or said.group(1) in phrase, note


def test_a_coat_alone_in_german():
    _, said = look(DE, "glänzender Klarlack")
    _, spelled = look(LEX, "steel with a glossy clear coat")
    assert said == spelled
    assert look(DE, "rote Pulverbeschichtung")[1] == look(LEX, "red powder coating")[1]


# ---------------------------------------------------------------- 2. "guitar varnish": where it is used


@pytest.mark.parametrize(
    ("phrase", "same_as", "used"),
    [
        ("boat paint", "paint", "boat"),
        ("guitar varnish", "wood with a varnish", "guitar"),
        ("violin lacquer", "lacquer", "violin"),  # piano lacquer is a material of its own (nouns_plastics.toml)
        ("glossy yacht paint", "glossy paint", "yacht"),
        ("skateboard deck maple", "maple", "skateboard"),
        ("red bicycle paint", "red paint", "bicycle"),
        ("oxidised canoe aluminium", "oxidised aluminium", "canoe"),
    ],
)
def test_a_noun_that_says_where_the_material_is_used_is_read_with_a_note(phrase, same_as, used):
    result, said = look(LEX, phrase)
    _, plain = look(LEX, same_as)
    assert said == plain
    assert any(n.startswith(f"read '{used}") for n in notes(result)), notes(result)


@pytest.mark.parametrize(
    ("phrase", "same_as"),
    [("floor varnish", "wood with a varnish"), ("car clear coat", "car paint with a clear coat"), ("planks", "wood")],
)
def test_an_object_before_a_coat_alone_is_what_the_coat_is_on(phrase, same_as):
    """'floor varnish': the floor's usual material with the coat; an object alone is still its material."""
    assert look(LEX, phrase)[1] == look(LEX, same_as)[1]


@pytest.mark.parametrize(
    ("phrase", "wanted"),
    [("blu boat paint", "blue"), ("shny guitar lacquer", "shiny")],
)
def test_a_misspelling_still_gets_its_did_you_mean(phrase, wanted):
    result = compile_source(phrase, "t.cnl", LEX)
    errors = [d for d in result.diagnostics if d.code == "E001"]
    assert errors and any(wanted in d.suggestions for d in errors), [(d.message, d.suggestions) for d in errors]


@pytest.mark.parametrize("phrase", ["guitar", "the guitar", "glossy guitar"])
def test_a_use_noun_with_no_material_after_it_is_still_unknown(phrase):
    result = compile_source(phrase, "t.cnl", LEX)
    assert "E001" in codes(result)


def test_a_colour_or_adjective_before_the_use_noun_keeps_its_meaning():
    _, said = look(LEX, "dark green boat paint")
    _, plain = look(LEX, "dark green paint")
    assert said == plain


def test_the_use_note_on_the_command_line():
    done = run_cnlmc("compile", "-", "--target", "ir", "-o", "-", stdin="trumpet lacquer\n")
    assert done.returncode == 0, done.stderr
    assert "read 'trumpet' as where the material is used" in done.stderr


# ---------------------------------------------------------------- every rule together, never a traceback

WORDS = (
    "than", "als", "not", "rusty", ",", "and", "a", "the", "lighter", "less", "glossy", "satin", "varnish",
    "powder coating", "clear coat", "gel coat", "floor", "planks", "guitar", "boat", "blu", "oak", "steel",
    "lemon", "orange", "blood", "with", "red", "very", "paint", "deck:", "more", "grain",
)  # fmt: skip


@settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.lists(st.sampled_from(WORDS), min_size=1, max_size=7))
def test_any_line_of_these_words_compiles_or_reports_without_a_traceback(words):
    result = compile_source(" ".join(words), "t.cnl", LEX)
    assert result.ok or any(d.severity.name == "ERROR" and d.span is not None for d in result.diagnostics)


@pytest.mark.parametrize("line", ["fine silver leaf with an anodic oxide", "fine silver leaf or gold"])
def test_a_multi_word_noun_before_a_clause_or_a_join_is_the_noun(line):
    """A form gives way to a multi-word noun that starts on its last word and runs to where a noun
    ends: a separator or 'with' / 'or' / 'and', as at the end of the line: 'fine' (nothing to
    modify, W103) + 'silver leaf', not the noun 'fine silver' followed by a stray 'leaf'."""
    result = compile_source(line + "\n")
    assert [d.code for d in result.diagnostics if d.severity.name == "ERROR"] == []
    plain = compile_source(line.removeprefix("fine ") + "\n")
    assert [m["params"] for m in result.ir["materials"]] == [m["params"] for m in plain.ir["materials"]]


@pytest.mark.parametrize(
    ("phrase", "same_as", "lexicon"),
    [
        ("lighter than red", "lighter red", LEX),
        ("darker than navy", "darker navy", LEX),
    ],
)
def test_a_comparison_with_a_colour_alone_is_that_colour_a_step_further(phrase, same_as, lexicon):
    """'darker than navy': a colour darker than navy, on the everyday noun (as 'darker navy' is)."""
    got, want = compile_source(phrase, "t.cnl", lexicon), compile_source(same_as, "t.cnl", lexicon)
    assert got.ok and meaning(got) == meaning(want)
