"""'Did you mean': the known forms an unknown word may be a typo of, best first.

A suggestion must be a typo of the word (a few edits, by its length: stdlib/data/teaching.toml),
the whole form that the word begins ('stainless' -> 'stainless steel'), or the known word a
compound ends in ('rubberwood' -> 'wood'). Never a word the unknown one negates or
grades with a prefix ('non-glossy' is not 'glossy', 'unpolished' is not 'polished'), and never a
far-fetched look-alike (pewter -> water, beech -> bleach: 2-3 edits on 5-7 letters).
"""

from __future__ import annotations

import re
from bisect import bisect_left
from collections import Counter, OrderedDict
from collections.abc import Iterable, Mapping, Sequence
from functools import lru_cache
from itertools import chain
from types import MappingProxyType
from typing import Any

from .package_data import package_folder

__all__ = ["FormIndex", "allowed_edits", "teaching"]

#: Words whose typos an index remembers (the tagger and then the word's slot ask for the same word;
#: our choice: a few dozen lines of words).
RECENT_WORDS = 256


@lru_cache(maxsize=1)
def teaching() -> Mapping[str, Any]:
    """stdlib/data/teaching.toml, read once per process (immutable package data), its phrases also
    without their apostrophes (with_unmarked_contractions)."""
    return MappingProxyType(with_unmarked_contractions(_teaching_file()))


@lru_cache(maxsize=1)
def _teaching_file() -> dict[str, Any]:
    """stdlib/data/teaching.toml as written."""
    import tomllib

    return tomllib.loads((package_folder("cnlmc.stdlib") / "data" / "teaching.toml").read_text("utf-8"))


APOSTROPHE = re.compile(r"(?<=\w)['’](?=\w)")


def with_unmarked_contractions(data: dict[str, Any]) -> dict[str, Any]:
    """The teaching's phrase lists with each phrase holding a contraction also as typed without its
    apostrophe ("that's gone" -> "thats gone", "what's a good" -> "whats a good"), unless that makes
    one of its [unmarked_contractions] not_words ('it's' -> 'its'): dictation and phones leave the
    mark out (the teaching's own not_words where `data` has none)."""
    table = data.get("unmarked_contractions") or _teaching_file()["unmarked_contractions"]
    unmarked: dict[str, Any] = _unmarked(data, frozenset(table["not_words"]))
    return unmarked


def _unmarked(data: Any, not_words: frozenset[str]) -> Any:
    if isinstance(data, dict):
        return {k: _unmarked(v, not_words) for k, v in data.items()}
    if not isinstance(data, list) or not all(isinstance(x, str) for x in data):
        return data
    extra = [APOSTROPHE.sub("", x) for x in data if APOSTROPHE.search(x)]
    seen = set(data)
    return data + [x for x in dict.fromkeys(extra) if x not in seen and x not in not_words]


def everyday_noun() -> str:
    """The everyday noun colours and finishes go on when no material is named: the first of
    teaching.toml [completions] nouns (paint)."""
    return str(teaching()["completions"]["nouns"][0])


def allowed_edits(word: str) -> int:
    """How many edits a typo of `word` may have (teaching.toml's typo_edits, by its length)."""
    edits = 0
    for step in teaching()["typo_edits"]:
        if len(word) >= step["letters"]:
            edits = step["edits"]
    return edits


