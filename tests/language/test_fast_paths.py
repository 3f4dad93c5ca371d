"""The shortcuts taken for speed give exactly what the plain path gives.

Parse shapes are cached by terminal sequence (a shape read from one line builds the AST of
any line whose words carry the same tags); IR numbers are rounded by a fast path; a noun's
optics are rounded once per lexicon list.
"""

import math
import random

import pytest

from cnlmc.api import compile_source, lexicon_for
from cnlmc.document import parse_document
from cnlmc.formulas import round6, rounded
from cnlmc.parser import ParseFailure, parse_line_shape, parse_tagged
from cnlmc.passes.variants import NON_WORD, ascii_fold, identifier
from cnlmc.syntax import ShapeCache
from cnlmc.tagger import MEMO_SIZE, Tagger


@pytest.fixture(scope="module")
def lexicon():
    return lexicon_for()


def _words(lexicon, line):
    tagged, _ = Tagger(lexicon).tag_line(line, 1, 0)
    return [t for t in tagged if t.candidates]


def _fresh_build(lexicon, line):
    """The plain path: parse this very line (an empty cache) and build its AST."""
    words = _words(lexicon, line)
    shape, picks = parse_line_shape(words, ShapeCache())
    return shape.build(words, picks, line)


def test_one_shape_serves_lines_with_the_same_tags(lexicon):
    lexicon.caches.shapes.clear()
    first = parse_document("blue anodized aluminum", lexicon).items[0]
    second = parse_document("red brushed steel", lexicon).items[0]
    assert len(lexicon.caches.shapes) == 1
    assert [w.text for w in second.groups[0].colours[0].words] == ["red"]
    assert [w.text for w in second.groups[0].adjectives] == ["brushed"]
    assert second.nouns[0].text == "steel" and second.span.end == len("red brushed steel")
    assert first.nouns[0].text == "aluminum"


@pytest.mark.parametrize(
    "seen, line",
    [
        ("hull: lightly brushed, blue anodized aluminum", "deck: heavily polished, red brushed steel"),
        ("oak with a glossy white varnish", "pine with a matte black varnish"),
        ("red or blue anodized aluminum", "green or white brushed steel"),
        ("darker blue, less diffuse", "lighter red, more diffuse"),
        ("pale dark slate gray plastic", "light dark slate gray rubber"),
        ("dark pale slate gray rubber", "light deep navy blue rubber"),
        ("gold plated steel", "gold plated steel"),
    ],
)
def test_a_cached_shape_builds_what_a_fresh_parse_builds(lexicon, seen, line):
    shapes = ShapeCache()
    parse_line_shape(_words(lexicon, seen), shapes)
    words = _words(lexicon, line)
    shape, picks = parse_line_shape(words, shapes)
    assert len(shapes) == 1, "the second line has the first line's tags"
    built = shape.build(words, picks, line)
    assert built == _fresh_build(lexicon, line)
    assert shape.build(words, picks, line) == built  # a shape is used again unchanged


def test_ambiguous_words_keep_their_choice_through_the_cache(lexicon):
    lexicon.caches.shapes.clear()
    for _ in range(3):
        item = parse_document("gold plated steel", lexicon).items[0]
        assert item.groups[0].colours[0].base.key == "gold" and item.nouns[0].key == "steel"
        item = parse_document("polished gold", lexicon).items[0]
        assert item.nouns[0].key == "gold"


def test_failures_are_not_cached(lexicon):
    shapes = ShapeCache()
    words = _words(lexicon, "aluminum brushed")
    for _ in range(2):
        with pytest.raises(ParseFailure):
            parse_line_shape(words, shapes)
    with pytest.raises(ParseFailure):
        parse_tagged(words)
    assert len(shapes) == 0


def test_cached_and_uncached_compiles_agree(lexicon, monkeypatch):
    text = "lightly brushed, blue anodized aluminum\ndarker blue\nwhite varnished oak\nmore grain"
    monkeypatch.setattr(lexicon.caches.shapes, "persistent", False)  # cold: parsed, not recalled from stored shapes
    lexicon.caches.shapes.clear()
    cold = compile_source(text, "a.cnl", lexicon).ir
    for _ in range(3):
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


def test_identifier_shortcut_is_the_general_rule():
    def general(text):
        name = NON_WORD.sub("_", ascii_fold(text).strip().lower()).strip("_") or "material"
        return "m_" + name if name[0].isdigit() else name

    rng = random.Random(5)
    texts = ["anodized aluminum", "Brushed  Steel", " x ", "_a", "a_", "1abc", "", "red_blue", "gebürstetes Weiß"]
    texts += ["".join(rng.choice("aZ _-9ßé\t.'") for _ in range(rng.randint(0, 8))) for _ in range(20000)]
    for text in texts:
        assert identifier(text) == general(text), repr(text)


def test_the_tagger_memo_is_bounded_least_recently_used_first(lexicon):
    """#13: the language server kept 2.83 GB after 40 documents of unknown words (the memo grew forever)."""
    tagger = Tagger(lexicon, memo_size=50)
    tagger.tag_line("polished brass", 1, 0)
    for n in range(300):
        tagger.tag_line(f"zq{n}x brass", 1, 0)  # a new unknown word each line; 'brass' stays in use
    assert len(tagger.memo) == 50
    assert ("brass",) in tagger.memo  # used on every line: kept
    assert ("polished",) not in tagger.memo  # not used since the start: evicted
    assert ("zq0x",) not in tagger.memo and ("zq299x",) in tagger.memo
    words, _ = tagger.tag_line("polished brass", 1, 0)
    assert [c.tag for c in words[0].candidates] == ["ADJ"]  # evicted words are simply looked up again


def test_documents_share_the_lexicons_tagger(lexicon):
    parse_document("polished brass", lexicon)
    tagger = Tagger.of(lexicon)
    assert Tagger.of(lexicon) is tagger
    assert ("brass",) in tagger.memo
    assert tagger.memo.limit == MEMO_SIZE
