"""'less glossy', 'more matte', 'stronger brushing': an adjective's parameters, moved relative to now.

An adjective's formula says which way it pushes a parameter (its pole): 'glossy' (roughness = 0.08)
and 'shiny' (roughness * 0.5) push roughness down, 'matte' (= 0.8) pushes it up. "more X" moves
the parameter towards X's pole, "less X" away from it, on the bracket of that parameter (the same
one 'rougher' and 'less diffuse' use, in the parameter's own direction). The step is the
adjective's formula at the weight step (paper: stronger brushing = brushed again at 0.5); where
that formula cannot move the value the right way (a 'set' already reached, a factor of zero), it
is one step of the property that owns the parameter (properties.toml: roughness +- 0.1).

An adjective that only sets parameters refines any material ('less glossy' on plain plastic); one
that brings a treatment (a map, a coat, a material) must be part of the material (W104).
"""

from __future__ import annotations

from typing import NamedTuple

from .. import ast
from ..diagnostics import Diagnostic, warning
from ..formulas import apply_op, invert_op
from ..lexicon import Entry
from ..state import Context, MaterialState
from .base import noun_of
from .bracket import Move, Step, bracket_move, scaled_steps
from .refine_property import refine_property
from .refine_target import highlight_shown, item_text, item_words, move_sigma_too, note, note_unmoved_number, surface
from .refine_wear import refine_drawn_maps, refine_missing_treatment, refine_weighted_map
from .subsurface import refine_translucency
from .words import Effect, effects_for


class Strength(NamedTuple):
    """How strongly a refinement acts: its adjective formula's weight (the weight step times the
    adverbs') and the adverbs' own weight (for property steps and the bracket)."""

    formula: float
    adverbs: float


MIN_MOVE = 1e-6  # a formula step smaller than this does not move the value
MIDDLE = 1 / 6  # a 'set' this close to its range's centre (a fraction of the range) has no pole: it is a target


def refine_adjective(
    state: MaterialState, ctx: Context, adjective: Entry, item: ast.RefineItem, direction: int, weight: float
) -> None:
    if adjective.get("subsurface"):  # 'more translucent': the medium's mean free path (passes/subsurface.py)
        refine_translucency(state, adjective, item, direction, weight)
        return
    word = _target(item)
    applied = adjective.key in [k for k, _w in state.applied]
    effects = [e for e in effects_for(adjective, state) if e["param"] != "model"]
    if not applied and (brings_treatment(adjective) or not effects):
        if _refined_as_property(state, ctx, item, direction, weight):  # 'more grainy' oak: more grain
            return
        if not (brings_treatment(adjective) and refine_missing_treatment(state, ctx, adjective, item, direction)):
            state.diagnostics.append(_absent(state, adjective, item))  # 'more worn' leather: a little wear
        return
    if not applied:
        state.diagnostics.append(
            note(
                item.span,
                "N104",
                f"read '{item_text(item)}' relative to the current material ('{word.text}' is not among its describing words)",
            )
        )
    w = ctx.settings.get("weight_step", 0.5) * weight
    for effect in effects:
        _refine_effect(state, ctx, effect, item, direction, Strength(w, weight))
    for role in adjective.get("maps", {}):
        for name in adjective.get("maps")[role].get("weighted", []):
            refine_weighted_map(state, role, name, item, direction, w, weight)
    if applied and adjective.get("features_on") and not adjective.get("maps"):  # 'more weathered' bronze
        refine_drawn_maps(state, ctx, [adjective], item, direction)


def _refined_as_property(
    state: MaterialState, ctx: Context, item: ast.RefineItem, direction: int, weight: float
) -> bool:
    """'more grainy' on a wood: the word's stem is a map property of the material's map (grain)."""
    from .refine_missing_map import map_property_of

    prop = map_property_of(state, ctx, _target(item).text.lower())
    if prop is None:
        return False
    message = (
        f"read '{item_text(item)}' as '{item.word.text} {prop.key}' (the material's map has no '{_target(item).text}')"
    )
    state.diagnostics.append(note(item.span, "N104", message))
    refine_property(state, ctx, prop, item, direction, weight)
    return True


def _absent(state: MaterialState, adjective: Entry, item: ast.RefineItem) -> Diagnostic:
    """W104 for a treatment the material lacks, with the phrase that adds it."""
    phrase = f"lightly {adjective.key} {noun_of(state).key}"
    return warning(
        item.span,
        "W104",
        f"'{_target(item).text}' is not part of this material",
        (f"add it to the phrase, e.g. '{phrase}', or refine a word it has",),
    )


def _target(item: ast.RefineItem) -> ast.Word:
    assert isinstance(item.target, ast.Word), item
    return item.target


def brings_treatment(adjective: Entry) -> bool:
    return any(adjective.get(field) for field in ("maps", "coat", "material", "features_on"))


