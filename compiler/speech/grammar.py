"""The recogniser's finite-state grammar, generated from a lexicon's sayable vocabulary.

The structure follows grammar/cnl.lark (docs/language.md), flattened so that each word class is a
set of parallel arcs between two states (a JSGF rule is copied at each reference, which made a
grammar of this lexicon take 35 s to load): a material is [article] up to `max_describing`
describing words (adverbs, shades, colours, adjectives, 'and', 'or'; a comparative first)
then a noun [or a noun], then up to `max_clauses` 'with' clauses; a refinement is up to
`max_items` items ([adverb] comparative [target]) or a 'with' clause; "undo" is the session's
command. No state loops, and only the end of a noun, a clause, a refinement item or "undo" is
final, so every accepted path is a complete phrase.
"""

from __future__ import annotations

import math
from collections.abc import Iterable
from dataclasses import dataclass, field

from .prior import WordPrior
from .settings import SpeechSettings
from .vocabulary import Vocabulary

Transition = tuple[int, int, float, str] | tuple[int, int, float]


@dataclass
class Grammar:
    """States 0..count-1, start 0, one final state; word arcs carry a word, null arcs none."""

    transitions: list[Transition] = field(default_factory=list)
    count: int = 2  # 0 start, 1 final
    start: int = 0
    final: int = 1

    def state(self) -> int:
        self.count += 1
        return self.count - 1

    def words(
        self, source: int, target: int, forms: Iterable[str], prior: WordPrior | None = None, total: float = 1.0
    ) -> None:
        """An arc for each form (a multi-word form through states of its own); the forms share a
        probability of `total`, in proportion to the prior's weights (equally without one)."""
        shares = {form: share * total for form, share in _shares(list(dict.fromkeys(forms)), prior).items()}
        for form, share in shares.items():
            words = form.split()
            at = source
            for word in words[:-1]:
                step = self.state()
                self.transitions.append((at, step, share if at == source else 1.0, word))
                at = step
            self.transitions.append((at, target, share if at == source else 1.0, words[-1]))

    def skip(self, source: int, target: int, probability: float = 1.0) -> None:
        self.transitions.append((source, target, probability))

    def words_used(self) -> set[str]:
        return {t[3] for t in self.transitions if len(t) == 4}

    def fsg_text(self, name: str = "cnlmc") -> str:
        """The grammar in Sphinx's FSG text format (what `cnlmc listen --grammar` prints)."""
        lines = [
            f"FSG_BEGIN {name}",
            f"NUM_STATES {self.count}",
            f"START_STATE {self.start}",
            f"FINAL_STATE {self.final}",
        ]
        for t in self.transitions:
            lines.append(f"TRANSITION {t[0]} {t[1]} {t[2]:.6g}" + (f" {t[3]}" if len(t) == 4 else ""))
        return "\n".join([*lines, "FSG_END"]) + "\n"


def _shares(forms: list[str], prior: WordPrior | None) -> dict[str, float]:
    """Each form's share of a slot's probability: prior weight over the slot's total (softmax of
    the scaled log probabilities, so the rarest words do not underflow)."""
    if prior is None or not forms:
        return {form: 1.0 / max(1, len(forms)) for form in forms}
    scores = {form: prior.of(form) for form in forms}
    top = max(scores.values())
    weights = {form: math.exp(score - top) for form, score in scores.items()}
    total = sum(weights.values())
    return {form: weight / total for form, weight in weights.items()}


