"""The canonical order describing groups apply in, whatever the order of the words (issue #14).

Adjectives apply by their `stage` (stdlib/schema.toml; docs/language.md "Degrees and order"):
shaping (brushed, sandblasted), treatment (anodized, oiled, painted), finish (matte, polished),
then the colour words, then ageing (rusty, weathered), then coats (varnished). Within a stage an
adjective that sets a value applies before one that scales or shifts it ("satin shiny" = shiny
satin), the rest by key, so word order never changes the numbers, except where two words of one
stage contradict each other (or two colours meet): then that stage keeps the phrase order, and the
later word applies last and wins.
"""

from __future__ import annotations

from collections.abc import Sequence

from .. import ast
from ..lexicon import Entry, Lexicon

STAGES = ("shaping", "treatment", "finish", "colour", "ageing", "coat")
DEFAULT_STAGE = "finish"  # an adjective without a declared stage describes the surface's look


def stage_of(adjective: Entry) -> str:
    return str(adjective.get("stage", DEFAULT_STAGE))


def canonical_groups(groups: Sequence[ast.Group], lexicon: Lexicon) -> Sequence[ast.Group]:
    if len(groups) < 2 and not (groups and groups[0].colours and groups[0].adjectives):
        return groups
    stages: dict[int, list[tuple[int, ast.Group]]] = {}
    for index, group in enumerate(_colours_apart(groups, lexicon)):
        stages.setdefault(_rank(group, lexicon), []).append((index, group))
    ordered: list[ast.Group] = []
    for rank in sorted(stages):
        ordered += _within_stage(stages[rank], lexicon)
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


def _rank(group: ast.Group, lexicon: Lexicon) -> int:
    """The stage a group applies in (colour words have their own; unknown words come last)."""
    if group.kind == "colour":
        return STAGES.index("colour")
    adjective = _adjective(group, lexicon)
    if adjective is None:
        return len(STAGES)  # dangling adverbs and unknown words: last, in phrase order
    return STAGES.index(stage_of(adjective))


def _adjective(group: ast.Group, lexicon: Lexicon) -> Entry | None:
    if group.kind != "adjective" or not group.adjectives or group.adjectives[0].unknown:
        return None
    return lexicon.entry("adjectives", group.adjectives[0].key)


def _sets_a_value(adjective: Entry) -> bool:
    effects = adjective.get("effects", [])
    return bool(adjective.get("material")) or any(e.get("op") == "set" for e in effects)


def _within_stage(members: list[tuple[int, ast.Group]], lexicon: Lexicon) -> list[ast.Group]:
    """Phrase order where two members contradict each other (or are colours); else the words that
    set a value first, then those that scale or shift one, each by adjective key."""
    entries = [_adjective(g, lexicon) for _, g in members]
    known = [e for e in entries if e is not None]
    if len(members) < 2 or len(known) < len(entries) or _any_opposed(known):
        return [g for _, g in members]
    keyed = sorted(zip(known, members), key=lambda pair: (not _sets_a_value(pair[0]), pair[0].key, pair[1][0]))
    return [member[1] for _, member in keyed]


def _any_opposed(entries: list[Entry]) -> bool:
    keys = {e.key for e in entries}
    return any(keys & set(e.get("opposes", [])) for e in entries)
