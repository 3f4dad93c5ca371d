"""Package C of #14: the syntax of inline comparatives, adverbs on refinement words, clauses.

Phrases here are deliberately not the ones of tests/language/everyday.toml.
"""

import pytest

from cnlmc import ast
from cnlmc.document import parse_document


def parse(text, lexicon):
    doc = parse_document(text, lexicon, "test.cnl")
    assert not [d for d in doc.diagnostics if d.is_error], [d.message for d in doc.diagnostics]
    (item,) = doc.items
    return item


def target_text(item):
    target = item.target
    if target is None:
        return None
    return " ".join(w.text for w in target.words) if isinstance(target, ast.Colour) else target.text


@pytest.mark.parametrize(
    "text,adverbs,word",
    [
        ("slightly duller", ["slightly"], "duller"),
        ("a little glossier", ["a little"], "glossier"),
        ("very slightly rougher", ["very", "slightly"], "rougher"),
    ],
)
def test_adverbs_before_a_refinement_word(stdlib, text, adverbs, word):
    item = parse(text, stdlib)
    assert isinstance(item, ast.Refinement)
    (refine,) = item.items
    assert refine.word.text == word
    assert [a.text for a in refine.adverbs] == adverbs


def test_adverbs_on_each_item_of_a_refinement_list(stdlib):
    item = parse("slightly darker, heavily rougher", stdlib)
    assert isinstance(item, ast.Refinement)
    assert [(r.word.text, [a.text for a in r.adverbs]) for r in item.items] == [
        ("darker", ["slightly"]),
        ("rougher", ["heavily"]),
    ]


@pytest.mark.parametrize(
    "text,word,target,adverbs,nouns,group_words",
    [
        ("smoother granite", "smoother", None, [], ["granite"], []),
        ("slightly duller copper", "duller", None, ["slightly"], ["copper"], []),
        ("less rough concrete", "less", "rough", [], ["concrete"], []),
        ("more polished brass", "more", "polished", [], ["brass"], []),
        ("darker green velvet", "darker", "green", [], ["velvet"], []),
        ("less shiny lightly brushed steel", "less", "shiny", [], ["steel"], ["lightly", "brushed"]),
        ("more grain oak", "more", "grain", [], ["oak"], []),
    ],
)
def test_inline_comparative_before_a_material(stdlib, text, word, target, adverbs, nouns, group_words):
    item = parse(text, stdlib)
    assert isinstance(item, ast.Material)
    (refine,) = item.refinements
    assert refine.word.text == word
    assert target_text(refine) == target
    assert [a.text for a in refine.adverbs] == adverbs
    assert [n.text for n in item.nouns] == nouns
    words = [
        w.text for g in item.groups for w in g.adverbs + tuple(x for c in g.colours for x in c.words) + g.adjectives
    ]
    assert words == group_words


def test_a_material_without_comparative_has_no_refinements(stdlib):
    item = parse("lightly brushed, blue anodized aluminum with a clear coat", stdlib)
    assert isinstance(item, ast.Material)
    assert item.refinements == ()


def test_inline_comparative_keeps_the_coat(stdlib):
    item = parse("darker oak with a glossy varnish", stdlib)
    assert [r.word.text for r in item.refinements] == ["darker"]
    assert item.coat is not None and item.coat.coat.text == "varnish"


def test_inline_comparative_compiles(compile_text):
    result = compile_text("smoother granite\nrougher\n")
    assert result.ok, [d.message for d in result.diagnostics]


def test_a_list_of_comparatives_before_a_material_is_refused_with_a_hint(compile_text):
    (d,) = compile_text("lighter, smoother granite").diagnostics
    assert d.code == "E002"
    assert "one comparative may stand before the material" in d.message
    assert d.hints and "next line" in d.hints[0]


def test_refinement_after_the_noun_still_says_where_it_goes(compile_text):
    (d,) = compile_text("polished granite darker").diagnostics
    assert d.message == "a refinement changes the material above it and stands on its own line"


def test_shape_cache_keeps_adverbs_apart(stdlib):
    """Two lines with the same tags share a parse shape; each builds from its own words."""
    first = parse("slightly darker", stdlib)
    second = parse("heavily rougher", stdlib)
    assert [a.text for a in first.items[0].adverbs] == ["slightly"]
    assert [a.text for a in second.items[0].adverbs] == ["heavily"]
    assert second.items[0].word.text == "rougher"


def test_a_line_that_ends_in_a_noun_reads_as_a_material(stdlib):
    """'copper' is a colour and a noun: before a noun reading, the refinement reading loses."""
    item = parse("a bit duller silver", stdlib)
    assert isinstance(item, ast.Material)
    assert [n.key for n in item.nouns] == ["silver"]
    assert [r.word.text for r in item.refinements] == ["duller"]


def test_a_refinement_of_a_colour_stays_a_refinement(stdlib):
    item = parse("darker navy", stdlib)
    assert isinstance(item, ast.Refinement)


def test_the_coat_clause_span_starts_at_with(stdlib):
    item = parse("walnut with a satin lacquer", stdlib)
    assert item.coat is not None
    assert item.text[item.coat.span.start : item.coat.span.end] == "with a satin lacquer"
