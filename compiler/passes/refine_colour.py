"""Colour refinements: 'darker' / 'lighter' (the paper's linear steps), 'bluer' / 'warmer' (OKLab
steps, refinements.toml `ops`), 'more saturated' / 'less colour' (OKLCh chroma).

Each colour axis keeps its own bracket: lightness on the colour's key (darker and lighter share it,
paper §4.2), a hue axis on `<colour>.<axis>` (bluer and yellower share 'blue-yellow'), chroma on
`<colour>.chroma`. A bracket whose colour another axis has moved since is forgotten
(passes/bracket.py), so the axes never pull each other back.
"""

from __future__ import annotations

import math
from typing import Any

from .. import ast
from ..colour import linear_to_oklab, oklab_to_linear_in_gamut
from ..lexicon import Entry
from ..state import Context, MaterialState
from .bracket import Move, Step, bracket_move, scaled_steps
from .colour_steps import (
    Ops,
    chroma_step,
    colour_step,
    colour_towards,
    hue_share,
    hue_step,
    less_of,
    opposite_ops,
    scaled_ops,
    shade_step,
    yellow_kept,
)
from .colours import colour_text, resolve_colour
from .layer_shade import shade_layers
from .refine_target import item_text, item_words, note

COLOUR_LIMITS = (0.0, 1.0)
LIGHTNESS_AXIS = "lightness"  # the axis of darker / lighter: its bracket is on the colour's own key
NEUTRAL_CHROMA = 1e-4  # an OKLCh chroma below this has no hue to saturate
UNMOVED = 1e-4  # a colour step smaller than this (per linear channel) is no visible change
MID_GREY = [0.18, 0.18, 0.18]  # where the base colour cannot move, a layer takes the step a mid grey would


def refine_colour(state: MaterialState, entry: Entry, item: ast.RefineItem, direction: int, weight: float) -> None:
    param = _colour_param(state, item)
    holder, name = _colour_holder(state, param)
    ops = entry.get("ops")
    if ops:
        step: Step = on_apparent(state, param, lambda x: colour_step(x, scaled_ops(ops, weight)))
        axis = entry.get("axis", entry.key)
        key = param if axis == LIGHTNESS_AXIS else f"{param}.{axis}"
    else:
        paper = scaled_steps(entry.get("step"), weight)[0]  # the paper's step, on the parameter itself
        step = lambda x: yellow_kept(x, paper(x))
        key = param
    current = holder[name]
    new = bracket_move(state.brackets, key, current, Move(direction, step, weight, COLOUR_LIMITS))
    holder[name] = new
    state.note(param, new, f"refinements.{entry.key}: bracket step", item_words(item))
    if param == "base_color" and key == param:  # darker / lighter: a layer's own colours follow
        moved = max(abs(a - b) for a, b in zip(current, new)) > UNMOVED
        before, after = (current, new) if moved else (MID_GREY, step(MID_GREY))  # a metal at its top
        if shade_layers(state, before, after, item_words(item)):
            return  # the layer moved: the line did something ('tarnished silver', then 'lighter')
    note_unmoved(state, item, param, current, new)


def on_apparent(state: MaterialState, param: str, step: Step) -> Step:
    """A metal's visible colour is its base colour times its measured reflectance f0: a hue or
    chroma step acts on that, and the base colour becomes what gives the result; where that would
    need a channel above 1 (more than the metal reflects), the base colour is the one of two that
    shows the colour nearest (in OKLab) to the one asked for: that channel held at 1, or the whole
    tint scaled down (hue and saturation kept, brightness given up)."""
    f0 = state.params.get("f0")
    if param != "base_color" or state.kind != "conductor" or not isinstance(f0, list):
        return step
    return lambda base: _base_for(step(_shown(base, f0)), f0, base)


def _shown(base: list[float], f0: list[float]) -> list[float]:
    return [b * f for b, f in zip(base, f0)]


def _base_for(seen: list[float], f0: list[float], base: list[float]) -> list[float]:
    """The base colour in [0, 1] that shows (nearest to) `seen` on a metal of reflectance f0."""
    wanted = [max(v, 0.0) / f if f > 0 else b for v, f, b in zip(seen, f0, base)]
    top = max(wanted, default=0.0)
    if top <= 1.0:
        return wanted
    held = [min(w, 1.0) for w in wanted]
    scaled = [w / top for w in wanted]
    goal = linear_to_oklab(seen)
    # the nearest of the two, or the base as it is when neither comes nearer to what was asked
    return min((base, held, scaled), key=lambda b: _lab_distance(linear_to_oklab(_shown(b, f0)), goal))


