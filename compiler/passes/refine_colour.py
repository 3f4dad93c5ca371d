"""Colour refinements: 'darker' / 'lighter' (the paper's linear steps), 'bluer' / 'warmer' (OKLab
steps, refinements.toml `ops`), 'more saturated' / 'less colour' (OKLCh chroma).

Each colour axis keeps its own bracket: lightness on the colour's key (darker and lighter share it,
paper §4.2), a hue axis on `<colour>.<axis>` (bluer and yellower share 'blue-yellow'), chroma on
`<colour>.chroma`. A bracket whose colour another axis has moved since is forgotten
(passes/bracket.py), so the axes never pull each other back.
"""

from __future__ import annotations

from typing import Any

from .. import ast
from ..colour import apply_ops, linear_to_oklab, scale_chroma
from ..lexicon import Entry
from ..state import Context, MaterialState
from .bracket import Move, Step, bracket_move, scaled_steps
from .refine_target import item_words, note

COLOUR_LIMITS = (0.0, 1.0)
LIGHTNESS_AXIS = "lightness"  # the axis of darker / lighter: its bracket is on the colour's own key
NEUTRAL_CHROMA = 1e-4  # an OKLCh chroma below this has no hue to saturate
Ops = list[dict[str, Any]]


def refine_colour(state: MaterialState, entry: Entry, item: ast.RefineItem, direction: int, weight: float) -> None:
    param = _colour_param(state, item)
    holder, name = (
        (state.coat, "color") if param == "coat.color" and state.coat is not None else (state.params, "base_color")
    )
    ops = entry.get("ops")
    if ops:
        step: Step = lambda x: apply_ops(x, scaled_ops(ops, weight))
        axis = entry.get("axis", entry.key)
        key = param if axis == LIGHTNESS_AXIS else f"{param}.{axis}"
    else:
        step = scaled_steps(entry.get("step"), weight)[0]  # the entry's own step goes its own way
        key = param
    new = bracket_move(state.brackets, key, holder[name], Move(direction, step, weight, COLOUR_LIMITS))
    holder[name] = new
    state.note(param, new, f"refinements.{entry.key}: bracket step", item_words(item))


def _colour_param(state: MaterialState, item: ast.RefineItem) -> str:
    """'darker blue' acts on the colour that 'blue' set; plain 'darker' on the base colour."""
    if isinstance(item.target, ast.Colour) and item.target.base is not None:
        key = item.target.base.key
        for param in ("coat.color", "base_color"):
            if key in state.words_of(param):
                return param
    return "base_color"


def scaled_ops(ops: Ops, weight: float) -> Ops:
    """A colour step (shades' ops) taken `weight` times: amounts 1 - (1 - t)^w, scales s^w."""
    if weight == 1.0:
        return ops
    out = []
    for op in ops:
        scaled = dict(op)
        if "amount" in op:
            scaled["amount"] = 1.0 - (1.0 - op["amount"]) ** weight
        if "scale" in op:
            scaled["scale"] = op["scale"] ** weight
        out.append(scaled)
    return out


def refine_saturation(state: MaterialState, ctx: Context, item: ast.RefineItem, direction: int, weight: float) -> None:
    """'more saturated', 'less colour', 'more blue': the OKLCh chroma of the base colour, hue and
    lightness kept (the step: properties.toml 'colour', a chroma factor)."""
    current = state.params["base_color"]
    _l, a, b = linear_to_oklab(current)
    if (a * a + b * b) ** 0.5 < NEUTRAL_CHROMA:
        state.diagnostics.append(
            note(item.span, "N105", f"'{item.word.text}' has no hue to act on: the colour is a neutral grey")
        )
        return
    factor = ctx.lexicon.require("properties", "colour").get("step")["value"] ** weight
    step: Step = (lambda x: scale_chroma(x, factor)) if direction > 0 else (lambda x: scale_chroma(x, 1 / factor))
    new = bracket_move(state.brackets, "base_color.chroma", current, Move(direction, step, weight, COLOUR_LIMITS))
    state.record("base_color", new, f"refinements.{item.word.key}: saturation", item_words(item))
