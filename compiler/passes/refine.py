"""Refinement: "darker", "less diffuse", "stronger brushing" change the material above.

The bracket rule (docs/refinement.md): each target keeps the interval the user has
narrowed it to. "less X" says the current value is too high (it becomes the upper bound),
"more X" that it is too low (the lower bound). With both bounds known the new value is
their midpoint; otherwise it moves one step. Paper §4.2: m 0.3 -less diffuse-> 0.2
-more diffuse-> 0.25; blue (0,0,1) -darker-> (0,0,0.5).
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

from .. import ast
from ..colour import saturate
from ..diagnostics import warning
from ..formulas import apply_op, invert_op, midpoint
from ..graphs import graph_params
from ..lexicon import Entry
from ..state import Context, MaterialState
from .base import noun_of
from .words import Effect, effects_for

Step = Callable[[Any], Any]  # one bracket step of a value (a number or an RGB list)


def bracket_move(state: MaterialState, key: str, current: Any, direction: int, step_up: Step, step_down: Step) -> Any:
    """The next value for `key`: a step, or the midpoint once the value is bracketed."""
    bounds = state.brackets.setdefault(key, {"lo": None, "hi": None})
    if direction > 0:
        bounds["lo"] = current
        other = bounds["hi"]
        return midpoint(current, other) if other is not None else step_up(current)
    bounds["hi"] = current
    other = bounds["lo"]
    return midpoint(current, other) if other is not None else step_down(current)


def _step_fns(step: dict[str, Any]) -> tuple[Step, Step]:
    op, value = step["op"], step["value"]
    if op == "blend":
        to = step.get("to", [1.0, 1.0, 1.0])
        return (lambda x: apply_op("blend", x, to, 1.0, value), lambda x: invert_op("blend", x, to, 1.0, value))
    return (lambda x: apply_op(op, x, value), lambda x: invert_op(op, x, value))


def apply_refinement(state: MaterialState, ctx: Context, item: ast.RefineItem) -> None:
    entry = ctx.lexicon.require("refinements", item.word.key)
    direction, target = entry.get("direction"), entry.get("target")
    if item.word.unknown or (item.target is not None and _is_unknown(item.target)):
        return
    if target == "colour":
        _refine_colour(state, entry, item, direction)
    elif target != "any":
        _refine_property(state, ctx, ctx.lexicon.require("properties", target), item, direction)
    elif item.target is None:
        state.diagnostics.append(
            warning(
                item.span,
                "W104",
                f"'{item.word.text}' of what?",
                ("name what to change, e.g. 'more grain' or 'less diffuse'",),
            )
        )
    else:
        _refine_named(state, ctx, item, direction)


def _is_unknown(target: ast.Word | ast.Colour) -> bool:
    words = target.words if isinstance(target, ast.Colour) else (target,)
    return any(w.unknown for w in words)


def _refine_named(state: MaterialState, ctx: Context, item: ast.RefineItem, direction: int) -> None:
    target = item.target
    if isinstance(target, ast.Colour):
        _refine_saturation(state, item, direction)
    elif _target_word(item).category == "properties":
        _refine_property(state, ctx, ctx.lexicon.require("properties", _target_word(item).key), item, direction)
    else:
        _refine_adjective(state, ctx, ctx.lexicon.require("adjectives", _target_word(item).key), item, direction)


def _target_word(item: ast.RefineItem) -> ast.Word:
    """The word a refinement names ('grain' in 'more grain'), where it names one."""
    assert isinstance(item.target, ast.Word), item
    return item.target


def _colour_param(state: MaterialState, item: ast.RefineItem) -> str:
    """'darker blue' acts on the colour that 'blue' set; plain 'darker' on the base colour."""
    if isinstance(item.target, ast.Colour) and item.target.base is not None:
        key = item.target.base.key
        for param in ("coat.color", "base_color"):
            if key in state.words_of(param):
                return param
    return "base_color"


def _refine_colour(state: MaterialState, entry: Entry, item: ast.RefineItem, direction: int) -> None:
    param = _colour_param(state, item)
    holder, name = (
        (state.coat, "color") if param == "coat.color" and state.coat is not None else (state.params, "base_color")
    )
    forward, backward = _step_fns(entry.get("step"))
    up, down = (forward, backward) if direction > 0 else (backward, forward)
    new = bracket_move(state, param, holder[name], direction, up, down)
    holder[name] = new
    state.note(param, new, f"refinements.{entry.key}: bracket step", _item_words(item))


def _refine_saturation(state: MaterialState, item: ast.RefineItem, direction: int) -> None:
    new = bracket_move(
        state,
        "saturation",
        state.params["base_color"],
        direction,
        lambda x: saturate(x, 0.25),
        lambda x: saturate(x, -0.25),
    )
    state.record("base_color", new, f"refinements.{item.word.key}: saturation", _item_words(item))


def _refine_property(state: MaterialState, ctx: Context, prop: Entry, item: ast.RefineItem, direction: int) -> None:
    if prop.get("invert"):
        direction = -direction
    if prop.get("map_param"):
        _refine_map_param(state, prop, item, direction)
        return
    param = prop.get("param")
    if param == "saturation":
        _refine_saturation(state, item, direction)
        return
    up, down = _step_fns(prop.get("step"))
    new = bracket_move(state, param, state.params.get(param, 0.0), direction, up, down)
    state.record(param, new, f"refinements.{item.word.key} {prop.key}: bracket step", _item_words(item))


def _refine_map_param(state: MaterialState, prop: Entry, item: ast.RefineItem, direction: int) -> None:
    name = prop.get("map_param")
    roles = [role for role, ref in state.maps.items() if name in graph_params(ref["graph"])]
    if not roles:
        what = "no procedural map" if not state.maps else f"no map with '{name}'"
        state.diagnostics.append(
            warning(
                item.span,
                "W106",
                f"'{prop.key}' has nothing to act on: {noun_of(state).key} has {what}",
                ("maps come from words such as 'wood', 'marble', 'brushed' or 'rusty'",),
            )
        )
        return
    up, down = _step_fns(prop.get("step"))
    for role in roles:
        ref = state.maps[role]
        key = f"maps.{role}.{name}"
        default = graph_params(ref["graph"])[name][2]
        new = bracket_move(state, key, ref["params"].get(name, default), direction, up, down)
        ref["params"][name] = new
        state.note(key, new, f"refinements.{item.word.key} {prop.key}: bracket step", _item_words(item))


def _refine_adjective(
    state: MaterialState, ctx: Context, adjective: Entry, item: ast.RefineItem, direction: int
) -> None:
    """'stronger brushing': apply the adjective's formulas again at the weight step (or undo them)."""
    if adjective.key not in [k for k, _w in state.applied]:
        state.diagnostics.append(
            warning(
                item.span,
                "W104",
                f"'{_target_word(item).text}' is not part of this material",
                ("refine a word the material has, or add it to the phrase",),
            )
        )
        return
    w = ctx.settings.get("weight_step", 0.5)
    for effect in effects_for(adjective, state):
        if effect["param"] == "model":
            continue
        _refine_effect(state, effect, item, direction, w)
    for role in adjective.get("maps", {}):
        for name in adjective.get("maps")[role].get("weighted", []):
            _refine_weighted_map(state, role, name, item, direction, w)


