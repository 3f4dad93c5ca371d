"""The per-lexicon memos of the hot path (LexiconCaches.noun_plans, pattern_colours; #13 speed)
change no output: a phrase compiled after many others gives the IR it gives with the memos empty."""

from __future__ import annotations

import random

from cnlmc.api import compile_source, lexicon_for
from cnlmc.ir import json_text
from cnlmc.lexicon import LexiconCaches

NOUNS = ("granite", "marble", "oak", "walnut", "brick", "leather", "steel", "plastic", "velvet", "copper")
COLOURS = ("black", "white", "red", "dark blue", "pale green", "bright orange", "grey", "cobalt blue")


def _ir_text(phrase: str) -> str:
    return json_text(compile_source(phrase, "<memo>", lexicon_for()).ir)


def _with_empty_memos(phrase: str) -> str:
    caches = lexicon_for().caches
    caches.noun_plans.clear()
    caches.pattern_colours.clear()
    return _ir_text(phrase)


def test_a_warm_lexicon_compiles_as_a_fresh_one() -> None:
    phrases = [f"{colour} {noun}" for noun in NOUNS for colour in COLOURS] + list(NOUNS)
    phrases += ["varnished oak", "black marble with white veins", "red or blue granite"]
    expected = {phrase: _with_empty_memos(phrase) for phrase in phrases}
    random.Random(3).shuffle(phrases)
    warm = {phrase: _ir_text(phrase) for phrase in phrases}  # each after others filled the memos
    assert warm == expected
    caches = lexicon_for().caches
    assert caches.noun_plans and caches.pattern_colours  # the memos were used


def test_the_memos_stay_bounded() -> None:
    caches = lexicon_for().caches
    caches.pattern_colours.clear()
    for n in range(LexiconCaches.MAX_ENTRIES):
        caches.pattern_colours[(float(n),), "x"] = None
    _ir_text("black granite")  # a look-up that misses starts the full memo over
    assert len(caches.pattern_colours) <= LexiconCaches.MAX_ENTRIES
    caches.pattern_colours.clear()