class GrammarBuilder:
    def __init__(self, vocabulary: Vocabulary, settings: SpeechSettings, prior: WordPrior | None = None) -> None:
        self.forms = vocabulary.forms
        self.settings = settings
        self.prior = prior
        self.grammar = Grammar()

    def of(self, *categories: str) -> list[str]:
        return [form for c in categories for form in self.forms.get(c, ())]

    def build(self) -> Grammar:
        g, s = self.grammar, self.settings
        clauses = self.clauses()
        material, refinement = g.state(), g.state()
        g.skip(g.start, material)
        g.skip(g.start, refinement)
        g.words(g.start, g.final, s.undo)
        self.material(material, clauses)
        self.refinement(refinement, clauses)
        return g

    def groups(self, begin: int, count: int) -> int:
        """Up to `count` describing groups, as cnl.lark's `group`: [adverb] [shade] [colour]
        [adjective] (each slot may be skipped), joined by an optional 'and'; returns the state after."""
        g = self.grammar
        at = begin
        for number in range(count):
            for category in ("adverbs", "shades", "colours", "adjectives"):
                following = g.state()
                g.words(at, following, self.of(category), self.prior)
                g.skip(at, following)
                at = following
            if number + 1 < count:
                joined = g.state()
                g.words(at, joined, [self.settings.and_word], total=self.settings.joiner_probability)
                g.skip(at, joined)
                at = joined
        return at

    def material(self, begin: int, clauses: int) -> None:
        g, s = self.grammar, self.settings
        after_article = g.state()
        g.words(begin, after_article, s.articles)
        g.skip(begin, after_article)
        compared = g.state()
        g.words(
            after_article, compared, self.of("refinements"), self.prior
        )  # an inline comparative: "shinier aluminum"
        g.skip(after_article, compared)
        noun = self.groups(compared, s.max_groups)
        named, second = g.state(), g.state()
        g.words(noun, named, self.of("nouns"), self.prior)
        self.ending(named, clauses)
        or_noun = g.state()
        g.words(named, or_noun, [s.or_word], total=s.joiner_probability)
        g.words(or_noun, second, self.of("nouns"), self.prior)
        self.ending(second, clauses)

    def ending(self, state: int, clauses: int) -> None:
        """A complete phrase may end here or go on to its 'with' clauses."""
        g = self.grammar
        g.skip(state, g.final)
        g.words(state, clauses, [self.settings.with_word])

    def clauses(self) -> int:
        """The 'with' clauses (after 'with'): [article] describing words, a coat or feature; 'and' another."""
        g, s = self.grammar, self.settings
        begin = g.state()
        at = begin
        for number in range(s.max_clauses):
            after_article = g.state()
            g.words(at, after_article, s.articles)
            g.skip(at, after_article)
            done = g.state()
            head = self.groups(after_article, s.max_clause_groups)
            g.words(head, done, self.of("coats", "features"), self.prior)
            g.skip(done, g.final)
            if number + 1 < s.max_clauses:
                at = g.state()
                g.words(done, at, [s.and_word, f"{s.and_word} {s.with_word}"])
        return begin

    def refinement(self, begin: int, clauses: int) -> None:
        g, s = self.grammar, self.settings
        g.words(begin, clauses, [s.with_word])
        at = begin
        for number in range(s.max_items):
            comparative, done = g.state(), g.state()
            g.words(at, comparative, self.of("adverbs"), self.prior)
            g.skip(at, comparative)
            g.words(comparative, done, self.of("refinements"), self.prior)
            targeted = g.state()
            g.words(done, targeted, self.of("colours", "adjectives", "properties"), self.prior)
            following = g.state()
            for end in (done, targeted):
                g.skip(end, g.final)
                if number + 1 < s.max_items:
                    g.words(end, following, [s.and_word], total=s.joiner_probability)
                    g.skip(end, following)
            at = following


def build_grammar(vocabulary: Vocabulary, settings: SpeechSettings, prior: WordPrior | None = None) -> Grammar:
    return GrammarBuilder(vocabulary, settings, prior).build()


def closed_words(settings: SpeechSettings) -> set[str]:
    """The words the grammar adds to the vocabulary's: articles, joiners, the session's commands."""
    phrases = [*settings.articles, settings.and_word, settings.or_word, settings.with_word, *settings.undo]
    return {word for phrase in phrases for word in phrase.split()}