def _refine_effect(state: MaterialState, effect: Effect, item: ast.RefineItem, direction: int, w: float) -> None:
    param, op, value, amount = effect["param"], effect["op"], effect.get("value"), effect.get("amount")
    up = lambda x: apply_op(op, x, value, w, amount)
    down = lambda x: invert_op(op, x, value, w, amount)
    new = bracket_move(state, param, state.params.get(param, 0.0), direction, up, down)
    rule = f"refinements.{item.word.key} {_target_word(item).key}: bracket step"
    state.record(param, new, rule, _item_words(item))


def _refine_weighted_map(
    state: MaterialState, role: str, name: str, item: ast.RefineItem, direction: int, w: float
) -> None:
    ref = state.maps.get(role)
    if ref is None:
        return
    key = f"maps.{role}.{name}"
    new = bracket_move(
        state, key, ref["params"].get(name, 1.0), direction, lambda x: x * (1 + w), lambda x: x / (1 + w)
    )
    ref["params"][name] = new
    state.note(key, new, f"refinements.{item.word.key} {_target_word(item).key}: bracket step", _item_words(item))


def _item_words(item: ast.RefineItem) -> tuple[ast.Word, ...]:
    target = item.target
    extra = target.words if isinstance(target, ast.Colour) else ((target,) if target else ())
    return (item.word, *extra)
