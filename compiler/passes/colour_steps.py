"""Colour steps of refinements, in OKLab / OKLCh (Ottosson 2020; compiler/colour.py): a hue shift,
a chroma factor, a named colour's share taken away, a shade's operations or their opposite. Each
keeps the OKLab lightness where the sRGB gamut allows and gives up at most MAX_LIGHTNESS_GIVEN of
it before it gives up chroma."""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

from ..colour import apply_ops, darkened_yellow, linear_to_oklab, oklab_to_linear, oklab_to_linear_in_gamut
from ..degrees import weighted_shade

MAX_LIGHTNESS_GIVEN = 0.1  # OKLab L a hue or chroma step may give up for its chroma (our choice)
LIGHTNESS_SEARCH_STEP = 0.005
Ops = list[dict[str, Any]]


def colour_step(rgb: list[float], ops: Ops) -> list[float]:
    """A refinement's colour operations (shades.toml's): a hue shift ('toward') by hue_step; a
    chroma factor fitted to the gamut when it is the step's only operation (a step that also sets
    the lightness, 'brighter', keeps that lightness); the others as the shades apply them."""
    out = list(rgb)
    for op in ops:
        if op["op"] == "toward":
            out = hue_step(out, op["oklab"][1:], op["amount"])
        elif op["op"] == "chroma" and len(ops) == 1:
            out = chroma_step(out, op["scale"])
        else:
            out = apply_ops(out, [op])
    return out


def shade_step(rgb: list[float], ops: Ops) -> list[float]:
    """A shade said as a change ('more vivid', 'less muted'): its operations as the shades apply
    them; where the gamut turns the shade's chroma pull around (a lighter 'vivid' on a pale pink
    would lose chroma at the gamut's edge), its chroma factor alone, fitted to the gamut by giving
    up a little lightness, so the colour still moves the way the word says."""
    out = apply_ops(rgb, ops)
    scale = 1.0
    for op in ops:
        if op["op"] == "chroma":
            scale *= op["scale"]
    if (_chroma(out) - _chroma(rgb)) * (scale - 1.0) >= 0.0:
        return out
    return chroma_step(rgb, scale)


def hue_step(rgb: list[float], ab: Sequence[float], amount: float) -> list[float]:
    """One step towards a hue: OKLab a, b plus `amount` of the target's own a, b vector (its hue
    direction at its chroma), lightness kept where the gamut allows. A colour already past the
    target's chroma still moves further its way ('greener' on bright green is greener still)."""
    L, a, b = linear_to_oklab(rgb)
    out = fit_in_gamut(L, a + ab[0] * amount, b + ab[1] * amount)
    return out if _along(out, ab) > _along(rgb, ab) else list(rgb)  # the gamut's edge: no step back


def colour_towards(rgb: list[float], goal: list[float], amount: float) -> list[float]:
    """`amount` of the way from the colour to the goal in OKLab (lightness, a and b), in gamut."""
    here, there = linear_to_oklab(rgb), linear_to_oklab(goal)
    L, a, b = (h + (t - h) * amount for h, t in zip(here, there))
    return fit_in_gamut(L, a, b)


def chroma_step(rgb: list[float], scale: float) -> list[float]:
    """OKLCh chroma times `scale`, hue kept, lightness kept where the gamut allows."""
    L, a, b = linear_to_oklab(rgb)
    out = fit_in_gamut(L, a * scale, b * scale)
    grew = _chroma(out) - (a * a + b * b) ** 0.5
    return out if grew * (scale - 1.0) > 0 else list(rgb)  # the gamut's edge: no step back


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


def yellow_kept(rgb: list[float], darker: list[float]) -> list[float]:
    """A step that made `rgb` darker (the paper's linear 'darker' keeps the OKLCh hue): a yellow's
    hue turned as the survey's yellows turn (colour.darkened_yellow), so it darkens to a mustard,
    not an olive; anything else as the step gave it."""
    (was, _a, _b), (L, a, b) = linear_to_oklab(rgb), linear_to_oklab(darker)
    turned = darkened_yellow(was, L, a, b)
    return darker if turned == (a, b) else oklab_to_linear_in_gamut((L, *turned))


def scaled_ops(ops: Ops, weight: float) -> Ops:
    """A colour step (shades' ops) taken `weight` times (compiler/degrees.py): amounts 1 - (1 - t)^w, scales s^w."""
    return ops if weight == 1.0 else [weighted_shade(op, weight) for op in ops]


def _along(rgb: Sequence[float], ab: Sequence[float]) -> float:
    """The colour's OKLab a, b along the direction of `ab`."""
    _l, a, b = linear_to_oklab(rgb)
    u = _unit((ab[0], ab[1]))
    return a * u[0] + b * u[1]


def _chroma(rgb: Sequence[float]) -> float:
    _l, a, b = linear_to_oklab(rgb)
    return float((a * a + b * b) ** 0.5)


def _unit(ab: tuple[float, float]) -> tuple[float, float]:
    norm = (ab[0] ** 2 + ab[1] ** 2) ** 0.5
    return (ab[0] / norm, ab[1] / norm) if norm > 0 else (0.0, 0.0)


def hue_share(rgb: list[float], ab: tuple[float, float]) -> float:
    """How much of the hue `ab` the colour has: its OKLab a, b along ab's direction (0 when none)."""
    _l, a, b = linear_to_oklab(rgb)
    u = _unit(ab)
    return max(0.0, a * u[0] + b * u[1])


def less_of(rgb: list[float], ab: tuple[float, float], amount: float) -> list[float]:
    """The colour with `amount` of its share of the hue `ab` taken away, lightness kept."""
    L, a, b = linear_to_oklab(rgb)
    u, share = _unit(ab), hue_share(rgb, ab)
    return fit_in_gamut(L, a - amount * share * u[0], b - amount * share * u[1])


def opposite_ops(ops: Ops) -> Ops:
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
