"""One step of a named property ('rougher', 'more grain'), shared by refinement lines and the
refinements other passes make (refine_effects' 'more grainy' on a wood)."""

from __future__ import annotations

from .. import ast
from ..diagnostics import Diagnostic, Severity, warning
from ..graphs import graph_params
from ..lexicon import Entry
from ..state import Context, MaterialState
from ..tagged import NOTE_CODE
from .base import applies_to, noun_of
from .bracket import Move, bracket_move, scaled_steps
from .refine_colour import refine_saturation
from .refine_target import highlight_shown, item_words, move_sigma_too, note_unmoved_number, surface
from .words import draw_feature


def refine_property(
    state: MaterialState, ctx: Context, prop: Entry, item: ast.RefineItem, direction: int, weight: float
) -> None:
    """One step of a property (properties.toml) in `direction`: a surface parameter, the
    saturation, or a map parameter of the maps that have it."""
    if prop.get("invert"):
        direction = -direction
    if prop.get("map_param"):
        _refine_map_param(state, ctx, prop, item, direction, weight)
        return
    param = prop.get("param")
    if param == "saturation":
        refine_saturation(state, ctx, item, direction, weight)
        return
    holder, key, limits = surface(state, param)
    up, down = scaled_steps(prop.get("step"), weight)
    move = Move(direction, up if direction > 0 else down, weight, limits)
    current = holder.get(param, 0.0)
    new = bracket_move(state.brackets, key, current, move)
    holder[param] = new
    rule = f"refinements.{item.word.key} {prop.key}: bracket step"
    state.note(key, new, rule, item_words(item))
    note_unmoved_number(state, item, key, current, new)
    move_sigma_too(state, key, move, item_words(item), rule)
    highlight_shown(state, ctx, key, current, new, item_words(item), rule)


def acted_on(state: MaterialState, prop: Entry) -> list[str]:
    """The map roles a map property acts on ('veins': the marble maps); [] for none."""
    name = prop.get("map_param")
    graphs = prop.get("graphs")
    return [
        role
        for role, ref in state.maps.items()
        if name in graph_params(ref["graph"]) and (not graphs or ref["graph"] in graphs)
    ]


def _refine_map_param(
    state: MaterialState, ctx: Context, prop: Entry, item: ast.RefineItem, direction: int, weight: float
) -> None:
    name = prop.get("map_param")
    graphs = prop.get("graphs")
    roles = acted_on(state, prop)
    if not roles and direction > 0 and prop.get("draws"):
        draw_absent_feature(state, ctx, prop, item, weight)
        return
    if not roles:
        what = "no procedural map" if not state.maps else f"no map with '{name}'"
        if graphs:
            what = f"no {' or '.join(graphs)} map"
        state.diagnostics.append(
            warning(
                item.span,
                "W106",
                f"'{prop.key}' has nothing to act on: {noun_of(state).key} has {what}",
                ("maps come from words such as 'wood', 'marble', 'brushed' or 'rusty'",),
            )
        )
        return
    up, down = scaled_steps(prop.get("step"), weight)
    for role in roles:
        ref = state.maps[role]
        key = f"maps.{role}.{name}"
        low, high, default = graph_params(ref["graph"])[name]
        move = Move(direction, up if direction > 0 else down, weight, (low, high))
        current = ref["params"].get(name, default)
        new = bracket_move(state.brackets, key, current, move)
        ref["params"][name] = new
        state.note(key, new, f"refinements.{item.word.key} {prop.key}: bracket step", item_words(item))
        note_unmoved_number(state, item, key, current, new)


def draw_absent_feature(state: MaterialState, ctx: Context, prop: Entry, item: ast.RefineItem, weight: float) -> None:
    """'copper | more patina': more of a feature the material has none of draws it, as a clause
    naming it would ('with a patina'), with a note saying so."""
    feature = ctx.lexicon.require("features", str(prop.get("draws")))
    said = " ".join(w.text for w in sorted(item_words(item), key=lambda w: w.span.start))
    noun = noun_of(state).key
    drawn = ctx.lexicon.entry("adjectives", str(feature.get("adjective"))) if feature.get("adjective") else None
    if drawn is not None and not applies_to(noun_of(state), drawn):  # rust on oak: nothing drawn
        note = drawn.get("applies_note", f"it applies to {', '.join(drawn.get('applies_to'))}")
        state.diagnostics.append(warning(item.span, "W102", f"'{said}' does not apply to {noun}: {note}", ()))
        return
    draw_feature(state, ctx, feature, weight, item_words(item))
    message = f"'{said}': {noun} had none, so it has some now (as 'with {feature.key}')"
    state.diagnostics.append(Diagnostic(item.span, Severity.NOTE, NOTE_CODE, message, ()))
