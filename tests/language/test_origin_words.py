"""A place of origin before a noun ('Italian marble', 'Burmese teak': adjectives_origins.toml) names
the stock, not a look: the same parameters as the noun alone, with note N141; an article may stand
before an inline comparative ('a rougher concrete'). The phrases here are not in everyday.toml."""

from __future__ import annotations

import tomllib
from pathlib import Path

import pytest

from cnlmc.api import compile_source, lexicon_for

LEX = lexicon_for()
PHRASES = ["Tuscan travertine", "Welsh slate", "Canadian maple", "imported teak", "a much glossier walnut"]


def compiled(text: str):
    return compile_source(text, "t.cnl", LEX)


def test_the_phrases_here_are_not_in_the_everyday_set():
    data = tomllib.loads(Path(__file__).with_name("everyday.toml").read_text("utf-8"))
    assert not {row["text"].lower() for row in data["phrase"]} & {p.lower() for p in PHRASES}


@pytest.mark.parametrize("text", PHRASES[:4])
def test_an_origin_word_keeps_the_look_of_its_noun_and_says_so(text):
    origin, noun = text.split(" ", 1)
    result = compiled(text)
    assert result.ok and not [d for d in result.diagnostics if d.severity.name == "WARNING"]
    assert result.materials[0]["params"] == compiled(noun).materials[0]["params"]
    assert [d.code for d in result.diagnostics] == ["N141"]
    assert f"'{origin}' does not change how" in result.diagnostics[0].message


def test_a_colour_that_starts_with_an_origin_word_is_still_the_colour():
    red = compiled("indian red paint").materials[0]["params"]["base_color"]
    assert red != compiled("red paint").materials[0]["params"]["base_color"]


def test_an_article_may_stand_before_an_inline_comparative():
    said = compiled("a much glossier walnut")
    assert said.ok
    assert said.materials[0]["params"] == compiled("much glossier walnut").materials[0]["params"]
    assert said.materials[0]["params"]["roughness"] < compiled("walnut").materials[0]["params"]["roughness"]
