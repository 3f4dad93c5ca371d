"""Colour refinements: 'darker' / 'lighter' (the paper's linear steps), 'bluer' / 'warmer' (OKLab
steps, refinements.toml `ops`), 'more saturated' / 'less colour' (OKLCh chroma).

Each colour axis keeps its own bracket: lightness on the colour's key (darker and lighter share it,
paper §4.2), a hue axis on `<colour>.<axis>` (bluer and yellower share 'blue-yellow'), chroma on
`<colour>.chroma`. A bracket whose colour another axis has moved since is forgotten
(passes/bracket.py), so the axes never pull each other back.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

from .. import ast
from ..colour import apply_ops, linear_to_oklab, oklab_to_linear, oklab_to_linear_in_gamut
from ..degrees import weighted_shade
from ..lexicon import Entry
from ..state import Context, MaterialState
from .bracket import Move, Step, bracket_move, scaled_steps
from .colours import colour_text, resolve_colour
from .refine_target import item_text, item_words, note

COLOUR_LIMITS = (0.0, 1.0)
MAX_LIGHTNESS_GIVEN = 0.1  # OKLab L a hue or chroma step may give up for its chroma (our choice)
LIGHTNESS_SEARCH_STEP = 0.005
LIGHTNESS_AXIS = "lightness"  # the axis of darker / lighter: its bracket is on the colour's own key
NEUTRAL_CHROMA = 1e-4  # an OKLCh chroma below this has no hue to saturate
UNMOVED = 1e-4  # a colour step smaller than this (per linear channel) is no visible change
Ops = list[dict[str, Any]]


def refine_colour(state: MaterialState, entry: Entry, item: ast.RefineItem, direction: int, weight: float) -> None:
    param = _colour_param(state, item)
    holder, name = (
        (state.coat, "color") if param == "coat.color" and state.coat is not None else (state.params, "base_color")
    )
    ops = entry.get("ops")
    if ops:
        step: Step = on_apparent(state, param, lambda x: colour_step(x, scaled_ops(ops, weight)))
        axis = entry.get("axis", entry.key)
        key = param if axis == LIGHTNESS_AXIS else f"{param}.{axis}"
    else:
        step = scaled_steps(entry.get("step"), weight)[0]  # the paper's step, on the parameter itself
        key = param
    current = holder[name]
    new = bracket_move(state.brackets, key, current, Move(direction, step, weight, COLOUR_LIMITS))
    holder[name] = new
    state.note(param, new, f"refinements.{entry.key}: bracket step", item_words(item))
    note_unmoved(state, item, param, current, new)


def on_apparent(state: MaterialState, param: str, step: Step) -> Step:
    """A metal's visible colour is its base colour times its measured reflectance f0: a hue or
    chroma step acts on that, and the base colour becomes what gives the result (within [0, 1])."""
    f0 = state.params.get("f0")
    if param != "base_color" or state.kind != "conductor" or not isinstance(f0, list):
        return step
    return lambda base: [
        min(max(v / f, 0.0), 1.0) if f > 0 else b for v, f, b in zip(step([b * f for b, f in zip(base, f0)]), f0, base)
    ]


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


def colour_step(rgb: list[float], ops: Ops) -> list[float]:
    """A refinement's colour operations (shades.toml's), a hue shift ('toward') by hue_step."""
    out = list(rgb)
    for op in ops:
        out = hue_step(out, op["oklab"][1:], op["amount"]) if op["op"] == "toward" else apply_ops(out, [op])
    return out


def hue_step(rgb: list[float], ab: Sequence[float], amount: float) -> list[float]:
    """OKLab a, b moved `amount` of the way toward `ab`, lightness kept where the gamut allows."""
    L, a, b = linear_to_oklab(rgb)
    return fit_in_gamut(L, a + (ab[0] - a) * amount, b + (ab[1] - b) * amount)


def chroma_step(rgb: list[float], scale: float) -> list[float]:
    """OKLCh chroma times `scale`, hue kept, lightness kept where the gamut allows."""
    L, a, b = linear_to_oklab(rgb)
    return fit_in_gamut(L, a * scale, b * scale)


def fit_in_gamut(L: float, a: float, b: float) -> list[float]:
    """Linear RGB of an OKLab colour a refinement asked for. Where the sRGB gamut has no room for its
    chroma at this lightness (near white, near black, at a saturated colour's edge), the colour gives
    up a little lightness (at most MAX_LIGHTNESS_GIVEN, the nearest that works) before it gives up
    chroma, so 'warmer' on white paint is a warm white and 'more saturated' red gains some chroma."""
    if _fits((L, a, b)):
        return oklab_to_linear((L, a, b))
    window = [L + d for d in _offsets() if 0.0 <= L + d <= 1.0]
    for lightness in window:
        if _fits((lightness, a, b)):
            return oklab_to_linear_in_gamut((lightness, a, b))
    best = max(window, key=lambda lightness: _chroma_kept(lightness, a, b) - 1e-6 * abs(lightness - L))
    return oklab_to_linear_in_gamut((best, a, b))


def _offsets() -> list[float]:
    """0, then +-0.005, +-0.01, ... up to MAX_LIGHTNESS_GIVEN: the nearest lightness first."""
    n = round(MAX_LIGHTNESS_GIVEN / LIGHTNESS_SEARCH_STEP)
    out = [0.0]
    for i in range(1, n + 1):
        out += [-i * LIGHTNESS_SEARCH_STEP, i * LIGHTNESS_SEARCH_STEP]
    return out


def _chroma_kept(L: float, a: float, b: float) -> float:
    """The largest share of the chroma (a, b) that fits the gamut at lightness L (bisection)."""
    low, high = 0.0, 1.0
    for _ in range(20):
        mid = (low + high) / 2
        low, high = (mid, high) if _fits((L, a * mid, b * mid)) else (low, mid)
    return low


def _fits(lab: Sequence[float]) -> bool:
    return all(-1e-7 <= c <= 1 + 1e-7 for c in oklab_to_linear(lab))


def _colour_param(state: MaterialState, item: ast.RefineItem) -> str:
    """'darker blue' acts on the colour that 'blue' set; plain 'darker' on the base colour."""
    if isinstance(item.target, ast.Colour) and item.target.base is not None:
        key = item.target.base.key
        for param in ("coat.color", "base_color"):
            if key in state.words_of(param):
                return param
    return "base_color"


def scaled_ops(ops: Ops, weight: float) -> Ops:
    """A colour step (shades' ops) taken `weight` times (compiler/degrees.py): amounts 1 - (1 - t)^w, scales s^w."""
    return ops if weight == 1.0 else [weighted_shade(op, weight) for op in ops]


def refine_saturation(state: MaterialState, ctx: Context, item: ast.RefineItem, direction: int, weight: float) -> None:
    """'more saturated', 'less colour', 'more blue': the OKLCh chroma of the base colour, hue and
    lightness kept (the step: properties.toml 'colour', a chroma factor)."""
    current = state.params["base_color"]
    _l, a, b = linear_to_oklab(apparent(state, "base_color", current))
    if (a * a + b * b) ** 0.5 < NEUTRAL_CHROMA:
        state.diagnostics.append(
            note(item.span, "N105", f"'{item.word.text}' has no hue to act on: the colour is a neutral grey")
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
    _l, a, b = linear_to_oklab(resolve_colour(target, ctx))
    amount = 1.0 - (1.0 - HUE_STEP) ** weight
    if direction < 0 and _share(apparent(state, param, holder[name]), (a, b)) < NEUTRAL_CHROMA:
        state.diagnostics.append(
            note(item.span, "N105", f"'{item.word.text} {colour_text(target)}': the colour has none of it to take away")
        )
        return
    towards: Step = lambda x: hue_step(x, (a, b), amount)
    away: Step = lambda x: _less_of(x, (a, b), amount)
    key = f"{param}.hue:{colour_text(target)}"
    move = Move(direction, on_apparent(state, param, towards if direction > 0 else away), weight, COLOUR_LIMITS)
    current = holder[name]
    new = bracket_move(state.brackets, key, current, move)
    holder[name] = new
    note_unmoved(state, item, param, current, new)
    state.note(param, new, f"refinements.{item.word.key} {colour_text(target)}: hue step", item_words(item))


def _colour_holder(state: MaterialState, param: str) -> tuple[dict[str, Any], str]:
    if param == "coat.color" and state.coat is not None:
        return state.coat, "color"
    return state.params, "base_color"


def _shade_only(target: ast.Colour, ctx: Context) -> bool:
    """'vivid', 'muted': shades with no colour ('reddish' alone is a colour: resolve_colour)."""
    if target.base is not None or not target.shades:
        return False
    return ctx.lexicon.entry("colours", target.shades[-1].key) is None


def _unit(ab: tuple[float, float]) -> tuple[float, float]:
    norm = (ab[0] ** 2 + ab[1] ** 2) ** 0.5
    return (ab[0] / norm, ab[1] / norm) if norm > 0 else (0.0, 0.0)


def _share(rgb: list[float], ab: tuple[float, float]) -> float:
    """How much of the hue `ab` the colour has: its OKLab a, b along ab's direction (0 when none)."""
    _l, a, b = linear_to_oklab(rgb)
    u = _unit(ab)
    return max(0.0, a * u[0] + b * u[1])


def _less_of(rgb: list[float], ab: tuple[float, float], amount: float) -> list[float]:
    """The colour with `amount` of its share of the hue `ab` taken away, lightness kept."""
    L, a, b = linear_to_oklab(rgb)
    u, share = _unit(ab), _share(rgb, ab)
    return oklab_to_linear_in_gamut((L, a - amount * share * u[0], b - amount * share * u[1]))


def _refine_shade(
    state: MaterialState, ctx: Context, item: ast.RefineItem, target: ast.Colour, direction: int, weight: float
) -> None:
    ops: Ops = []
    for word in target.shades:
        ops += ctx.lexicon.require("shades", word.key).get("ops")
    w = ctx.settings.get("weight_step", 0.5) * weight
    step_ops = scaled_ops(ops, w) if direction > 0 else _opposite_ops(scaled_ops(ops, w))
    key = f"base_color.shade:{colour_text(target)}"
    move = Move(direction, lambda x: apply_ops(x, step_ops), weight, COLOUR_LIMITS)
    new = bracket_move(state.brackets, key, state.params["base_color"], move)
    state.record("base_color", new, f"refinements.{item.word.key} {colour_text(target)}: shade step", item_words(item))


def _opposite_ops(ops: Ops) -> Ops:
    """A shade's operations undone, last first: chroma scales inverted, lightness moved the other way
    (a hue shift 'toward' has no opposite and is left out)."""
    out: Ops = []
    for op in reversed(ops):
        if op["op"] == "chroma" and op["scale"] > 0:
            out.append({**op, "scale": 1.0 / op["scale"]})
        elif op["op"] == "lightness":
            out.append({**op, "toward": 1.0 - op["toward"]})
        elif op["op"] == "mul" and isinstance(op.get("value"), (int, float)) and op["value"] > 0:
            out.append({**op, "value": 1.0 / op["value"]})
    return out
