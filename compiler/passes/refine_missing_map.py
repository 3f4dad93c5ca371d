"""'rustier iron': an inline comparative whose own target is a map the material does not have.

A comparative such as 'rustier' names a map property (properties.toml 'coverage'); on a material
that has that map it moves the map's parameter (passes/refine.py). Written before a material that
has none ('rustier iron', 'rustier steel'), it means one step of the quality from none: the
describing word that draws the map at the weight step (settings.toml weight_step: 'rustier iron' =
'slightly rusty iron'), with a note (issue #14). The word is found from the lexicon's data: the
adjectives whose maps weigh the property's parameter; only when they all draw one graph (coverage:
the rust graph, so 'rusty'), so a generic parameter ('strength': brushed, hammered, sandblasted)
never guesses, and only one that applies to the material's class.
"""

from __future__ import annotations

from .. import ast
from ..lexicon import Entry
from ..state import Context, MaterialState
from .base import noun_of
from .refine_target import note, refine_weight
from .words import apply_adjective

__all__ = ["add_missing_map", "map_property_of"]


def add_missing_map(state: MaterialState, ctx: Context, item: ast.RefineItem) -> bool:
    """Apply the adjective that draws the comparative's missing map; False if there is none to apply."""
    adjective = _drawing_adjective(state, ctx, item)
    if adjective is None:
        return False
    weight = float(ctx.settings.get("weight_step", 0.5)) * refine_weight(item, ctx)  # 'much rustier': more
    word = ast.Word(item.word.text, adjective.key, "adjectives", item.word.span)
    group = ast.Group("adjective", (), (), (word,), item.word.span)
    apply_adjective(state, ctx, adjective, group, weight, "base")
    message = (
        f"read '{item.word.text}' as '{adjective.key}' at weight {weight:g}: "
        f"{noun_of(state).key} has no such map, so one step more is a little of it"
    )
    state.diagnostics.append(note(item.span, "N104", message))
    return True


def _drawing_adjective(state: MaterialState, ctx: Context, item: ast.RefineItem) -> Entry | None:
    entry = ctx.lexicon.require("refinements", item.word.key)
    target = entry.get("target")
    if entry.get("direction") <= 0 or target in ("any", "colour") or item.target is not None:
        return None
    prop = ctx.lexicon.require("properties", target)
    name, graphs = prop.get("map_param"), prop.get("graphs")
    if not name or any(name in ref.get("params", {}) or _draws(ref, name, graphs) for ref in state.maps.values()):
        return None
    drawing = [
        adjective
        for adjective in ctx.lexicon.all_of("adjectives").values()
        if any(_weighs(ref, name, graphs) for ref in adjective.get("maps", {}).values())
    ]
    drawn = {ref["graph"] for a in drawing for ref in a.get("maps", {}).values() if _weighs(ref, name, graphs)}
    if len(drawn) != 1:
        return None
    noun = noun_of(state)
    return next((a for a in drawing if _applies(a, noun)), None)


def _weighs(ref: dict[str, object], name: str, graphs: list[str] | None) -> bool:
    weighted = ref.get("weighted") or []
    return isinstance(weighted, list) and name in weighted and (not graphs or ref.get("graph") in graphs)


def _draws(ref: dict[str, object], name: str, graphs: list[str] | None) -> bool:
    return bool(graphs) and ref.get("graph") in (graphs or [])


def _applies(adjective: Entry, noun: Entry) -> bool:
    classes = adjective.get("applies_to")
    return not classes or noun.get("class") in classes or noun.key in classes


def map_property_of(state: MaterialState, ctx: Context, word: str) -> Entry | None:
    """'more grainy' on oak: 'grainy' is an adjective the material lacks ('textured'), but its stem
    names a map property of a map the material has ('grain'): that property."""
    endings = [e for layer in ctx.lexicon.word_formation for e in layer["properties"]["endings"]]
    for ending in dict.fromkeys(endings):  # word_formation*.toml [properties], the overlay's first
        if not word.endswith(ending) or len(word) - len(ending) < 3:
            continue
        stem = word[: len(word) - len(ending)]
        for entry in ctx.lexicon.lookup((stem,)):
            name = entry.get("map_param") if entry.category == "properties" else None
            graphs = entry.get("graphs") if name else None
            if name and any(_has_param(ref, name, graphs) for ref in state.maps.values()):
                return entry
    return None


def _has_param(ref: dict[str, object], name: str, graphs: list[str] | None) -> bool:
    from ..graphs import graph_params

    graph = str(ref.get("graph"))
    return name in graph_params(graph) and (not graphs or graph in graphs)
