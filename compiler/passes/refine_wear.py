"""'more worn' on leather that has no wear yet, 'less worn' on weathered bronze (issue #14).

A describing word that brings a treatment (a map) must be part of the material to be refined
(passes/refine_effects.py). Two readings come first, from the lexicon's data:

- the material shows another word of the same stage (`stage`, e.g. "ageing": worn, weathered,
  rusty, patinated): 'less worn' on weathered bronze is less of the wear it shows — the weighted
  parameters of its maps drawn by that stage (the patina that 'weathered' grows) move, one bracket
  step, as the word's own maps would;
- otherwise, asked for more, a word of a stage that accumulates (teaching.toml [refining]: ageing)
  that applies to the material is added at the weight step ('more worn' on leather = slightly worn
  leather), as 'rustier iron' is (passes/refine_missing_map.py); 'stronger brushing' on plain steel
  still says that brushing is not part of it (W104).

Each with a note that says how the line was read.
"""

from __future__ import annotations

from collections.abc import Iterator
from typing import Any

from .. import ast
from ..lexicon import Entry
from ..state import Context, MaterialState
from .base import noun_of
from .bracket import Move, Step, bracket_move
from .refine_target import item_words, note, refine_weight

__all__ = ["refine_drawn_maps", "refine_missing_treatment", "refine_weighted_map"]


def refine_missing_treatment(
    state: MaterialState, ctx: Context, adjective: Entry, item: ast.RefineItem, direction: int
) -> bool:
    """Refine a treatment word the material lacks by its stage's maps, or add it when asked for
    more; False when neither reading applies."""
    return _same_stage(state, ctx, adjective, item, direction) or _added(state, ctx, adjective, item, direction)


def _same_stage(state: MaterialState, ctx: Context, adjective: Entry, item: ast.RefineItem, direction: int) -> bool:
    stage = adjective.get("stage")
    if not stage:
        return False
    of_stage = [a for a in ctx.lexicon.all_of("adjectives").values() if a.get("stage") == stage]
    graphs = refine_drawn_maps(state, ctx, of_stage, item, direction)
    if not graphs:
        return False
    said = f"{item.word.text} {adjective.key}"
    message = f"read '{said}' as {item.word.text} of the material's own {stage} ({graphs}): it has no '{adjective.key}'"
    state.diagnostics.append(note(item.span, "N104", message))
    return True


def refine_drawn_maps(
    state: MaterialState, ctx: Context, adjectives: list[Entry], item: ast.RefineItem, direction: int
) -> str:
    """Move the weighted parameters of the material's maps that `adjectives` draw (their own maps,
    and the features they grow: `features_on`) one bracket step; the graphs moved, joined ('' for
    none). 'more weathered' on weathered bronze grows its patina so."""
    weighted = _weighted_by_graph(ctx, adjectives)
    shown = [(role, ref) for role, ref in state.maps.items() if ref.get("graph") in weighted]
    weight = refine_weight(item, ctx)
    formula = float(ctx.settings.get("weight_step", 0.5)) * weight
    for role, ref in shown:
        for name in sorted(weighted[ref["graph"]]):
            refine_weighted_map(state, role, name, item, direction, formula, weight)
    return ", ".join(sorted({ref["graph"] for _role, ref in shown}))


def refine_weighted_map(
    state: MaterialState, role: str, name: str, item: ast.RefineItem, direction: int, formula: float, adverbs: float
) -> None:
    """One bracket step of a map's weighted parameter (a rust mask's coverage, a brushing's
    strength): times 1 + the formula weight up, divided by it down."""
    ref: dict[str, Any] | None = state.maps.get(role)
    if ref is None:
        return
    key = f"maps.{role}.{name}"
    step: Step = (lambda x: x * (1 + formula)) if direction > 0 else (lambda x: x / (1 + formula))
    new = bracket_move(state.brackets, key, ref["params"].get(name, 1.0), Move(direction, step, adverbs))
    ref["params"][name] = new
    assert isinstance(item.target, ast.Word), item
    state.note(key, new, f"refinements.{item.word.key} {item.target.key}: bracket step", item_words(item))


def _weighted_by_graph(ctx: Context, adjectives: list[Entry]) -> dict[str, set[str]]:
    """The graphs the adjectives draw, each with its weighted parameters."""
    out: dict[str, set[str]] = {}
    for adjective in adjectives:
        for maps in _drawn_maps(ctx, adjective):
            for ref in maps.values():
                out.setdefault(ref["graph"], set()).update(ref.get("weighted") or [])
    return {graph: names for graph, names in out.items() if names}


def _drawn_maps(ctx: Context, adjective: Entry) -> Iterator[dict[str, Any]]:
    lexicon = ctx.lexicon
    yield adjective.get("maps") or {}
    for feature_key in (adjective.get("features_on") or {}).values():
        feature = lexicon.entry("features", feature_key)
        if feature is None:
            continue
        yield feature.get("maps") or {}
        drawn_by = feature.get("adjective")
        if drawn_by and (source := lexicon.entry("adjectives", drawn_by)) is not None:
            yield source.get("maps") or {}


def _added(state: MaterialState, ctx: Context, adjective: Entry, item: ast.RefineItem, direction: int) -> bool:
    from ..suggest import teaching
    from .words import apply_adjective

    noun = noun_of(state)
    classes = adjective.get("applies_to")
    if direction <= 0 or adjective.get("stage") not in teaching()["refining"]["accumulating_stages"]:
        return False
    if classes and noun.get("class") not in classes and noun.key not in classes:
        return False
    weight = float(ctx.settings.get("weight_step", 0.5)) * refine_weight(item, ctx)
    assert isinstance(item.target, ast.Word), item
    word = ast.Word(item.target.text, adjective.key, "adjectives", item.target.span)
    apply_adjective(state, ctx, adjective, ast.Group("adjective", (), (), (word,), item.span), weight, "base")
    message = (
        f"read '{item.word.text} {item.target.text}' as '{adjective.key}' at weight {weight:g}: "
        f"{noun.key} had none, so more is a little of it"
    )
    state.diagnostics.append(note(item.span, "N104", message))
    return True
