"""Nouns of English that say nothing cnlmc can show (issue #14): an unknown word that is a noun of
English and nothing else (a thing, a place, a context), with no lexicon word a slip away, is read
past with a warning (W123) when the rest of the line reads without it: 'mirrored aviator lenses'
(mirrored glass), 'wasteland scrap metal', 'a galaxy black PLA'. The warning names the word, so
nothing is dropped silently; the material is made from the words cnlmc knows.

Never read past, so the error (E001, with its "did you mean") stands:
- a word that is no English noun (`stdlib/data/english_nouns.txt`, WordNet 3.0, by
  scripts/gen_english_nouns.py; regular plurals taken off here): 'PETG', 'xyzzy' — a product name
  or a slip; an adjective or adverb ('mottled', 'lackluster', 'insufficiently', 'sickly'), which
  likely says how it looks, and a participle ('reddened'), which likely says what was done to it;
- a word a slip away from a lexicon word ('heat': hat, seat, wheat): it may be that word mistyped;
- more than MAX_PASSED words of a line: too little of it would be read to be what was meant;
- a line whose other errors are not unknown words, or whose material is not named by a word
  left on it ('glossy guitar' stays an error: not glossy paint).
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from functools import lru_cache

from .diagnostics import Diagnostic, Severity
from .word_formation_rules import wordnet_file

__all__ = ["english_noun", "passable_words"]

WORDS_FILE = "english_nouns.txt"
CODE = "W123"
MAX_PASSED = 2  # our choice: a line with more words cnlmc does not know is not read as it was meant

#: regular plural endings taken off to find a noun's base: (ending, what replaces it)
_PLURALS = (("ies", "y"), ("es", ""), ("s", ""))


@lru_cache(maxsize=1)
def _words() -> frozenset[str]:
    lines = wordnet_file(WORDS_FILE).read_text("utf-8").splitlines()
    return frozenset(line for line in lines if line and not line.startswith("#"))


def english_noun(word: str) -> bool:
    """Whether `word` (any case) is a noun of English and nothing else: a WordNet noun lemma or its
    plural ('sides', 'galaxies'), not also an adjective or adverb (see the module doc)."""
    low = word.lower()
    return low in _words() or any(low[: -len(end)] + to in _words() for end, to in _PLURALS if low.endswith(end))


def passable_words(
    errors: Sequence[Diagnostic], said: Callable[[Diagnostic], str], near: Callable[[str], bool]
) -> list[Diagnostic] | None:
    """The unknown-word errors of a line that may be read past (see the module doc), or None when
    any error of the line may not. `said(d)`: the word an error is about; `near(w)`: whether a
    lexicon word is a slip away from it."""
    if not errors or len(errors) > MAX_PASSED:
        return None
    for diag in errors:
        word = said(diag)
        if diag.code != "E001" or not word or not english_noun(word) or near(word.lower()):
            return None
    return list(errors)


def warning(diag: Diagnostic, word: str) -> Diagnostic:
    """The W123 that replaces an unknown word's E001, keeping its "did you mean"."""
    message = f"'{word}' names nothing cnlmc can show: read past, the material is made without it"
    return Diagnostic(diag.span, Severity.WARNING, CODE, message, diag.hints, diag.suggestions)
