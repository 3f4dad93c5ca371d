"""The canonical order describing groups apply in, whatever the order of the words (issue #14).

Adjectives apply by their `stage` (stdlib/schema.toml; docs/language.md "Degrees and order"):
shaping (brushed, sandblasted), treatment (anodized, oiled, painted), finish (matte, polished),
then the colour words, then ageing (rusty, weathered), then coats (varnished). Within a stage an
adjective that sets a value applies before one that scales or shifts it ("satin shiny" = shiny
satin); the rest apply by key, so word order never changes the numbers, except between two words
that contradict each other (or two colours), where the later word applies last and wins.
"""

from __future__ import annotations

from collections.abc import Sequence

from .. import ast
from ..lexicon import Entry, Lexicon

STAGES = ("shaping", "treatment", "finish", "colour", "ageing", "coat")
DEFAULT_STAGE = "finish"  # an adjective without a declared stage describes the surface's look

SortKey = tuple[int, int, int]


def stage_of(adjective: Entry) -> str:
    return str(adjective.get("stage", DEFAULT_STAGE))


def canonical_groups(groups: Sequence[ast.Group], lexicon: Lexicon) -> Sequence[ast.Group]:
    if len(groups) < 2 and not (groups and groups[0].colours and groups[0].adjectives):
        return groups
    buckets: dict[tuple[int, int], list[tuple[int, ast.Group]]] = {}
    for index, group in enumerate(_colours_apart(groups, lexicon)):
        rank, setting = _rank(group, lexicon)
        buckets.setdefault((rank, setting), []).append((index, group))
    ordered: list[ast.Group] = []
    for place in sorted(buckets):
        ordered += _within_bucket(buckets[place], lexicon)
    return ordered


def _colours_apart(groups: Sequence[ast.Group], lexicon: Lexicon) -> list[ast.Group]:
    """A colour before an adjective that does not take one ("green faded", unlike "blue anodized")
    is a colour word of its own, applied in the colour stage."""
    out: list[ast.Group] = []
    for group in groups:
        adjective = _adjective(group, lexicon)
        if adjective is None or not group.colours or adjective.get("colour_target"):
            out.append(group)
            continue
        out.append(ast.Group("colour", (), group.colours, (), group.span))
        out.append(ast.Group(group.kind, group.adverbs, (), group.adjectives, group.span))
    return out


def _rank(group: ast.Group, lexicon: Lexicon) -> tuple[int, int]:
    """(stage rank, 0 for words that set a value / 1 for words that scale or shift one)."""
    if group.kind == "colour":
        named = any(c.base is not None for c in group.colours)
        return STAGES.index("colour"), 0 if named else 1
    adjective = _adjective(group, lexicon)
    if adjective is None:
        return len(STAGES), 0  # dangling adverbs and unknown words: last, in phrase order
    return STAGES.index(stage_of(adjective)), 0 if _sets_a_value(adjective) else 1


def _adjective(group: ast.Group, lexicon: Lexicon) -> Entry | None:
    if group.kind != "adjective" or not group.adjectives or group.adjectives[0].unknown:
        return None
    return lexicon.entry("adjectives", group.adjectives[0].key)


def _sets_a_value(adjective: Entry) -> bool:
    effects = adjective.get("effects", [])
    return bool(adjective.get("material")) or any(e.get("op") == "set" for e in effects)


def _within_bucket(members: list[tuple[int, ast.Group]], lexicon: Lexicon) -> list[ast.Group]:
    """Phrase order where two members contradict each other (or are colours), else by adjective key."""
    entries = [_adjective(g, lexicon) for _, g in members]
    if len(members) < 2 or any(e is None for e in entries) or _any_opposed([e for e in entries if e]):
        return [g for _, g in members]
    keyed = sorted(zip(entries, members), key=lambda pair: (pair[0].key if pair[0] else "", pair[1][0]))
    return [member[1] for _, member in keyed]


def _any_opposed(entries: list[Entry]) -> bool:
    keys = {e.key for e in entries}
    return any(keys & set(e.get("opposes", [])) for e in entries)
