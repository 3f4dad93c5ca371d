"""The speech model of one lexicon: its sayable vocabulary, pronunciations and grammar, and the
recogniser loaded with them."""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass
from pathlib import Path

from ..lexicon import Lexicon
from .branches import CONTEXTS, bundled_counts, weigh_branches
from .grammar import Grammar, build_grammar, closed_words
from .homophones import with_homophones_pooled
from .prior import WordPrior
from .pronounce import Pronunciations
from .recogniser import Recogniser, model_files, pocketsphinx_module
from .settings import SpeechSettings
from .vocabulary import Vocabulary, joined_colours, sayable_vocabulary
from .voice import Voice


@dataclass(frozen=True)
class SpeechModel:
    vocabulary: Vocabulary
    grammar: Grammar  # for the utterance that starts a material
    later: Grammar  # for utterances said after it (the same phrases, changes weighed likelier)
    dictionary: str  # CMU-format pronunciations of every word of the grammar
    unsayable: frozenset[str]  # words left out: no pronunciation anywhere
    settings: SpeechSettings

    @classmethod
    def of(
        cls, lexicon: Lexicon, folders: Iterable[str | Path] = (), settings: SpeechSettings | None = None
    ) -> SpeechModel:
        """The model of `lexicon`; `folders` are its user lexicon folders (their speech/pronunciations.toml)."""
        settings = settings or SpeechSettings.bundled()
        vocabulary = sayable_vocabulary(lexicon, settings)
        words = vocabulary.words() | closed_words(settings)
        pronunciations = Pronunciations(words, model_files().dictionary, folders, british=settings.british_variants)
        vocabulary = vocabulary.without(pronunciations.missing | joined_colours(vocabulary, pronunciations.english))
        prior = with_homophones_pooled(vocabulary, pronunciations.table, word_prior(vocabulary, settings))
        grammar = build_grammar(vocabulary, settings, prior)
        first, later = (weighed(grammar, context, settings.branch_smoothing) for context in CONTEXTS)
        dictionary, missing = pronunciations.dictionary_text(), frozenset(pronunciations.missing)
        return cls(vocabulary, first, later, dictionary, missing, settings)

    def recogniser(self, voice: Voice | None = None) -> Recogniser:
        """The recogniser of this model, adapted to an enrolled speaker's `voice` when given."""
        return Recogniser(self.grammar, self.dictionary, self.settings, self.later, voice)


def weighed(grammar: Grammar, context: str, smoothing: float) -> Grammar:
    """The grammar's branches weighed by the bundled counts of `context` (as built when 0)."""
    return weigh_branches(grammar, bundled_counts(context), smoothing) if smoothing else grammar


def word_prior(vocabulary: Vocabulary, settings: SpeechSettings) -> WordPrior | None:
    """The words' weights from the language model (None: every word of a slot alike)."""
    if not settings.prior_exponent:
        return None
    files = model_files()
    return WordPrior.from_model(
        pocketsphinx_module(), files.language_model, vocabulary.words(), settings.prior_exponent
    )
