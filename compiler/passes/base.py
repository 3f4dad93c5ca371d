"""Start from the noun: its kind (conductor, dielectric, glass), parameters and maps."""

from __future__ import annotations

from typing import Any

from .. import ast
from ..lexicon import Entry
from ..state import NOUN_PARAMS, Context, MaterialState, Step


def noun_word(state: MaterialState) -> ast.Word:
    return state.selection.nouns[0]


def noun_of(state: MaterialState) -> Entry:
    """The material's noun entry (apply_noun, the first pass, sets it)."""
    assert state.noun is not None, "apply_noun runs first"
    return state.noun


def apply_noun(state: MaterialState, ctx: Context) -> MaterialState:
    word = noun_word(state)
    entry = ctx.lexicon.require("nouns", word.key)
    state.noun = entry
    state.kind = entry.get("model")
    rule, words, data = f"nouns.{entry.key}", (word,), entry.data
    source, params, provenance = data.get("source"), state.params, state.provenance
    for param in NOUN_PARAMS:  # state.record, written out: nouns set up to eight parameters
        if param in data:
            value = params[param] = data[param]
            provenance.setdefault(param, []).append(Step(rule, words, value, source))
    params.setdefault("diffuse_roughness", 0.0)
    params.setdefault("anisotropy", 0.0)
    params.setdefault("anisotropy_rotation", 0.0)
    for role, ref in entry.get("maps", {}).items():
        state.maps[role] = _map_ref(ref, ctx)
        state.note(f"maps.{role}", ref["graph"], f"nouns.{entry.key}.maps", (word,))
    if entry.get("coat"):
        state.coat = dict(ctx.lexicon.require("coats", entry.get("coat")).data)
        state.coat["name"] = entry.get("coat")
        state.note("coat", entry.get("coat"), f"nouns.{entry.key}.coat", (word,))
    return state


def _map_ref(ref: dict[str, Any], ctx: Context, weight: float = 1.0) -> dict[str, Any]:
    params = dict(ref.get("params", {}))
    for name in ref.get("weighted", []):
        params[name] = params.get(name, 1.0) * weight
    return {"graph": ref["graph"], "output": ref.get("output", "color"), "params": params, "seed": ctx.seed}
