"""The block-by-block analysis gives exactly what compiling the whole text gives."""

from __future__ import annotations

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from cnlmc.api import compile_source, lexicon_for
from cnlmc.lsp.incremental import Analyzer
from cnlmc.lsp.positions import LineIndex, chars_for_units, code_units

pytestmark = pytest.mark.lsp

LINES = [
    "lightly brushed, blue anodized aluminum",
    "darker blue",
    "less diffuse",
    "",
    "# a comment",
    "deck: white varnished oak",
    "polished brushed steel",
    "anodized oak",
    "blu plastic",
    "lightly aluminum",
    "red or green plastic",
    "darker",
    "rougher",
    "plastic brushed",
    "with a clear coat",
    "😀 bleu steel",
    "hull: dark slate blue plastic with a clear coat",
    "gold plated steel",
    "very",
    "mirror polished brass",
    "zorblat quimble",
    "darker zorblat",
    "blorpy steel",
]
LEXICON = lexicon_for()
ANALYZER = Analyzer(LEXICON, "test.cnl")


def summary(diags):
    return [(d.code, d.span, d.message) for d in diags]


@settings(max_examples=60, deadline=None)
@given(st.lists(st.sampled_from(LINES), max_size=25))
def test_blocks_equal_the_whole_document(lines):
    text = "\n".join(lines)
    whole = compile_source(text, "test.cnl", LEXICON)
    snap = ANALYZER.analyse(text)
    with_span = [d for d in whole.diagnostics if d.span is not None]
    assert summary([d for d in snap.diagnostics if d.code != "W108"]) == summary(
        [d for d in with_span if d.code != "W108"]
    )
    assert sorted(m["phrase"] for b in snap.blocks for m in b.result.materials) == sorted(
        m["phrase"] for m in whole.materials
    )


def test_materials_are_found_by_line():
    snap = ANALYZER.analyse("# head\nblue plastic\ndarker\n\nred steel")
    assert [m["phrase"] for m in snap.materials_on(1)] == ["blue plastic"]
    assert snap.materials_on(2) == [] and snap.materials_on(0) == []
    assert [m["phrase"] for m in snap.materials_on(4)] == ["red steel"]


def test_code_units():
    assert code_units("😀 a", "utf-16") == 4
    assert code_units("😀 a", "utf-8") == 6
    assert code_units("😀 a", "utf-32") == 3
    assert chars_for_units("😀 blu", 3, "utf-16") == 2
    assert chars_for_units("木材 x", 99, "utf-16") == 4


def test_line_index_positions():
    index = LineIndex("ab\r\n😀 cd\nx", "utf-16")
    assert index.lines == ["ab", "😀 cd", "x"]
    offset = index.starts[1] + 2  # 'c'
    assert (index.position(offset).line, index.position(offset).character) == (1, 3)
    assert index.line_col(index.position(offset)) == (1, 2)
    assert index.line_col(index.position(10**6)) == (2, 1)
