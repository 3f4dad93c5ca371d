"""Start from the noun: its kind (conductor, dielectric, glass), parameters and maps."""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any, NamedTuple

from .. import ast
from ..lexicon import Entry, LexiconCaches
from ..params import Params
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
    plan = _noun_plan(entry, ctx)
    state.noun = entry
    state.kind = plan.kind
    words, params, provenance = (word,), state.params, state.provenance
    rule, source = plan.rule, plan.source
    for param, value in plan.params:  # state.record, written out: nouns set up to eight parameters
        params[param] = value
        provenance.setdefault(param, []).append(Step(rule, words, value, source))
    params.setdefault("diffuse_roughness", 0.0)
    params.setdefault("anisotropy", 0.0)
    params.setdefault("anisotropy_rotation", 0.0)
    for role, graph, output, map_params in plan.maps:
        state.maps[role] = {"graph": graph, "output": output, "params": dict(map_params), "seed": ctx.seed}
        state.note(f"maps.{role}", graph, plan.maps_rule, words)
    if plan.coat is not None:
        coat_name, coat = plan.coat
        state.coat = dict(coat)
        state.coat["name"] = coat_name
        state.note("coat", coat_name, plan.coat_rule, words)
    return state


class NounPlan(NamedTuple):
    """What apply_noun sets from one noun entry, read once per lexicon (LexiconCaches.noun_plans)."""

    entry: Entry  # the entry it was read from
    kind: Any
    rule: str
    source: Any
    params: tuple[tuple[str, Any], ...]  # the entry's own values (the IR keeps a lexicon list by identity)
    maps: tuple[tuple[str, Any, Any, dict[str, Any]], ...]  # role, graph, output, params at weight 1
    maps_rule: str
    coat: tuple[Any, dict[str, Any]] | None  # the coat's name and its entry's data
    coat_rule: str


def _noun_plan(entry: Entry, ctx: Context) -> NounPlan:
    plans = ctx.lexicon.caches.noun_plans
    plan: NounPlan | None = plans.get(entry.key)
    if plan is None or plan.entry is not entry:
        data, coat_name = entry.data, entry.get("coat")
        maps = tuple(
            (role, ref["graph"], ref.get("output", "color"), _map_ref(ref, ctx)["params"])
            for role, ref in entry.get("maps", {}).items()
        )
        if len(plans) >= LexiconCaches.MAX_ENTRIES:
            plans.clear()
        plan = plans[entry.key] = NounPlan(
            entry,
            entry.get("model"),
            f"nouns.{entry.key}",
            data.get("source"),
            tuple((param, data[param]) for param in NOUN_PARAMS if param in data),
            maps,
            f"nouns.{entry.key}.maps",
            (coat_name, ctx.lexicon.require("coats", coat_name).data) if coat_name else None,
            f"nouns.{entry.key}.coat",
        )
    return plan


def _map_ref(ref: dict[str, Any], ctx: Context, weight: float = 1.0) -> dict[str, Any]:
    params = dict(ref.get("params", {}))
    for name in ref.get("weighted", []):
        params[name] = params.get(name, 1.0) * weight
    return {"graph": ref["graph"], "output": ref.get("output", "color"), "params": params, "seed": ctx.seed}


def colour_seen_through(state: MaterialState, words: tuple[ast.Word, ...] = ()) -> None:
    """Before a word names or changes a glass's colour ('blue glass', 'smoky glass', 'deep red
    wine', a colour refinement): the colour the glass has is restated as the one seen through the
    table's default depth (an object a few centimetres thick), the depth a colour word describes,
    both recorded. Beer-Lambert keeps the glass the same (`through_depth`). A glass noun's own depth
    (a dataset's 1 cm of wine) belongs to its own colour only."""
    if state.kind != "glass":
        return
    seen = Params.transmission_depth
    depth = state.params.get("transmission_depth", seen)
    if depth == seen:
        return
    colour = state.params.get("base_color")
    restated = through_depth(colour, depth, seen) if colour is not None else None
    if restated is not None and max(restated) < HUE_FLOOR:
        return  # black coffee through 5 cm has no hue left to make lighter: its own depth keeps it
    rule = f"the colour seen through {seen * 100:g} cm (Beer-Lambert)"
    state.record("transmission_depth", seen, rule, words)
    if restated is not None:
        state.record("base_color", restated, rule, words)


#: the brightest channel under which a restated glass colour is black, its hue lost (our choice:
#: linear 1e-3, sRGB 3/255, black to the eye); the colour then stays at its own depth
HUE_FLOOR = 1e-3


def through_depth(colour: Sequence[float], depth: float, other: float) -> list[float]:
    """A glass colour, the transmittance through `depth`, restated as the transmittance through
    `other` (Beer-Lambert: colour^(other / depth))."""
    return [max(float(c), 0.0) ** (other / depth) for c in colour]


def applies_to(noun: Entry, adjective: Entry) -> bool:
    """Whether the adjective's classes (if any) include the noun or its class."""
    classes = adjective.data.get("applies_to")
    return not classes or noun.data.get("class") in classes or noun.key in classes