def _refine_effect(
    state: MaterialState,
    ctx: Context,
    effect: Effect,
    item: ast.RefineItem,
    direction: int,
    strength: Strength,
) -> None:
    param = effect["param"]
    holder, key, limits = surface(state, param)
    current = holder.get(param, 0.0)
    if isinstance(current, list):
        _refine_list_effect(state, effect, item, direction, strength)
        return
    pole = _pole(effect, current, limits) or _pole_from_noun(state, key, effect)
    if pole == 0:
        return
    param_direction = direction * pole
    step = _step(ctx, effect, current, param_direction, direction, strength)
    move = Move(param_direction, step, strength.adverbs, limits)
    new = bracket_move(state.brackets, key, current, move)
    holder[param] = new
    way = "up" if param_direction > 0 else "down"
    rule = f"refinements.{item.word.key} {_target(item).key}: {param} {way} (bracket step)"
    state.note(key, new, rule, item_words(item))
    note_unmoved_number(state, item, key, current, new)
    move_sigma_too(state, key, move, item_words(item), rule)
    highlight_shown(state, ctx, key, current, new, item_words(item), rule)


def _pole(effect: Effect, current: float, limits: tuple[float, float] | None) -> int:
    """Which way the adjective pushes the parameter: +1 up, -1 down, 0 nowhere."""
    op, value = effect["op"], effect.get("value")
    if not isinstance(value, (int, float)):
        return 0
    if op == "mul":
        return _sign(value - 1.0)
    if op == "add":
        return _sign(value)
    low, high = limits or (0.0, 1.0)
    centre = (low + high) / 2
    if abs(value - centre) > MIDDLE * (high - low):
        return _sign(value - centre)  # glossy, matte: a pole
    return _sign(value - current)  # satin: a target in the middle


def _pole_from_noun(state: MaterialState, key: str, effect: Effect) -> int:
    """A middle target the parameter already stands at ('less frosted' on frosted glass at 0.5): the
    way the adjective took the parameter from the noun's own value (glass 0.0 -> frosted 0.5: up);
    0 when the noun set none, or the same."""
    value = effect.get("value")
    if effect["op"] != "set" or not isinstance(value, (int, float)):
        return 0
    own = next((s.value for s in state.provenance.get(key, ()) if s.rule.startswith("nouns.")), None)
    return _sign(value - own) if isinstance(own, (int, float)) else 0


def _sign(x: float) -> int:
    return (x > 0) - (x < 0)


def _step(
    ctx: Context, effect: Effect, current: float, param_direction: int, direction: int, strength: Strength
) -> Step:
    """The adjective's formula at the weight step when it moves the value the right way by a
    visible amount; else the parameter's own property step (properties.toml). Visible: at least
    the settings' `visible_step_share` of that property step ('less shiny' on piano black: the
    factor of 'shiny' moves roughness 0.02 -> 0.027, which no one sees, so it takes the step of
    'rougher', 0.12; the paper overlay's share is 0: its formulas step exactly)."""
    op, value, amount = effect["op"], effect.get("value"), effect.get("amount")
    w = strength.formula
    formula: Step = (
        (lambda x: apply_op(op, x, value, w, amount))
        if direction > 0
        else (lambda x: invert_op(op, x, value, w, amount))
    )
    prop = _property_of(ctx, effect["param"])
    if prop is None:
        return formula
    up, down = scaled_steps(prop.get("step"), strength.adverbs)
    own = up if param_direction > 0 else down
    moved = (formula(current) - current) * param_direction
    if op != "set" and moved > MIN_MOVE and not _invisible(op, current, moved, abs(own(current) - current), ctx):
        return formula
    return own


def _invisible(op: str, current: float, moved: float, own_step: float, ctx: Context) -> bool:
    """Whether a factor's step is too small to see: near zero (below one property step) a factor
    hardly moves the value ('less shiny' on piano black, roughness 0.02), so a move below the
    settings' `visible_step_share` of the property's step is none (0 in the paper overlay)."""
    share = float(ctx.settings.get("visible_step_share", 0.0))
    return op == "mul" and abs(current) < own_step and moved < share * own_step


def _property_of(ctx: Context, param: str) -> Entry | None:
    """The property that owns a parameter ('roughness', 'anisotropy'), for its step."""
    entry = ctx.lexicon.entry("properties", param)
    if entry is not None and entry.get("param") == param and not entry.get("invert"):
        return entry
    return None


def _refine_list_effect(
    state: MaterialState, effect: Effect, item: ast.RefineItem, direction: int, strength: Strength
) -> None:
    """A colour an adjective sets: towards it ("more"), or away from it ("less")."""
    param, op, value, amount = effect["param"], effect["op"], effect.get("value"), effect.get("amount")
    w = strength.formula
    step: Step = (
        (lambda x: apply_op(op, x, value, w, amount))
        if direction > 0
        else (lambda x: invert_op(op, x, value, w, amount))
    )
    key = f"{param}:{_target(item).key}"
    new = bracket_move(
        state.brackets, key, state.params.get(param), Move(direction, step, strength.adverbs, (0.0, 1.0))
    )
    state.record(param, new, f"refinements.{item.word.key} {_target(item).key}: bracket step", item_words(item))