def _lab_distance(p: list[float], q: list[float]) -> float:
    return sum((x - y) ** 2 for x, y in zip(p, q))


def apparent(state: MaterialState, param: str, value: list[float]) -> list[float]:
    f0 = state.params.get("f0")
    if param != "base_color" or state.kind != "conductor" or not isinstance(f0, list):
        return value
    return [b * f for b, f in zip(value, f0)]


def note_unmoved(state: MaterialState, item: ast.RefineItem, param: str, before: Any, after: Any) -> None:
    """A colour refinement that could not move the colour says why (a note, never a warning)."""
    if max(abs(a - b) for a, b in zip(before, after)) > UNMOVED:
        return
    why = "its end of the colour range"
    if param == "base_color" and state.kind == "conductor":
        why = "a metal's colour is its measured reflectance, which a tint can only lower"
    state.diagnostics.append(note(item.span, "N106", f"'{item_text(item)}' leaves the colour as it is: {why}"))


def _colour_param(state: MaterialState, item: ast.RefineItem) -> str:
    """'darker blue' acts on the colour that 'blue' set; plain 'darker' on the base colour."""
    if isinstance(item.target, ast.Colour) and item.target.base is not None:
        key = item.target.base.key
        for param in ("coat.color", "base_color"):
            if key in state.words_of(param):
                return param
    return "base_color"


def refine_saturation(state: MaterialState, ctx: Context, item: ast.RefineItem, direction: int, weight: float) -> None:
    """'more saturated', 'less colour', 'more blue': the OKLCh chroma of the base colour, hue and
    lightness kept (the step: properties.toml 'colour', a chroma factor)."""
    current = state.params["base_color"]
    _l, a, b = linear_to_oklab(apparent(state, "base_color", current))
    if (a * a + b * b) ** 0.5 < NEUTRAL_CHROMA:
        state.diagnostics.append(
            note(item.span, "N105", f"'{item_text(item)}' has no hue to act on: the colour is a neutral grey")
        )
        return
    factor = ctx.lexicon.require("properties", "colour").get("step")["value"] ** weight
    scale = factor if direction > 0 else 1 / factor
    step = on_apparent(state, "base_color", lambda x: chroma_step(x, scale))
    new = bracket_move(state.brackets, "base_color.chroma", current, Move(direction, step, weight, COLOUR_LIMITS))
    state.record("base_color", new, f"refinements.{item.word.key}: saturation", item_words(item))
    note_unmoved(state, item, "base_color", current, new)


HUE_STEP = 0.25  # 'more blue': a quarter of the way to blue's OKLab a, b (as refinements.toml's 'bluer')


def refine_named_colour(
    state: MaterialState, ctx: Context, item: ast.RefineItem, direction: int, weight: float
) -> None:
    """'more blue' / 'less red': towards a named colour's hue, or its share taken away; a shade
    alone ('more vivid', 'less muted') applies the shade's operations at the weight step, or
    their opposite."""
    target = item.target
    assert isinstance(target, ast.Colour), item
    if _shade_only(target, ctx):
        _refine_shade(state, ctx, item, target, direction, weight)
        return
    param = _colour_param(state, item)
    holder, name = _colour_holder(state, param)
    whole = ctx.lexicon.require("refinements", item.word.key).get("towards")
    if whole is not None:  # 'closer to burgundy', 'more of a burgundy': the whole colour
        _closer(state, item, param, resolve_colour(target, ctx), 1.0 - (1.0 - float(whole)) ** weight)
        return
    named = resolve_colour(target, ctx)
    _l, a, b = linear_to_oklab(named)
    amount = 1.0 - (1.0 - HUE_STEP) ** weight
    if direction > 0 and math.hypot(a, b) < _achromatic():  # 'more grey' on black: a step of the whole colour
        _closer(state, item, param, named, amount)
        return
    away_from = _away_from_achromatic(_l, math.hypot(a, b), apparent(state, param, holder[name]))
    if direction < 0 and away_from is not None:  # 'less black' on black: a step toward a mid grey
        _closer(state, item, param, away_from, amount)
        return
    if direction < 0 and param == "base_color" and _a_mid_grey(_l, math.hypot(a, b)):
        refine_saturation(state, ctx, item, 1, weight)  # 'less grey' on sage green: more of its own hue
        return
    if direction < 0 and hue_share(apparent(state, param, holder[name]), (a, b)) < NEUTRAL_CHROMA:
        state.diagnostics.append(
            note(item.span, "N105", f"'{item.word.text} {colour_text(target)}': the colour has none of it to take away")
        )
        return
    towards: Step = lambda x: hue_step(x, (a, b), amount)
    away: Step = lambda x: less_of(x, (a, b), amount)
    key = f"{param}.hue:{colour_text(target)}"
    move = Move(direction, on_apparent(state, param, towards if direction > 0 else away), weight, COLOUR_LIMITS)
    current = holder[name]
    new = bracket_move(state.brackets, key, current, move)
    holder[name] = new
    note_unmoved(state, item, param, current, new)
    state.note(param, new, f"refinements.{item.word.key} {colour_text(target)}: hue step", item_words(item))


