"""Friendly syntax errors learned from grammar/bad_examples.toml.

Each example phrase is parsed once; the parser state and token type where it fails become
the key for its message. A user's error with the same key gets that message.
"""

from __future__ import annotations

from typing import Any

from .diagnostics import FailureKey, Mistake
from .lexicon import Lexicon
from .package_data import package_folder
from .parser import ParseFailure, parse_tagged
from .tagged import Tagged
from .tagger import Tagger

__all__ = ["Mistake", "known_mistake", "learn"]


def _read_table() -> list[dict[str, Any]]:
    import tomllib

    text = (package_folder("cnlmc.grammar") / "bad_examples.toml").read_text("utf-8")
    table: list[dict[str, Any]] = tomllib.loads(text)["mistake"]
    return table


def learn(lexicon: Lexicon) -> dict[FailureKey, Mistake]:
    """(state, token type) -> Mistake, from every example phrase (first example wins)."""
    tagger = Tagger(lexicon)
    table: dict[FailureKey, Mistake] = {}
    for row in _read_table():
        mistake = Mistake(row["message"], row["hint"])
        for phrase in row["phrases"]:
            key = _failure_key(tagger, phrase)
            if key is not None:
                table.setdefault(key, mistake)
    return table


def _failure_key(tagger: Tagger, phrase: str) -> FailureKey | None:
    tagged, _diags = tagger.tag_line(phrase, 1, 0)
    try:
        parse_tagged([_as_written(t) for t in tagged if t.candidates])
    except ParseFailure as failure:
        return failure.key
    return None


def _as_written(word: Tagged) -> Tagged:
    """An example's word that can be a material noun is that noun: "oak blue" shows a colour after
    the material, whether or not 'oak' also names a colour (colours.toml), so the key it teaches is
    the failure at 'blue', not the one of a line of two colours."""
    nouns = tuple(c for c in word.candidates if c.tag == "NOUN")
    return Tagged(word.text, word.span, nouns, word.unknown) if nouns else word


def known_mistake(lexicon: Lexicon, failure: ParseFailure) -> Mistake | None:
    """The learned message for this failure, if an example phrase failed the same way."""
    caches = lexicon.caches
    if caches.mistakes is None:
        caches.mistakes = learn(lexicon)
    return None if failure.key is None else caches.mistakes.get(failure.key)
