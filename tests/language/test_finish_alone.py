"""A finish substance named as the whole material (issue #14, package LANG2): a describing word
whose lexicon entry declares the words naming its substance and the noun it is usually on
(adjectives `substances`, `substrate`) is that finish on that noun, with a note: 'blue glaze' =
blue glazed ceramic, 'red enamel' = red enameled steel. A describing word that names no substance
('glossy', 'brushed', 'glazed') alone is read on the material the teaching offers first
(cnlmc.implied), not as a finish named alone. The phrases
here are not in tests/language/everyday.toml."""

from __future__ import annotations

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from cnlmc.api import compile_source, lexicon_for
from tests.helpers import run_cnlmc

from .conftest import look

LEX = lexicon_for()
DE = lexicon_for(("de",))


def notes(result) -> list[str]:
    return [d.message for d in result.diagnostics if d.severity.name == "NOTE"]


@pytest.mark.parametrize(
    ("phrase", "same_as", "lexicon"),
    [
        ("glaze", "glazed ceramic", LEX),
        ("a pale blue glaze", "pale blue glazed ceramic", LEX),
        ("very glossy dark green glaze", "very glossy dark green glazed ceramic", LEX),
        ("enamel", "enameled steel", LEX),
        ("slightly matte cream enamel", "slightly matte cream enameled steel", LEX),
        ("oil", "oiled wood", LEX),
        ("a satin oil", "satin oiled wood", LEX),
        ("very dark stain", "very dark stained wood", LEX),
        ("red glaze-finished", "red glazed ceramic", LEX),
        ("oil-finished", "oiled wood", LEX),
        ("mat: glossy black enamel", "mat: glossy black enameled steel", LEX),
        ("grüne Glasur", "grüne glasierte Keramik", DE),
        ("dunkle Beize", "dunkles gebeiztes Holz", DE),
    ],
)
def test_a_finish_substance_named_alone_is_that_finish_on_its_usual_substrate(phrase, same_as, lexicon):
    result, said = look(lexicon, phrase)
    _, spelled = look(lexicon, same_as)
    assert said == spelled
    assert any("a finish named alone" in n for n in notes(result)), notes(result)


@pytest.mark.parametrize("phrase", ["glossy", "brushed", "very glossy red", "glazed", "enamelled", "blue glazed"])
def test_a_describing_word_that_names_no_substance_is_read_on_its_implied_material_not_as_a_finish(phrase):
    result = compile_source(phrase, "t.cnl", LEX)
    assert result.ok
    assert any(n.startswith(f"no material named: read '{phrase}' as '{phrase} ") for n in notes(result)), notes(result)
    assert not any("a finish named alone" in n for n in notes(result))


@pytest.mark.parametrize(
    ("phrase", "same_as"),
    [
        ("ceramic with a blue glaze", "blue glazed ceramic"),
        ("cast iron, red enamel", "red enameled cast iron"),
        ("oak with a dark stain", "dark stained oak"),
    ],
)
def test_a_finish_with_its_material_keeps_that_material(phrase, same_as):
    result, said = look(LEX, phrase)
    assert said == look(LEX, same_as)[1]
    assert not any("a finish named alone" in n for n in notes(result))


def test_every_declared_substance_is_a_form_of_its_entry_and_every_substrate_a_noun():
    declared = [key for key in LEX.all_of("adjectives") if LEX.require("adjectives", key).get("substrate")]
    assert {"glazed", "enameled"} <= set(declared)
    for key in declared:
        entry = LEX.require("adjectives", key)
        assert LEX.entry("nouns", entry.get("substrate")) is not None, key
        for word in entry.get("substances"):
            assert any(e.key == key for e in LEX.lookup((word,))), (key, word)


def test_the_note_points_at_the_words_and_the_material_is_the_substrate(tmp_path):
    path = tmp_path / "m.cnl"
    path.write_text("tile: pale blue glaze\n", encoding="utf-8")
    result = compile_source(path.read_text(encoding="utf-8"), str(path), LEX)
    (note,) = [d for d in result.diagnostics if "a finish named alone" in d.message]
    assert (note.span.col, note.span.end - note.span.start) == (7, len("pale blue glaze"))
    (material,) = result.ir["materials"]
    assert material["name"] == "tile"
    done = run_cnlmc("compile", str(path))
    assert done.returncode == 0
    assert "read 'pale blue glaze' as 'pale blue glazed ceramic'" in done.stderr


_DEGREES = st.sampled_from(["", "very ", "slightly ", "a bit "])
_LOOKS = st.sampled_from(["", "glossy ", "matte ", "satin "])
_COLOURS = st.sampled_from(["", "red ", "dark green ", "pale blue ", "cream "])
_SUBSTANCES = st.sampled_from(["glaze", "enamel", "oil", "stain", "glaze-finished"])


@settings(max_examples=25, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(_DEGREES, _LOOKS, _COLOURS, _SUBSTANCES)
def test_degree_look_and_colour_before_a_substance_compile_with_the_note(degree, finish, colour, substance):
    phrase = f"{degree}{finish}{colour}{substance}".strip()
    if degree and not finish:
        phrase = f"{finish}{colour}{substance}"  # a degree needs a describing word after it
    result = compile_source(phrase, "t.cnl", LEX)
    assert result.ok, (phrase, [d.message for d in result.diagnostics])
    assert any("a finish named alone" in n for n in notes(result)), phrase


def test_the_implied_substrate_is_marked_implied_in_the_tokens():
    done = run_cnlmc("compile", "--emit", "tokens", "-", stdin="cobalt blue glaze\n")
    assert done.returncode == 0, done.stderr
    rows = [line.split("\t") for line in done.stdout.splitlines()]
    assert ["1:13", "ADJ", "glaze"] in rows
    assert ["1:13", "NOUN", "ceramic", "(implied)"] in rows


@pytest.mark.parametrize(
    ("phrase", "rule"),
    [("satin varnish", "a coat named alone"), ("glossy white enamel coat", "a coat named alone")],
)
def test_a_coat_named_alone_keeps_its_own_rule(phrase, rule):
    result, _ = look(LEX, phrase)
    assert any(rule in n for n in notes(result))
    assert not any("a finish named alone" in n for n in notes(result))
