"""The shortcuts taken for speed give exactly what the plain path gives.

Parse shapes are cached by terminal sequence and later compiled to a function; IR numbers
are rounded by a fast path; a noun's optics are rounded once per lexicon list.
"""

import math
import random

import pytest

from cnlmc import parser
from cnlmc.api import compile_source, lexicon_for
from cnlmc.document import parse_document
from cnlmc.formulas import round6, rounded
from cnlmc.parser import ParseFailure, clear_shape_cache, parse_line_shape, parse_tagged
from cnlmc.syntax import PROMOTE_AFTER
from cnlmc.tagger import Tagger


@pytest.fixture(scope="module")
def lexicon():
    return lexicon_for()


def _words(lexicon, line):
    tagged, _ = Tagger(lexicon).tag_line(line, 1, 0)
    return [t for t in tagged if t.candidates]


def test_one_shape_serves_lines_with_the_same_tags(lexicon):
    clear_shape_cache()
    first = parse_document("blue anodized aluminum", lexicon).items[0]
    second = parse_document("red brushed steel", lexicon).items[0]
    assert [w.text for w in second.groups[0].colours[0].words] == ["red"]
    assert [w.text for w in second.groups[0].adjectives] == ["brushed"]
    assert second.nouns[0].text == "steel" and second.span.end == len("red brushed steel")
    assert first.nouns[0].text == "aluminum"


def test_compiled_shape_builds_what_the_closures_build(lexicon):
    lines = [
        "hull: lightly brushed, blue anodized aluminum",
        "oak with a glossy white varnish",
        "red or blue anodized aluminum",
        "darker blue, less diffuse",
        "pale dark slate gray plastic",
    ]
    for line in lines:
        clear_shape_cache()
        words = _words(lexicon, line)
        shape, picks = parse_line_shape(words)
        before = shape.build(words, picks, line)
        for _ in range(PROMOTE_AFTER + 1):
            shape, picks = parse_line_shape(words)
            after = shape.build(words, picks, line)
        assert after == before, line
        assert shape.build.__name__ == "build"  # compiled by now


def test_ambiguous_words_keep_their_choice_through_the_cache(lexicon):
    clear_shape_cache()
    for _ in range(3):
        item = parse_document("gold plated steel", lexicon).items[0]
        assert item.groups[0].colours[0].base.key == "gold" and item.nouns[0].key == "steel"
        item = parse_document("polished gold", lexicon).items[0]
        assert item.nouns[0].key == "gold"


def test_failures_are_not_cached(lexicon):
    clear_shape_cache()
    words = _words(lexicon, "aluminum brushed")
    for _ in range(2):
        with pytest.raises(ParseFailure):
            parse_line_shape(words)
    with pytest.raises(ParseFailure):
        parse_tagged(words)
    assert not parser._shapes


def test_cached_and_uncached_compiles_agree(lexicon):
    text = "lightly brushed, blue anodized aluminum\ndarker blue\nwhite varnished oak\nmore grain"
    clear_shape_cache()
    cold = compile_source(text, "a.cnl", lexicon).ir
    for _ in range(PROMOTE_AFTER + 2):
        warm = compile_source(text, "a.cnl", lexicon).ir
    assert warm == cold


def test_round6_is_round_to_6_digits():
    rng = random.Random(11)
    values = [0.0, -0.0, 5e-7, -5e-7, 2.5e-6, 0.165, 1e300, -1e-300, math.inf, -math.inf]
    for _ in range(20000):
        k = rng.randint(-(10**8), 10**8)
        values += [
            rng.uniform(-3, 3),
            k / 1e6,
            (k + 0.5) / 1e6,
            math.nextafter((k + 0.5) / 1e6, 0.0),
            rng.uniform(-1e7, 1e7),
        ]
    for x in values:
        expected = round(x, 6) or 0.0
        assert round6(x) == expected and math.copysign(1, round6(x)) == math.copysign(1, expected), x
    assert math.isnan(round6(math.nan))
    assert rounded([0.1234565, -1e-9, "x", [2.0000004]]) == [round(0.1234565, 6), 0.0, "x", [2.0]]
    assert rounded({"a": 1.23456789}, 3) == {"a": 1.235}


def test_lexicon_optics_are_copied_into_each_ir(lexicon):
    first = compile_source("aluminum", "a", lexicon).materials[0]["params"]
    first["eta"][0] = -1.0
    second = compile_source("aluminum", "a", lexicon).materials[0]["params"]
    assert second["eta"][0] != -1.0
