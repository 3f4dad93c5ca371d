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
