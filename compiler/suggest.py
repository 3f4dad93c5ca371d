"""'Did you mean': the known forms an unknown word may be a typo of, best first.

A suggestion must be a typo of the word (a few edits, by its length: stdlib/data/teaching.toml),
the whole form that the word begins ('stainless' -> 'stainless steel'), or the known word a
compound ends in ('rubberwood' -> 'wood'). Never a word the unknown one negates or
grades with a prefix ('non-glossy' is not 'glossy', 'unpolished' is not 'polished'), and never a
far-fetched look-alike (pewter -> water, beech -> bleach: 2-3 edits on 5-7 letters).
"""

from __future__ import annotations

from bisect import bisect_left
from collections.abc import Mapping, Sequence
from functools import lru_cache
from importlib import resources
from types import MappingProxyType
from typing import Any

__all__ = ["closest_forms", "teaching"]


@lru_cache(maxsize=1)
def teaching() -> Mapping[str, Any]:
    """stdlib/data/teaching.toml, read once per process (immutable package data)."""
    import tomllib

    text = resources.files("cnlmc.stdlib").joinpath("data").joinpath("teaching.toml").read_text("utf-8")
    return MappingProxyType(tomllib.loads(text))


def allowed_edits(word: str) -> int:
    """How many edits a typo of `word` may have (teaching.toml's typo_edits, by its length)."""
    edits = 0
    for step in teaching()["typo_edits"]:
        if len(word) >= step["letters"]:
            edits = step["edits"]
    return edits


def closest_forms(word: str, pool: Sequence[str], limit: int) -> list[str]:
    """The forms of `pool` (sorted lower-case surface forms) that `word` may stand for, best first:
    fewest edits, then those that begin with the word's first letter."""
    from rapidfuzz import process  # only needed when a word is unknown
    from rapidfuzz.distance import OSA

    low = word.lower()
    typos = process.extract(low, pool, scorer=OSA.distance, score_cutoff=allowed_edits(low), limit=None)
    scored = [(int(edits), form) for form, edits, _i in typos]
    scored += [(10, form) for form in _forms_begun_by(low, pool)]
    scored += [(11, form) for form in _heads(low, pool)]
    negated = _negated_stems(low)
    never = frozenset(teaching()["never_suggest"])
    out: list[str] = []
    for _rank, _other_start, form in sorted((rank, form[:1] != low[:1], form) for rank, form in scored):
        if form not in out and form not in negated and form != low and never.isdisjoint(form.split()):
            out.append(form)
    return out[:limit]


def _forms_begun_by(word: str, pool: Sequence[str]) -> list[str]:
    """'stainless' -> 'stainless steel': the multi-word forms whose first word is `word` (pool sorted)."""
    start = word + " "
    found = []
    for form in pool[bisect_left(pool, start) :]:
        if not form.startswith(start):
            break
        found.append(form)
    return found


def _heads(word: str, pool: Sequence[str]) -> list[str]:
    """'rubberwood' -> 'wood': the known one-word forms (>= 4 letters) the word ends in, after a
    first part of >= head_min_letters letters that is not a meaning prefix."""
    rules = teaching()
    found = []
    for cut in range(rules["head_min_letters"], len(word) - 3):
        first, rest = word[:cut].rstrip("-"), word[cut:].lstrip("-")
        if first in rules["meaning_prefixes"] or len(rest) < 4:
            continue
        index = bisect_left(pool, rest)
        if index < len(pool) and pool[index] == rest:
            found.append(rest)
    return found


def _negated_stems(word: str) -> frozenset[str]:
    """The words `word` is a prefixed form of: 'non-glossy' -> {'glossy'}, 'unpolished' -> {'polished'}."""
    stems = set()
    for prefix in teaching()["meaning_prefixes"]:
        if word.startswith(prefix) and len(word) > len(prefix) + 2:
            stems.add(word[len(prefix) :].lstrip("-").strip())
    if " " in word:
        stems.add(word.split(" ", 1)[1])
    return frozenset(stems)
