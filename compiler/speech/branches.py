"""How likely each branch of the grammar is: at a state where a phrase may go on in several ways
(say an adverb or not, end or go on to a 'with' clause, join two nouns with 'or'), each way's
probability is estimated from phrases people typed, counted per named branch (Grammar.slots) and
smoothed (add-`smoothing`, Laplace), so that what people rarely say costs the recogniser more.

The counts are data (stdlib/speech/branches.toml, written by scripts/gen_speech_branches.py from
tests/language/everyday.toml, the everyday phrases of issue #14); they name branches, not states,
so they hold for a user's lexicon too. They are kept per context: the first utterance of a session
starts a material, later ones mostly change it ('darker'), so the start's branches are weighed
apart for each (two grammars of one structure)."""

from __future__ import annotations

import tomllib
from collections import defaultdict
from collections.abc import Iterable
from functools import cache

from .grammar import Grammar
from .settings import speech_data

BRANCHES_FILE = "branches.toml"
CONTEXTS = ("first", "later")  # an utterance that starts a material; one said after it
START = "start."  # the branches of the start state: a material, a refinement or 'undo'


def bundled_counts(context: str) -> dict[str, float]:
    """The branch counts of stdlib/speech/branches.toml for an utterance said in `context`: how a
    phrase goes on is counted over both contexts, what it is (a material, a change) in its own."""
    counts: dict[str, float] = defaultdict(float)
    for table in CONTEXTS:
        for slot, count in _bundled_tables()[table].items():
            if table == context or not slot.startswith(START):
                counts[str(slot)] += float(count)
    return dict(counts)


@cache
def _bundled_tables() -> dict[str, dict[str, float]]:
    """stdlib/speech/branches.toml, read once (immutable package data)."""
    return {table: dict(counts) for table, counts in tomllib.loads(speech_data(BRANCHES_FILE)).items()}


def leaving(grammar: Grammar) -> dict[int, list[int]]:
    """Each state's outgoing transitions (indices)."""
    found: dict[int, list[int]] = defaultdict(list)
    for index, transition in enumerate(grammar.transitions):
        found[transition[0]].append(index)
    return found


def paths(grammar: Grammar, words: tuple[str, ...], out: dict[int, list[int]]) -> list[tuple[int, ...]]:
    """Every accepting path of `words` through the grammar (transition indices; none when the
    grammar cannot say them); `out` is leaving(grammar). The grammar has no loops, so the search ends."""

    @cache
    def onward(state: int, at: int) -> tuple[tuple[int, ...], ...]:
        found: list[tuple[int, ...]] = [()] if state == grammar.final and at == len(words) else []
        for index in out[state]:
            transition = grammar.transitions[index]
            if len(transition) == 3:
                found.extend((index, *rest) for rest in onward(transition[1], at))
            elif at < len(words) and transition[3] == words[at]:
                found.extend((index, *rest) for rest in onward(transition[1], at + 1))
        return tuple(found)

    return list(onward(grammar.start, 0))


def branching(grammar: Grammar) -> dict[int, set[str]]:
    """Each state's branches (the slots of the arcs that leave it)."""
    found: dict[int, set[str]] = defaultdict(set)
    for transition, slot in zip(grammar.transitions, grammar.slots, strict=True):
        found[transition[0]].add(slot)
    return found


def count_branches(grammar: Grammar, phrases: Iterable[str]) -> tuple[dict[str, float], int]:
    """How often each named branch is taken where a phrase had a choice, over the phrases the
    grammar can say (a phrase with several readings counts each reading by its share), and how
    many phrases were said."""
    choices = {state for state, slots in branching(grammar).items() if len(slots) > 1}
    out = leaving(grammar)
    counts: dict[str, float] = defaultdict(float)
    said = 0
    for phrase in phrases:
        readings = paths(grammar, tuple(phrase.split()), out)
        if not readings:
            continue
        said += 1
        for reading in readings:
            for index in reading:
                if grammar.transitions[index][0] in choices:
                    counts[grammar.slots[index]] += 1.0 / len(readings)
    return dict(counts), said


def weigh_branches(grammar: Grammar, counts: dict[str, float], smoothing: float) -> Grammar:
    """The grammar with each branching state's ways weighted by their counts: a branch's arcs
    share (count + smoothing) / (all the state's counts + smoothing x its branches), in the
    proportions they had (a slot's words keep their word weights)."""
    branches = branching(grammar)
    within: dict[tuple[int, str], float] = defaultdict(float)
    for transition, slot in zip(grammar.transitions, grammar.slots, strict=True):
        within[transition[0], slot] += transition[2]
    weighted = []
    for transition, slot in zip(grammar.transitions, grammar.slots, strict=True):
        state = transition[0]
        total = sum(counts.get(b, 0.0) + smoothing for b in branches[state])
        if len(branches[state]) > 1 and total > 0.0:
            share = (counts.get(slot, 0.0) + smoothing) / total
            transition = (state, transition[1], share * transition[2] / within[state, slot], *transition[3:])
        weighted.append(transition)
    return Grammar(weighted, list(grammar.slots), grammar.count, grammar.start, grammar.final)
