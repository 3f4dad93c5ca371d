"""'Did you mean': the known forms an unknown word may be a typo of, best first.

A suggestion must be a typo of the word (a few edits, by its length: stdlib/data/teaching.toml),
the whole form that the word begins ('stainless' -> 'stainless steel'), or the known word a
compound ends in ('rubberwood' -> 'wood'). Never a word the unknown one negates or
grades with a prefix ('non-glossy' is not 'glossy', 'unpolished' is not 'polished'), and never a
far-fetched look-alike (pewter -> water, beech -> bleach: 2-3 edits on 5-7 letters).
"""

from __future__ import annotations

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
    """The forms of `pool` (lower-case surface forms) that `word` may stand for, best first."""
    from rapidfuzz.distance import OSA  # only needed when a word is unknown

    low = word.lower()
    negated = _negated_stems(low)
    budget = allowed_edits(low)
    scored: list[tuple[int, str]] = []
    for form in pool:
        if form in negated or form == low:
            continue
        rank = _rank(low, form, budget, OSA.distance)
        if rank is not None:
            scored.append((rank, form))
    scored.sort()
    return [form for _rank_, form in scored[:limit]]


def _rank(word: str, form: str, budget: int, distance: Any) -> int | None:
    """0-9: a typo (its edit count), 10: the form the word begins, 11: a compound's head; None: unrelated."""
    if abs(len(form) - len(word)) <= budget:
        edits = distance(word, form, score_cutoff=budget)
        if edits <= budget:
            return int(edits)
    if " " in form and form.startswith(word + " "):
        return 10
    if _is_head(word, form):
        return 11
    return None


def _is_head(word: str, form: str) -> bool:
    """'rubberwood' ends in the noun 'wood' after a first part of >= head_min_letters letters."""
    if " " in form or len(form) < 4 or not word.endswith(form):
        return False
    first = word[: -len(form)].rstrip("-")
    return len(first) >= teaching()["head_min_letters"] and first not in teaching()["meaning_prefixes"]


def _negated_stems(word: str) -> frozenset[str]:
    """The words `word` is a prefixed form of: 'non-glossy' -> {'glossy'}, 'unpolished' -> {'polished'}."""
    stems = set()
    for prefix in teaching()["meaning_prefixes"]:
        if word.startswith(prefix) and len(word) > len(prefix) + 2:
            stems.add(word[len(prefix) :].lstrip("-").strip())
    if " " in word:
        stems.add(word.split(" ", 1)[1])
    return frozenset(stems)
