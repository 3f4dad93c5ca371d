"""Describing words after the noun with no comma (issue #14, cnlmc.noun_first): 'steel brushed'
is brushed steel, read only when nothing else reads the line, with a note that shows the order the
grammar writes. Colour names, coats after the noun, guessed words and a trailing adverb keep their
own readings or errors."""

from __future__ import annotations

import pytest

from tests.helpers import run_cnlmc
from tests.language.meaning import compiled, material, same_look


def problems(text: str) -> list[str]:
    return [d.code for d in compiled(text).diagnostics if d.severity.value in ("error", "warning")]


def notes(text: str) -> list[str]:
    return [d.message for d in compiled(text).diagnostics if d.severity.value == "note"]


def same_material(a: dict, b: dict) -> bool:
    return a["model"] == b["model"] and a["params"] == b["params"] and a.get("maps") == b.get("maps")


@pytest.mark.parametrize(
    ("said", "written"),
    [
        ("steel brushed", "brushed steel"),
        ("aluminum brushed", "brushed aluminum"),
        ("oak oiled", "oiled oak"),
        ("chrome hammered", "hammered chrome"),
        ("tin periwinkle", "periwinkle tin"),
        ("sandstone rough", "rough sandstone"),
        ("mahogany varnished", "varnished mahogany"),  # a noun that is also a colour, then a finish
        ("plastic charcoal grey", "charcoal grey plastic"),
        ("marble white polished", "white polished marble"),
        ("bronze satin hammered", "satin hammered bronze"),
        ("steel slightly rough", "slightly rough steel"),
        ("paint dark green with satin finish", "dark green paint with satin finish"),
        ("cushion burnt orange", "burnt orange cushion"),  # an object read as its material
    ],
)
def test_describing_words_after_the_noun_describe_it(said, written):
    assert problems(said) == []
    assert same_material(material(said), material(written))
    assert f"read '{said}' as '{written}' (describing words go before the noun)" in notes(said)


@pytest.mark.parametrize(
    ("said", "listed"),
    [
        ("oak a bit darker", "oak, a bit darker"),
        ("polished granite darker", "polished granite, darker"),
        ("white paint bit warmer", "white paint, bit warmer"),
    ],
)
def test_comparatives_after_the_noun_move_it(said, listed):
    assert problems(said) == []
    assert same_look(material(said), material(listed))
    assert f"read '{said}' as '{listed}' (a comma after the material)" in notes(said)


def test_the_comparatives_move_the_material_they_follow():
    darker = material("oak a bit darker")["params"]["base_color"]
    oak = material("oak")["params"]["base_color"]
    assert sum(darker) < sum(oak)


@pytest.mark.parametrize("colour", ["terracotta red", "satin navy", "slate grey", "ivory white"])
def test_a_colour_name_stays_a_colour(colour):
    assert same_look(material(colour), material(f"{colour} paint"))
    assert not any("go before the noun" in n for n in notes(colour))


@pytest.mark.parametrize(
    ("said", "why"),
    [
        ("satin varnish varnish", "a coat after the noun has readings of its own"),
        ("smooth peanut butter", "a word read as two ('pea nut') is a guess"),
        ("steel lightly", "an adverb with nothing to modify"),
        ("aluminum brushed and", "a line that ends in 'and'"),
        ("steel aluminum brushed", "two materials"),
    ],
)
def test_lines_it_does_not_read_keep_their_errors(said, why):
    assert compiled(said).ok is False, why
    assert not any("go before the noun" in n for n in notes(said)), why


def test_a_trailing_adverb_still_says_where_describing_words_go():
    (d,) = [d for d in compiled("steel lightly").diagnostics if d.severity.value == "error"]
    assert d.message == "'lightly' comes after the noun: describing words come before it"


def test_a_comma_already_there_keeps_its_reading():
    assert not any("go before the noun" in n for n in notes("oak, oiled"))
    assert same_material(material("oak, oiled"), material("oiled oak"))


def test_a_warning_of_the_reordered_phrase_stays():
    """'walnut plated' is 'plated walnut', and says what 'plated walnut' says (plating coats metal)."""
    assert problems("walnut plated") == problems("plated walnut") == ["W102"]


def test_the_command_line_compiles_it_with_the_note(tmp_path):
    out = tmp_path / "out"
    proc = run_cnlmc("compile", "-", "--target", "ir", "-o", str(out), stdin="steel brushed\n")
    assert proc.returncode == 0, proc.stderr
    assert "read 'steel brushed' as 'brushed steel'" in proc.stderr
    assert "1 | steel brushed" in proc.stderr