class FormIndex:
    """Every surface form of one lexicon with its categories, indexed for 'did you mean'; made
    once per lexicon on its first unknown word and kept with it (lexicon.caches.suggestion_index).

    A typo is a form within `allowed_edits(word)` edits of optimal string alignment (OSA: insert,
    delete, substitute, swap two neighbours). Rather than measuring the distance to every form,
    a filter that never drops a form within reach picks the few candidates to measure (rapidfuzz):

    - one edit (short words): each edit, a swap included, is undone by deleting one letter on each
      side, so the forms are indexed by themselves and each of their one-letter deletions, and
      looked up by the word and each of its one-letter deletions;
    - k edits (long words): an edit breaks at most 3 of the word's letter pairs (a swap 3, any
      other edit 2), and moves the pairs after it by at most one place, so a form within reach
      holds at least (letters - 1 - 3k) of the word's pairs, each within k places of where the
      word has it; the forms are indexed by (pair, place).

    tests/lsp/test_suggest_index.py checks the result against measuring every form.
    """

    def __init__(self, categories_by_form: Mapping[str, Iterable[str]]) -> None:
        self.forms: list[str] = sorted(categories_by_form)
        self._number = {form: i for i, form in enumerate(self.forms)}
        self._categories = [frozenset(categories_by_form[form]) for form in self.forms]
        self._lengths = [len(form) for form in self.forms]
        self._one_edit_longest = _longest_word_with_edits(1) + 1
        self._by_deletion: dict[str, list[int]] | None = None
        self._by_pair: dict[str, dict[int, list[int]]] | None = None
        self._recent: OrderedDict[str, list[tuple[int, int]]] = OrderedDict()

    def closest(self, word: str, categories: Iterable[str], limit: int, scan: bool = False) -> list[str]:
        """The forms of `categories` that `word` may stand for, best first: fewest edits, then
        those that begin with the word's first letter, then whole forms begun, then compound heads.
        `scan=True` measures every form instead of the index's candidates (the same answer, slowly:
        the reference tests/lsp/test_suggest_index.py and bench/suggest_bench.py compare with)."""
        wanted = frozenset(categories)
        low = word.lower()
        scored = self._scanned(low, wanted) if scan else self._typos(low, wanted)
        scored += [(10, form) for form in self._begun_by(low, wanted)]
        scored += [(11, form) for form in self._heads(low, wanted)]
        negated = _negated_stems(low)
        never = frozenset(teaching()["never_suggest"])
        out: list[str] = []
        for _rank, _other_start, form in sorted((rank, form[:1] != low[:1], form) for rank, form in scored):
            if form not in out and form not in negated and form != low and never.isdisjoint(form.split()):
                out.append(form)
        return out[:limit]

    def typos(self, word: str) -> list[tuple[int, str]]:
        """(edits, form) of every form, of any category, within allowed_edits(word) edits of it."""
        low = word.lower()
        typos = self._recent.get(low)
        if typos is None:
            return [(edits, self.forms[i]) for edits, i in self._all_typos(low)]
        return [(edits, self.forms[i]) for edits, i in typos]

    def forget_words(self) -> None:
        """Drop the typos remembered for recent words (the index itself stays)."""
        self._recent.clear()

    def _typos(self, low: str, wanted: frozenset[str]) -> list[tuple[int, str]]:
        """(edits, form) of every form of `wanted` within allowed_edits(low) edits of `low`."""
        typos = self._recent.get(low)
        if typos is None:
            typos = self._recent[low] = self._all_typos(low)
            if len(self._recent) > RECENT_WORDS:
                self._recent.popitem(last=False)
        return [(edits, self.forms[i]) for edits, i in typos if not wanted.isdisjoint(self._categories[i])]

    def _all_typos(self, low: str) -> list[tuple[int, int]]:
        """(edits, form number) of every form within allowed_edits(low) edits of `low`."""
        edits = allowed_edits(low)
        if edits == 0:
            return []
        if edits == 1 and len(low) < self._one_edit_longest:
            found = self._one_deletion_candidates(low)
        else:
            found = self._pair_candidates(low, edits)
        numbers = list(found)
        return [(d, numbers[at]) for d, at in _measured(low, [self.forms[i] for i in numbers], edits)]

    def _scanned(self, low: str, wanted: frozenset[str]) -> list[tuple[int, str]]:
        candidates = [
            form for form, categories in zip(self.forms, self._categories) if not wanted.isdisjoint(categories)
        ]
        return [(d, candidates[at]) for d, at in _measured(low, candidates, allowed_edits(low))]

    def _one_deletion_candidates(self, low: str) -> set[int]:
        if self._by_deletion is None:
            self._by_deletion = _deletion_index(self.forms, self._one_edit_longest)
        found: set[int] = set()
        for key in _with_one_deletion(low):
            found.update(self._by_deletion.get(key, ()))
        return found

    def _pair_candidates(self, low: str, edits: int) -> set[int]:
        needed = len(low) - 1 - 3 * edits
        shortest, longest = len(low) - edits, len(low) + edits
        if needed < 1:  # too short for pairs to tell: only the length does
            return {i for i, length in enumerate(self._lengths) if shortest <= length <= longest}
        if self._by_pair is None:
            self._by_pair = _pair_index(self.forms)
        near = []
        for place in range(len(low) - 1):
            places = self._by_pair.get(low[place : place + 2])
            if places is not None:  # a pair no form has (most of a made-up word's) costs one look-up
                near += [places[at] for at in range(max(0, place - edits), place + edits + 1) if at in places]
        if needed == 1:
            found: set[int] = set().union(*near)
        else:  # a form with a pair twice near one place counts twice: a few more candidates, none lost
            found = {i for i, count in Counter(chain.from_iterable(near)).items() if count >= needed}
        return {i for i in found if shortest <= self._lengths[i] <= longest}

    def _begun_by(self, word: str, wanted: frozenset[str]) -> list[str]:
        """'stainless' -> 'stainless steel': the multi-word forms whose first word is `word`."""
        start = word + " "
        found = []
        for i in range(bisect_left(self.forms, start), len(self.forms)):
            if not self.forms[i].startswith(start):
                break
            if not wanted.isdisjoint(self._categories[i]):
                found.append(self.forms[i])
        return found

    def _heads(self, word: str, wanted: frozenset[str]) -> list[str]:
        """'rubberwood' -> 'wood': the known one-word forms (>= 4 letters) the word ends in, after
        a first part of >= head_min_letters letters that is not a meaning prefix."""
        rules = teaching()
        found = []
        for cut in range(rules["head_min_letters"], len(word) - 3):
            first, rest = word[:cut].rstrip("-"), word[cut:].lstrip("-")
            if first in rules["meaning_prefixes"] or len(rest) < 4:
                continue
            i = self._number.get(rest)
            if i is not None and not wanted.isdisjoint(self._categories[i]):
                found.append(rest)
        return found


