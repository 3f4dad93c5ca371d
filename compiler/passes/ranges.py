"""Range checks: clamp values into their documented ranges, with a warning naming the words."""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from typing import Any

from ..diagnostics import warning
from ..graphs import graph_params
from ..params import COAT_PARAMS, PARAMS, ranges
from ..spans import Span
from ..state import Context, MaterialState, Step

#: The order clamps are checked and reported in when one word pushes several values out of range
#: (kept from IR version 1). Parameters not named here follow in the table's order.
CHECK_FIRST = ("roughness", "anisotropy", "diffuse_roughness", "ior", "base_color", "color", "thickness")


def _check_order(table: dict[str, tuple[float, float]]) -> dict[str, tuple[float, float]]:
    rank = {name: i for i, name in enumerate(CHECK_FIRST)}
    return dict(sorted(table.items(), key=lambda item: rank.get(item[0], len(rank))))


RANGES = _check_order(ranges(PARAMS))  # param -> (low, high), from the parameter table
COAT_RANGES = _check_order(ranges(COAT_PARAMS))


def clamp(value: Any, low: float, high: float) -> Any:
    if isinstance(value, list):
        return [clamp(v, low, high) for v in value]
    if not isinstance(value, (int, float)) or math.isnan(value):
        return low
    return min(max(float(value), low), high)


def check_ranges(state: MaterialState, ctx: Context) -> MaterialState:
    _check_all(state, state.params, RANGES, "")
    if state.coat is not None:
        _check_all(state, state.coat, COAT_RANGES, "coat.")
    for role, ref in state.maps.items():
        _check_all(state, ref["params"], graph_params(ref["graph"]), f"maps.{role}.")
    return state


def _check_all(
    state: MaterialState, holder: dict[str, Any], ranges: Mapping[str, Sequence[float]], prefix: str
) -> None:
    """`ranges`: param -> (low, high, ...)."""
    for param, bounds in ranges.items():
        value = holder.get(param)
        if value is None or (type(value) is float and bounds[0] <= value <= bounds[1]):
            continue  # absent, or a number in range: the common cases, checked without a call
        if not _in_range(value, bounds[0], bounds[1]):
            _clamp(state, holder, param, prefix + param, bounds[0], bounds[1])


def _in_range(value: Any, low: float, high: float) -> bool:
    if type(value) is not list:
        return (type(value) is float or type(value) is int) and low <= value <= high  # NaN fails both
    for v in value:
        if not ((type(v) is float or type(v) is int) and low <= v <= high):
            return False
    return True


def _clamp(state: MaterialState, holder: dict[str, Any], param: str, name: str, low: float, high: float) -> None:
    """Clamp an out-of-range value, with a W107 naming the words that set it."""
    value = holder[param]
    fixed = clamp(value, low, high)
    holder[param] = fixed
    steps = state.provenance.get(name, [])
    words = [w.text for s in steps for w in s.words]
    span = _last_span(steps)
    state.note(name, fixed, f"range check: clamped to [{low}, {high}]")
    state.diagnostics.append(
        warning(
            span,
            "W107",
            f"{name.replace('_', ' ')} {_fmt(value)} is outside [{low}, {high}] and was clamped to {_fmt(fixed)}",
            (f"set by: {' '.join(words)}" if words else "",),
        )
    )


def _last_span(steps: list[Step]) -> Span | None:
    for step in reversed(steps):
        if step.words:
            return step.words[-1].span
    return None


def _fmt(value: Any) -> str:
    if isinstance(value, list):
        return "(" + ", ".join(f"{v:.3g}" for v in value) + ")"
    return f"{value:.3g}"