def _away_from_achromatic(lightness: float, chroma: float, current: list[float]) -> list[float] | None:
    """The mid grey a step away from a named black or white goes toward (colour_rules.toml
    `achromatic_away`), where the material's colour is itself near that black or white ('less
    black' on black plastic; not on navy, which has no black to take away); for a colour with a hue
    ('too white' on limed oak) that colour at the mid lightness; None otherwise."""
    from ..lexicon_load import colour_rules

    rule = colour_rules()["achromatic_away"]
    mid, far = float(rule["mid_lightness"]), float(rule["min_distance"])
    now_l, now_a, now_b = linear_to_oklab(current)
    if chroma >= _achromatic() or abs(lightness - mid) < far:
        return None
    if (now_l - mid) * (lightness - mid) <= 0 or abs(now_l - mid) < far:
        return None  # a colour on the other side of the grey or near it
    if math.hypot(now_a, now_b) >= _achromatic():  # 'too white' on limed oak: its own hue, toward the mid lightness
        return oklab_to_linear_in_gamut([mid, now_a, now_b])
    return [mid**3] * 3  # OKLab L of a grey is the cube root of its linear value


def _a_mid_grey(lightness: float, chroma: float) -> bool:
    """A named colour without a hue nearer the mid grey than a black or white is (colour_rules.toml
    `achromatic_away`): 'grey', 'gray', not 'white'."""
    from ..lexicon_load import colour_rules

    rule = colour_rules()["achromatic_away"]
    return chroma < _achromatic() and abs(lightness - float(rule["mid_lightness"])) < float(rule["min_distance"])


def _achromatic() -> float:
    """The OKLCh chroma under which a named colour has no hue to step toward (colour_rules.toml)."""
    from ..lexicon_load import colour_rules

    return float(colour_rules()["achromatic_chroma"])


def _closer(state: MaterialState, item: ast.RefineItem, param: str, goal: list[float], amount: float) -> None:
    """A step of the whole colour (OKLab lightness, a and b) towards the named one: 'more of a
    burgundy' on red is a darker, duller red; on a metal, its visible colour moves (on_apparent)."""
    assert isinstance(item.target, ast.Colour), item
    holder, name = _colour_holder(state, param)
    key = f"{param}.towards:{colour_text(item.target)}"
    step = on_apparent(state, param, lambda x: colour_towards(x, goal, amount))
    current = holder[name]
    new = bracket_move(state.brackets, key, current, Move(1, step, 1.0, COLOUR_LIMITS))
    holder[name] = new
    note_unmoved(state, item, param, current, new)
    state.note(param, new, f"refinements.{item.word.key} {colour_text(item.target)}: towards it", item_words(item))


def _colour_holder(state: MaterialState, param: str) -> tuple[dict[str, Any], str]:
    if param == "coat.color" and state.coat is not None:
        return state.coat, "color"
    return state.params, "base_color"


def _shade_only(target: ast.Colour, ctx: Context) -> bool:
    """'vivid', 'muted': shades with no colour ('reddish' alone is a colour: resolve_colour)."""
    if target.base is not None or not target.shades:
        return False
    return ctx.lexicon.entry("colours", target.shades[-1].key) is None


def _refine_shade(
    state: MaterialState, ctx: Context, item: ast.RefineItem, target: ast.Colour, direction: int, weight: float
) -> None:
    ops: Ops = []
    for word in target.shades:
        ops += ctx.lexicon.require("shades", word.key).get("ops")
    w = ctx.settings.get("weight_step", 0.5) * weight
    step_ops = scaled_ops(ops, w) if direction > 0 else opposite_ops(scaled_ops(ops, w))
    key = f"base_color.shade:{colour_text(target)}"
    move = Move(direction, lambda x: shade_step(x, step_ops), weight, COLOUR_LIMITS)
    new = bracket_move(state.brackets, key, state.params["base_color"], move)
    state.record("base_color", new, f"refinements.{item.word.key} {colour_text(target)}: shade step", item_words(item))