def _measured(low: str, candidates: list[str], edits: int) -> list[tuple[int, int]]:
    """(edits, place in `candidates`) of the candidates within `edits` edits of `low`."""
    if not candidates:
        return []
    from rapidfuzz import process  # only needed when a word is unknown
    from rapidfuzz.distance import OSA

    typos = process.extract(low, candidates, scorer=OSA.distance, score_cutoff=edits, limit=None)
    return [(int(distance), at) for _form, distance, at in typos]


def _longest_word_with_edits(edits: int) -> int:
    """The most letters a word may have and still be allowed at most `edits` edits (teaching.toml)."""
    longer = [step["letters"] for step in teaching()["typo_edits"] if step["edits"] > edits]
    return min(longer) - 1 if longer else 10**9


def _with_one_deletion(text: str) -> set[str]:
    return {text, *(text[:i] + text[i + 1 :] for i in range(len(text)))}


def _deletion_index(forms: Sequence[str], longest: int) -> dict[str, list[int]]:
    """Each form of at most `longest` letters, and each of its one-letter deletions -> the forms."""
    index: dict[str, list[int]] = {}
    for i, form in enumerate(forms):
        if len(form) <= longest:
            for key in _with_one_deletion(form):
                index.setdefault(key, []).append(i)
    return index


def _pair_index(forms: Sequence[str]) -> dict[str, dict[int, list[int]]]:
    """Two neighbouring letters -> the place of the first -> the forms that have them there."""
    index: dict[str, dict[int, list[int]]] = {}
    for i, form in enumerate(forms):
        for place in range(len(form) - 1):
            index.setdefault(form[place : place + 2], {}).setdefault(place, []).append(i)
    return index


def _negated_stems(word: str) -> frozenset[str]:
    """The words `word` is a prefixed form of: 'non-glossy' -> {'glossy'}, 'unpolished' -> {'polished'}."""
    stems = set()
    for prefix in teaching()["meaning_prefixes"]:
        if word.startswith(prefix) and len(word) > len(prefix) + 2:
            stems.add(word[len(prefix) :].lstrip("-").strip())
    if " " in word:
        stems.add(word.split(" ", 1)[1])
    return frozenset(stems)
