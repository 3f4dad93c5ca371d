"""Change lines as people say them (issue #14): the alternative turned down ('eggshell rather than
flat', 'walnut instead of oak'), a verdict after the change ('brushed would look better'), where the
change goes ('more colour in it') and a question about the material ('can they be glazed')."""

from __future__ import annotations

import pytest

from cnlmc.api import compile_source, lexicon_for, refined

LEX = lexicon_for()


def look(document: str) -> dict:
    result = compile_source(document + "\n", "t.cnl", LEX)
    assert result.ok and result.materials
    material = result.materials[-1]
    return {"model": material["model"], "params": material["params"], "maps": material.get("maps")}


def changed(first: str, line: str) -> dict:
    document, result = refined(first, line, LEX, "t.cnl")
    assert result.ok and result.materials, [d.message for d in result.diagnostics]
    return look(document)


@pytest.mark.parametrize(
    ("first", "said", "meant"),
    [
        ("mint green bedroom paint", "eggshell rather than flat", "eggshell"),
        ("oak", "walnut instead of oak", "walnut"),
        ("oak", "satin as opposed to gloss please", "satin"),
        ("polished chrome tap", "actually brushed would look better", "brushed"),
        ("oak", "a warmer tone might work better", "warmer"),
        ("terracotta kitchen tiles", "can they be glazed", "glazed"),
        ("blue plastic", "a bit more colour in it", "a bit more colour"),
    ],
)
def test_a_change_said_around_its_words_is_those_words(first: str, said: str, meant: str) -> None:
    assert changed(first, said) == changed(first, meant)
    assert changed(first, said) != look(first)


def test_a_turned_down_alternative_that_names_the_noun_is_not_read_past() -> None:
    """'matte rather than glossy black plastic': the plastic is the phrase's, so the line is not cut."""
    result = compile_source("matte rather than glossy black plastic\n", "t.cnl", LEX)
    assert not result.materials or "plastic" in result.materials[-1]["name"]  # never 'matte paint'
    assert "rather than" not in " ".join(d.message for d in result.diagnostics)
    assert look("walnut instead of oak") == look("walnut")
    assert look("black plastic, matte rather than glossy") == look("black matte plastic")


@pytest.mark.parametrize(
    ("said", "lines"),
    [
        ("oak, no grain", "oak\nno grain"),
        ("white marble, no veins", "white marble\nno veins"),
        ("oak, without the grain", "oak\nwithout the grain"),
    ],
)
def test_a_removal_after_the_material_is_the_change_line(said: str, lines: str) -> None:
    """'oak, no grain' on one line means what 'no grain' under 'oak' means: much less of the grain
    its noun brings (cnlmc.removed); the default name keeps the words said."""
    assert look(said) == look(lines)
    assert look(said) != look(said.split(",")[0])
    name = compile_source(said + "\n", "t.cnl", LEX).materials[-1]["name"]
    removal, material = said.split(", ")[1], said.split(", ")[0]
    assert name == f"{removal}_{material}".replace(" ", "_")  # no_grain_oak, without_the_grain_oak


def test_one_note_for_a_removal_part_and_other_readings_kept() -> None:
    """'oak, no grain, a bit darker': the removal read once; 'oak, can we lose the grain': its
    openers go with it; 'rust on steel, no shine' keeps its clause reading."""
    for text in (
        "oak, no grain, a bit darker",
        "oak, can we lose the grain",
        "oak, please no grain",
        "rust on steel, no shine",
    ):
        result = compile_source(text + "\n", "t.cnl", LEX)
        assert result.ok and result.materials, (text, [d.message for d in result.diagnostics])
    notes = [d.message for d in compile_source("oak, no grain, a bit darker\n", "t.cnl", LEX).diagnostics]
    assert len([n for n in notes if "'no grain'" in n]) == 1, notes


def test_a_removal_of_what_the_material_lacks_is_as_said_and_never_a_describing_word() -> None:
    """Said with the material ('white paint, no texture', 'steel without any scratches'), what it has
    none of is already so: a note, no warning (a change line under it still warns: W122/W106)."""
    result = compile_source("white paint, no texture\n", "t.cnl", LEX)
    assert result.ok and [d.code for d in result.diagnostics if d.code.startswith("W")] == []
    assert any("none to take off" in d.message for d in result.diagnostics)
    for said in ("steel without any scratches", "oak with no knots", "steel, free of scratches"):
        result = compile_source(said + "\n", "t.cnl", LEX)
        assert result.ok and not [d for d in result.diagnostics if d.severity.value != "note"], said
        assert any("none to take off" in d.message for d in result.diagnostics), said
    assert look("white paint, no texture") == look("white paint")  # not 'paint with white texture'
