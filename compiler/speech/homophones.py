"""Spellings the recogniser cannot tell apart: forms of one grammar slot whose words sound the same
('grey' / 'gray', 'anodised' / 'anodized', the survey's 'creme' beside 'cream'). The decoder takes
the best path, not the sum of paths, so two spellings of one sound each compete with their own
share: 'grey' and 'gray' each lost to 'grape' where the two together would not. Each such form
weighs as the group together (the sum of their probabilities in text, then the prior's exponent):
the sound is as likely as all its spellings. What is sayable does not change."""

from __future__ import annotations

import math
from collections import defaultdict
from collections.abc import Mapping, Sequence

from .prior import WordPrior
from .vocabulary import Vocabulary


def sound_of(form: str, table: Mapping[str, Sequence[str]]) -> tuple[frozenset[str], ...]:
    """A form's sound: each word's set of pronunciations (two forms sound alike when equal)."""
    return tuple(frozenset(table.get(word, ())) for word in form.split())


def with_homophones_pooled(
    vocabulary: Vocabulary, table: Mapping[str, Sequence[str]], prior: WordPrior | None
) -> WordPrior | None:
    """`prior` with each form that shares its sound with another of its slot weighed as the group."""
    if prior is None or not prior.exponent:
        return prior
    pooled: dict[str, float] = {}
    for forms in vocabulary.forms.values():
        groups: dict[tuple[frozenset[str], ...], list[str]] = defaultdict(list)
        for form in forms:
            sound = sound_of(form, table)
            if all(sound):  # a word with no pronunciation sounds like nothing else
                groups[sound].append(form)
        for group in groups.values():
            if len(group) > 1:
                logs = [prior.of(form) / prior.exponent for form in group]
                top = max(logs)
                together = top + math.log(sum(math.exp(x - top) for x in logs))
                pooled.update(dict.fromkeys(group, prior.exponent * together))
    return prior.with_forms(pooled) if pooled else prior
