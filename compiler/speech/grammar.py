"""The recogniser's finite-state grammar, generated from a lexicon's sayable vocabulary.

The structure follows grammar/cnl.lark (docs/language.md), flattened so that each word class is a
set of parallel arcs between two states (a JSGF rule is copied at each reference, which made a
grammar of this lexicon take 35 s to load): a material is [article] up to `max_describing`
describing words (adverbs, shades, colours, adjectives, 'and', 'or'; a comparative first)
then a noun [or a noun], then up to `max_clauses` 'with' clauses; a refinement is up to
`max_items` items ([adverb] comparative [target]) or a 'with' clause; describing words alone end
in a colour or an adjective ('matte black'); "undo" is the session's command. No state loops, and
only the end of a noun, a clause, a refinement item, describing words or "undo" is final, so every
accepted path is a complete phrase. Each arc names its branch (`Grammar.slots`), which
cnlmc.speech.branches weighs by how often people take it.
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
    slots: list[str] = field(default_factory=list)  # each transition's branch: what choosing it says
    count: int = 2  # 0 start, 1 final
    start: int = 0
    final: int = 1

    def state(self) -> int:
        self.count += 1
        return self.count - 1

    def words(
        self, source: int, target: int, forms: Iterable[str], prior: WordPrior | None = None, slot: str = ""
    ) -> None:
        """An arc for each form (a multi-word form through states of its own); the forms share a
        probability of 1, in proportion to the prior's weights (equally without one). `slot` names
        the branch (cnlmc.speech.branches weighs branches against each other)."""
        shares = _shares(list(dict.fromkeys(forms)), prior)
        for form, share in shares.items():
            words = form.split()
            at = source
            for word in words[:-1]:
                step = self.state()
                self._add((at, step, share if at == source else 1.0, word), slot)
                at = step
            self._add((at, target, share if at == source else 1.0, words[-1]), slot)

    def skip(self, source: int, target: int, slot: str = "") -> None:
        self._add((source, target, 1.0), slot)

    def _add(self, transition: Transition, slot: str) -> None:
        self.transitions.append(transition)
        self.slots.append(slot)

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
        g.skip(g.start, material, "start.material")
        g.skip(g.start, refinement, "start.refinement")
        g.words(g.start, g.final, s.undo, slot="start.undo")
        self.material(material, clauses)
        self.refinement(refinement, clauses)
        self.describing()
        return g

    def describing(self) -> None:
        """Describing words alone ('purple', 'matte black', 'dark green'): a describing group, then
        a colour or an adjective (so the phrase is never empty). First, they start their implied
        material (matte black paint); later, they change the material ('make it purple')."""
        g = self.grammar
        begin = g.state()
        g.skip(g.start, begin, "start.describing")
        head = self.groups(begin, 1, "describing")
        g.words(head, g.final, self.of("colours", "adjectives"), self.prior, "describing.head")

    def optional(self, source: int, target: int, forms: list[str], slot: str) -> None:
        """Words that may be said or left out between two states: the branches `slot` and `slot`.skip."""
        self.grammar.words(source, target, forms, self.prior, slot)
        self.grammar.skip(source, target, f"{slot}.skip")

    def groups(self, begin: int, count: int, name: str) -> int:
        """Up to `count` describing groups, as cnl.lark's `group`: [adverb] [shade] [colour]
        [adjective] (each slot may be skipped), joined by an optional 'and'; returns the state after."""
        g = self.grammar
        at = begin
        for number in range(count):
            for category in ("adverbs", "shades", "colours", "adjectives"):
                following = g.state()
                self.optional(at, following, self.of(category), f"{name}.group{number}.{category}")
                at = following
            if number + 1 < count:
                joined = g.state()
                self.optional(at, joined, [self.settings.and_word], f"{name}.group{number}.and")
                at = joined
        return at

    def material(self, begin: int, clauses: int) -> None:
        g, s = self.grammar, self.settings
        after_article = g.state()
        self.optional(begin, after_article, list(s.articles), "material.article")
        compared = g.state()
        self.optional(after_article, compared, self.of("refinements"), "material.comparative")  # "shinier aluminum"
        noun = self.groups(compared, s.max_groups, "material")
        named, second = g.state(), g.state()
        g.words(noun, named, self.of("nouns"), self.prior, "material.noun")
        self.ending(named, clauses, "material.noun")
        or_noun = g.state()
        g.words(named, or_noun, [s.or_word], slot="material.noun.or")
        g.words(or_noun, second, self.of("nouns"), self.prior, "material.second_noun")
        self.ending(second, clauses, "material.second_noun")

    def ending(self, state: int, clauses: int, name: str) -> None:
        """A complete phrase may end here or go on to its 'with' clauses."""
        g = self.grammar
        g.skip(state, g.final, f"{name}.end")
        g.words(state, clauses, [self.settings.with_word], slot=f"{name}.with")

    def clauses(self) -> int:
        """The 'with' clauses (after 'with'): [article] describing words, a coat or feature; 'and' another."""
        g, s = self.grammar, self.settings
        begin = g.state()
        at = begin
        for number in range(s.max_clauses):
            name = f"clause{number}"
            after_article = g.state()
            self.optional(at, after_article, list(s.articles), f"{name}.article")
            done = g.state()
            head = self.groups(after_article, s.max_clause_groups, name)
            g.words(head, done, self.of("coats", "features"), self.prior, f"{name}.head")
            g.skip(done, g.final, f"{name}.end")
            if number + 1 < s.max_clauses:
                at = g.state()
                g.words(done, at, [s.and_word, f"{s.and_word} {s.with_word}"], slot=f"{name}.and")
        return begin

    def refinement(self, begin: int, clauses: int) -> None:
        g, s = self.grammar, self.settings
        g.words(begin, clauses, [s.with_word], slot="refinement.with")
        at = begin
        for number in range(s.max_items):
            name = f"item{number}"
            comparative, done = g.state(), g.state()
            self.optional(at, comparative, self.of("adverbs"), f"{name}.adverb")
            g.words(comparative, done, self.of("refinements"), self.prior, f"{name}.comparative_word")
            targeted = g.state()
            g.words(done, targeted, self.of("colours", "adjectives", "properties"), self.prior, f"{name}.target")
            following = g.state()
            for end, role in ((done, "comparative"), (targeted, "target")):
                g.skip(end, g.final, f"{name}.{role}.end")
                if number + 1 < s.max_items:
                    self.optional(end, following, [s.and_word], f"{name}.{role}.and")
            at = following


def build_grammar(vocabulary: Vocabulary, settings: SpeechSettings, prior: WordPrior | None = None) -> Grammar:
    return GrammarBuilder(vocabulary, settings, prior).build()


def closed_words(settings: SpeechSettings) -> set[str]:
    """The words the grammar adds to the vocabulary's: articles, joiners, the session's commands."""
    phrases = [*settings.articles, settings.and_word, settings.or_word, settings.with_word, *settings.undo]
    return {word for phrase in phrases for word in phrase.split()}
