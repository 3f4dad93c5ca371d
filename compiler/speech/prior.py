"""How likely each word is said: unigram probabilities from the English language model that ships
in pocketsphinx's wheel (en-us.lm.bin), so that a grammar slot of hundreds of words prefers the
common ones ('copper' over 'cupric'). Not tuned to any phrase: the model is general English text."""

from __future__ import annotations

import math
from collections.abc import Iterable
from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import Any

OUT_OF_VOCABULARY = -536870912  # what NGramModel.prob returns for a word it lacks


@dataclass(frozen=True)
class WordPrior:
    """word -> natural log of its unigram probability; `floor` for words the model lacks; a form's
    weight is its probability raised to `exponent` (0: all words alike, 1: as often as in text)."""

    log_probability: dict[str, float]
    floor: float
    exponent: float
    forms: dict[str, float] = field(default_factory=dict)  # scaled log weights set per form (homophones)

    def of(self, form: str) -> float:
        """A form's scaled log weight: its rarest word's (a multi-word form is as hard as its hardest
        word), or the weight set for it."""
        if form in self.forms:
            return self.forms[form]
        return self.exponent * min(self.log_probability.get(word, self.floor) for word in form.split())

    def with_forms(self, forms: dict[str, float]) -> WordPrior:
        """This prior with the given forms' scaled log weights set."""
        return replace(self, forms={**self.forms, **forms})

    @classmethod
    def from_model(cls, pocketsphinx: Any, path: Path, words: Iterable[str], exponent: float) -> WordPrior:
        """The unigram log probabilities of `words` in the n-gram model at `path`; the floor is the
        rarest known word's (our choice: a word the model lacks is rare, not impossible)."""
        model = pocketsphinx.NGramModel.readfile(str(path))
        logmath = pocketsphinx.LogMath()
        found: dict[str, float] = {}
        for word in words:
            score = model.prob([word])
            if score > OUT_OF_VOCABULARY:
                found[word] = float(logmath.log_to_ln(score))
        floor = min(found.values(), default=math.log(1e-7))
        return cls(found, floor, exponent)
