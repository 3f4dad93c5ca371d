"""A feature's maps drawn on a material at a weight: by a 'with' clause ('with a green patina',
passes/features.py) or by an adjective that grows the feature ('weathered copper': adjectives
`features_on`, passes/words.py); and a map reference's weighted parameters at an adverb weight."""

from __future__ import annotations

from typing import Any

from .. import ast
from ..degrees import weighted_map_value
from ..graphs import graph_params
from ..lexicon import Entry
from ..state import Context, MaterialState
from .base import _map_ref

__all__ = ["draw_feature_maps", "graphs_of", "roles_of", "weighted_map"]


def draw_feature_maps(
    state: MaterialState, ctx: Context, entry: Entry, weight: float, words: tuple[ast.Word, ...]
) -> None:
    """The feature's maps at the weight (a graph the material already has keeps its map, scaled),
    each noted as drawn by `words` (a clause's, or an adjective's own: adjectives `features_on`)."""
    rule = f"features.{entry.key}.maps (weight {weight:g})"
    for graph in graphs_of(entry):
        if not _scale_existing(state, graph, entry, weight):
            for role, ref in entry.get("maps").items():
                if ref["graph"] == graph:
                    state.maps[role] = _map_ref(weighted_map(ref, weight), ctx)
        for role in roles_of(state, graph):
            state.note(f"maps.{role}", graph, rule, words)


def graphs_of(entry: Entry) -> list[str]:
    return list(dict.fromkeys(ref["graph"] for ref in entry.get("maps").values()))


def roles_of(state: MaterialState, graph: str) -> list[str]:
    return [role for role, ref in state.maps.items() if ref["graph"] == graph]


def _scale_existing(state: MaterialState, graph: str, entry: Entry, weight: float) -> bool:
    """Scale the weighted parameters of the material's own maps of `graph`; False if it has none."""
    roles = roles_of(state, graph)
    if not roles:
        return False
    weighted = {name for ref in entry.get("maps").values() if ref["graph"] == graph for name in ref.get("weighted", [])}
    ranges = graph_params(graph)
    for role in roles:
        params = dict(state.maps[role].get("params", {}))
        for name in weighted:
            low, high, default = ranges[name]
            params[name] = min(high, max(low, weighted_map_value(params.get(name, default), weight, (low, high))))
        state.maps[role] = {**state.maps[role], "params": params}
    return True


def weighted_map(ref: dict[str, Any], weight: float) -> dict[str, Any]:
    """A map reference with its weighted parameters scaled by the adverb weight, inside their ranges."""
    if weight == 1.0 or not ref.get("weighted"):
        return ref
    bounds = graph_params(ref["graph"])
    params = dict(ref.get("params", {}))
    for name in ref["weighted"]:
        limits = bounds.get(name)
        params[name] = weighted_map_value(params.get(name, 1.0), weight, limits[:2] if limits else None)
    return {**ref, "params": params, "weighted": []}
