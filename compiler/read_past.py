"""Words of English that say nothing cnlmc can show (issue #14): an unknown word that is a real
English word, with no lexicon word a slip away, is read past with a warning (W123) when the rest of
the line reads without it: 'a sickly chartreuse green paint' (chartreuse green paint), 'a wizard's
staff of gnarled yew' (yew), 'white enamel dial' (white enamel). The warning names the word, so
nothing is dropped silently; the material is made from the words cnlmc knows.

Never read past, so the error (E001, with its "did you mean") stands:
- a word that is no English word (`stdlib/data/english_words.txt`, WordNet 3.0, by
  scripts/gen_english_words.py; its regular inflections taken off here): 'PETG', 'xyzzy' — a
  product name or a slip;
- a word a slip away from a lexicon word ('heat': hat, seat, wheat): it may be that word mistyped;
- a comparative or superlative ('tighter weave'): a change the person asked for;
- more than MAX_PASSED words of a line: too little of it would be read to be what was meant;
- a line whose other errors are not unknown words, or whose material is not named by a word
  left on it ('glossy guitar' stays an error: not glossy paint).
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from functools import lru_cache

from .diagnostics import Diagnostic, Severity
from .word_formation_rules import wordnet_file

__all__ = ["english", "passable_words"]

WORDS_FILE = "english_words.txt"
CODE = "W123"
MAX_PASSED = 2  # our choice: a line with more words cnlmc does not know is not read as it was meant

#: regular endings taken off to find a word's base: (ending, what replaces it)
_ENDINGS = (
    ("ies", "y"),
    ("ied", "y"),
    ("es", ""),
    ("s", ""),
    ("ed", ""),
    ("ed", "e"),
    ("ing", ""),
    ("ing", "e"),
    ("ily", "y"),
    ("ly", ""),
)
_COMPARING = ("er", "est", "ier", "iest")


@lru_cache(maxsize=1)
def _words() -> frozenset[str]:
    lines = wordnet_file(WORDS_FILE).read_text("utf-8").splitlines()
    return frozenset(line for line in lines if line and not line.startswith("#"))


def english(word: str) -> bool:
    """Whether `word` (any case) is a word of English: a WordNet lemma or a regular inflection of
    one ('gnarled', 'sides', 'retaining'), every part of a hyphenated word so ('saddle-like')."""
    low = word.lower()
    if "-" in low.strip("-"):
        return all(english(part) for part in low.split("-") if part)
    return low in _words() or any(_base(low, end, to) in _words() for end, to in _ENDINGS if low.endswith(end))


def _base(word: str, ending: str, replacement: str) -> str:
    stem = word[: -len(ending)] + replacement
    if len(stem) > 3 and stem[-1] == stem[-2] and not replacement and ending in ("ed", "ing"):
        return stem[:-1]  # 'chipped' -> 'chip'
    return stem


def _comparing(word: str) -> bool:
    """'tighter', 'glossiest': a comparative or superlative (an -er / -est word that is not itself
    a lemma: the word list holds no adjective's irregular forms, so 'springier' is not one)."""
    low = word.lower()
    return any(low.endswith(end) and len(low) > len(end) + 2 for end in _COMPARING) and low not in _words()


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
        if diag.code != "E001" or not word or not english(word) or _comparing(word) or near(word.lower()):
            return None
    return list(errors)


def warning(diag: Diagnostic, word: str) -> Diagnostic:
    """The W123 that replaces an unknown word's E001, keeping its "did you mean"."""
    message = f"'{word}' is a word cnlmc does not know: read past, the material is made without it"
    return Diagnostic(diag.span, Severity.WARNING, CODE, message, diag.hints, diag.suggestions)
