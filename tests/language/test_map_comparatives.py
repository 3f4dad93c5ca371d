"""Comparatives and negated degrees on map-driven qualities (issue #14, category 3).

'rustier', 'less rusty', 'more veined', 'fewer speckles', 'less grain' change the map graph's
parameter (coverage, scale, contrast, grain) and cnlmc.changes reports it as a change; an inline
comparative before a material with no such map adds a little of the quality
(passes/refine_missing_map.py: 'rustier iron' = slightly rusty iron, a note); 'not X at all', 'not at
all X' read as 'not X'; 'hardly any', 'barely any', 'almost no' are a trace of a feature. No phrase
here is in tests/language/everyday.toml.
"""

import pytest

from cnlmc.api import Session, compile_source, lexicon_for
from cnlmc.changes import material_changes
from cnlmc.diagnostics import Severity
from cnlmc.graphs import graph_params
from cnlmc.lexicon import load_lexicon

from .conftest import look


@pytest.fixture(scope="module")
def lexicon():
    return load_lexicon()


@pytest.mark.parametrize(
    ("text", "meaning"),
    [
        ("rustier cast iron", "slightly rusty cast iron"),
        ("rustier wrought iron", "slightly rusty wrought iron"),
        ("a bit rustier steel", "barely rusty steel"),
        ("much rustier iron", "rusty iron"),
    ],
)
def test_an_inline_comparative_adds_a_missing_map(lexicon, text, meaning):
    result, got = look(lexicon, text)
    _plain, expected = look(lexicon, meaning)
    assert got == expected, (text, meaning)
    assert "rust" in {ref["graph"] for ref in got["maps"].values()}


def test_the_inline_reading_says_so_in_a_note(lexicon):
    result, _got = look(lexicon, "rustier iron")
    (said,) = [d for d in result.diagnostics if d.code == "N104"]
    assert said.severity is Severity.NOTE and "'rusty'" in said.message


def test_a_comparative_whose_map_no_word_draws_alone_still_warns(lexicon):
    """'bumpier plastic': brushed, hammered and sandblasted all weigh 'strength': no guess, W106."""
    result = compile_source("bumpier plastic", "mc.cnl", lexicon)
    assert any(d.code == "W106" for d in result.diagnostics)


def map_param(material, graph, name):
    """The parameter of the material's map of `graph`, its graph default when the map does not set it."""
    default = graph_params(graph)[name][2]
    return next(ref["params"].get(name, default) for ref in material["maps"].values() if ref["graph"] == graph)


@pytest.mark.parametrize(
    ("first", "line", "graph", "param", "way"),
    [
        ("rusty steel", "rustier", "rust", "coverage", 1),
        ("rusty cast iron", "less rust", "rust", "coverage", -1),
        ("rusty iron", "less rusty", "rust", "coverage", -1),
        ("white marble", "more veined", "marble", "scale", 1),
        ("carrara marble", "fewer veins", "marble", "scale", -1),
        ("black granite", "more speckles", "granite", "contrast", 1),
        ("granite", "fewer speckles", "granite", "contrast", -1),
        ("walnut", "less grain", "wood", "grain", -1),
        ("maple", "more grain", "wood", "grain", 1),
        ("oak", "grainier", "wood", "grain", 1),
        ("oak", "more grainy", "wood", "grain", 1),
        ("walnut", "less grainy", "wood", "grain", -1),
    ],
)
def test_a_map_refinement_moves_the_graph_parameter_and_is_reported(lexicon, first, line, graph, param, way):
    session = Session(first, lexicon)
    before = session.material
    after = session.refine(line)
    old, new = map_param(before, graph, param), map_param(after, graph, param)
    assert (new - old) * way > 0, (first, line, old, new)
    rows = material_changes(before, after)
    assert any(f".{param}" in row for row in rows), rows
    assert not [d for d in session.result.diagnostics if d.severity is Severity.WARNING]


@pytest.mark.parametrize(
    ("text", "meaning"),
    [
        ("not rusty at all iron", "iron"),
        ("not at all glossy ceramic", "matte ceramic"),
        ("not glossy at all paint", "matte paint"),
        ("not shiny in the least brass", "dull brass"),
        ("not polished one bit marble", "rough marble"),
        ("not very glossy plastic", "satin plastic"),  # the finish between: never glossier than plastic is
    ],
)
def test_negated_degrees(lexicon, text, meaning):
    result, got = look(lexicon, text)
    _plain, expected = look(lexicon, meaning)
    assert got == expected, (text, meaning)
    assert any(d.code == "N101" for d in result.diagnostics)


@pytest.mark.parametrize(
    ("text", "full", "graph", "param"),
    [
        ("iron with hardly any rust", "iron with rust", "rust", "coverage"),
        ("steel with barely any scratches", "steel with scratches", "scratched", "strength"),
        ("marble with almost no veins", "marble with veins", "marble", "contrast"),
        ("granite with scarcely any speckles", "granite with speckles", "granite", "contrast"),
    ],
)
def test_hardly_any_is_a_trace(lexicon, text, full, graph, param):
    _result, got = look(lexicon, text)
    _plain, plain = look(lexicon, full)
    assert 0 < map_param(got, graph, param) <= 0.3 * map_param(plain, graph, param), text


def test_german_comparative_with_an_ending_adds_a_missing_map():
    de = lexicon_for(["de"])
    _r, got = look(de, "rostigeres Eisen")
    _r2, expected = look(de, "leicht rostiges Eisen")
    assert got == expected


@pytest.mark.parametrize("noun", ["oak", "walnut", "ash"])
def test_a_describing_word_on_the_nouns_own_graph_keeps_the_nouns_parameters(noun):
    """'fine-grained oak' is oak's own wood map with a finer grain: the adjective's parameters are
    set, the noun's (its grain, its colour variation) kept."""
    plain = compile_source(noun, "<t>").ir["materials"][0]["maps"]["base_color"]
    fine = compile_source(f"fine-grained {noun}", "<t>").ir["materials"][0]["maps"]["base_color"]
    assert fine["graph"] == plain["graph"] == "wood"
    said = {"scale", "ring_scale"}  # what 'fine-grained' sets (adjectives_participles.toml)
    kept = {k: v for k, v in plain["params"].items() if k not in said}
    assert kept and {k: fine["params"].get(k) for k in kept} == kept
    assert fine["params"]["scale"] > plain["params"].get("scale", 1.0)
