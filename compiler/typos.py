"""Slips of the keyboard (issue #14): an unknown word a slip or two away from exactly one word of
the lexicon is read as that word, with a note ('brushd alu', 'stainles steel', 'carara marble').

A slip is an edit of optimal string alignment (insert, delete, substitute, swap two neighbours),
measured by the 'did you mean' index (cnlmc.suggest.FormIndex) over the lexicon's words (every word
of every surface form). The word formation rules say how far a slip reaches ([typos] `reach`: a
word of at least `letters` letters may be `edits` slips away; stricter than 'did you mean', since a
reading is applied where a suggestion is only offered). Never read as a slip:

- a word with anything but letters, or shorter than the reach's first step;
- a real English word the lexicon lacks ([typos] `file`, stdlib/data/real_words.txt, from WordNet
  3.0 by scripts/gen_real_words.py): 'mate' is a word, not a mistyped 'matte';
- a word with two lexicon words equally near that name different things and both end as it does
  ('chrom': chrome or chroma) — it stays an error, with both offered.

A word spelt as it sounds, its consonants in place and only vowels changed, reaches further
([typos] `vowels`: from `letters` letters, up to `edits` vowels): 'mahagony' is mahogany, two
substitutions, where an edit reach would allow one (our choice: a vowel heard but not seen is
the commonest spelling slip of long words; the consonant frame keeps the reading unambiguous).

Only the tagger's unknown words come here (the last word formation rule, and inside an entry of
several words: cnlmc.word_formation.WordFormation.heard), so the hot path of known words never does.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable, Mapping, Sequence
from functools import lru_cache

from .suggest import FormIndex
from .word_formation_rules import wordnet_file

__all__ = ["Slips", "real_words"]

_WORD = "word"  # the one category of the index of words


class Slips:
    """The lexicon's words indexed for slips, the real words to leave alone, and the reach."""

    def __init__(
        self,
        vocabulary: Iterable[str],
        real: frozenset[str],
        reach: Sequence[Mapping[str, int]] = (),
        vowels: Mapping[str, int] | None = None,
    ) -> None:
        words = [word for word in vocabulary if word.isalpha()]
        self.index = FormIndex(dict.fromkeys(words, (_WORD,)))
        self.real = real
        self.reach = sorted(((step["letters"], step["edits"]) for step in reach or _DEFAULT_REACH), reverse=True)
        self.vowels = dict(vowels or _DEFAULT_VOWELS)
        self.frames: dict[str, list[str]] = {}
        for word in words:
            self.frames.setdefault(consonant_frame(word), []).append(word)

    def edits_allowed(self, word: str, extra: int = 0) -> int:
        """How many slips a word of this length may hold (0: none is read), with `extra` more for
        a word of ENTRY_EXTRA_LETTERS or more."""
        edits = next((edits for letters, edits in self.reach if len(word) >= letters), 0)
        return edits + extra if edits and len(word) >= ENTRY_EXTRA_LETTERS else edits

    def near(self, word: str) -> list[tuple[int, str]]:
        """(slips, lexicon word) of every lexicon word within the reach of `word`, fewest first;
        when none is, the words it differs from in vowels only, within the vowel reach."""
        low = word.lower()
        allowed = self.edits_allowed(low)
        if not allowed or not low.isalpha():
            return []
        found = sorted((edits, form) for edits, form in self.index.typos(low) if edits <= allowed)
        return found or self.vowels_apart(low)

    def vowels_apart(self, low: str) -> list[tuple[int, str]]:
        """(vowels changed, lexicon word) of the words with `low`'s consonant frame, within the
        vowel reach (see the module doc); [] for a word shorter than its `letters`."""
        if len(low) < self.vowels["letters"]:
            return []
        found = []
        for form in self.frames.get(consonant_frame(low), ()):
            changed = sum(a != b for a, b in zip(low, form))
            if 0 < changed <= self.vowels["edits"]:
                found.append((changed, form))
        return sorted(found)

    def within_reach(self, word: str) -> bool:
        """Whether some lexicon word is within a slip's reach (scripts/gen_real_words.py)."""
        return bool(self.near(word))

    def meant(self, word: str, same: Callable[[str, str], bool]) -> str | None:
        """The one lexicon word `word` is a slip of, or None (see the module doc). Of the words
        fewest slips away, those that `same` says name the same entries count as one ('alumnium':
        aluminium or aluminum); else the one that ends as the word does ('brushd': brushed, not
        brush); else none."""
        low = word.lower()
        if low in self.real:
            return None
        found = self.near(low)
        if not found:
            return None
        fewest = [form for edits, form in found if edits == found[0][0]]
        if all(same(fewest[0], other) for other in fewest[1:]):
            return fewest[0]
        ending = [form for form in fewest if form[-1] == low[-1]]
        return ending[0] if len(ending) == 1 else None

    def meant_among(self, word: str, forms: Sequence[str], extra: int = 0, shortest: int = 0) -> str | None:
        """The one of `forms` that `word` is fewest slips from, within the reach plus `extra` (for a
        word of ENTRY_EXTRA_LETTERS or more), or None (none there, two equally near, a real word).
        `shortest`: a word of that many letters or more holds one slip at least (the words around
        it confirm the entry)."""
        low = word.lower()
        allowed = self.edits_allowed(low, extra)
        if shortest and len(low) >= shortest:
            allowed = max(allowed, 1)
        if not allowed or not low.isalpha() or low in self.real or not forms:
            return None
        from rapidfuzz import process  # only needed when a word is unknown
        from rapidfuzz.distance import OSA

        found = sorted(
            (int(d), form)
            for form, d, _at in process.extract(low, forms, scorer=OSA.distance, score_cutoff=allowed, limit=None)
        )
        fewest = [form for edits, form in found if edits == found[0][0]] if found else []
        return fewest[0] if len(fewest) == 1 else None


#: the fewest letters of a word that may hold one slip more where the entry's next word confirms it
#: ('stainls steel'; our choice: shorter words are too often real words two slips from another)
ENTRY_EXTRA_LETTERS = 7

#: the reach when none is given: one slip from 5 letters, two from 10 (the stdlib rules')
_DEFAULT_REACH = ({"letters": 5, "edits": 1}, {"letters": 10, "edits": 2})

#: the vowel reach when none is given: two vowels from 7 letters (the stdlib rules')
_DEFAULT_VOWELS = {"letters": 7, "edits": 2}

_VOWELS = frozenset("aeiouy")


def consonant_frame(word: str) -> str:
    """The word with each vowel (y counted as one) replaced by '*': 'mahagony' -> 'm*h*g*n**'."""
    return "".join("*" if ch in _VOWELS else ch for ch in word)


@lru_cache(maxsize=4)
def real_words(name: str) -> frozenset[str]:
    """The real words of a stdlib/data file ('' : none; one word a line, '#' a comment line), read
    once per process."""
    if not name:
        return frozenset()
    lines = wordnet_file(name).read_text("utf-8").splitlines()
    return frozenset(line for line in lines if line and not line.startswith("#"))
