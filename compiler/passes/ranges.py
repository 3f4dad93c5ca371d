"""Range checks: clamp values into their documented ranges, with a warning naming the words."""

from __future__ import annotations

import math

from ..diagnostics import warning
from ..graphs import graph_params
from ..state import Context, MaterialState

RANGES = {
    "roughness": (0.0, 1.0), "anisotropy": (0.0, 1.0), "diffuse_roughness": (0.0, 1.6),
    "ior": (1.0, 5.0), "base_color": (0.0, 1.0),
}
COAT_RANGES = {"roughness": (0.0, 1.0), "ior": (1.0, 3.0), "color": (0.0, 1.0), "thickness": (0.0, 10.0)}


def clamp(value, low: float, high: float):
    if isinstance(value, list):
        return [clamp(v, low, high) for v in value]
    if not isinstance(value, (int, float)) or math.isnan(value):
        return low
    return min(max(float(value), low), high)


def check_ranges(state: MaterialState, ctx: Context) -> MaterialState:
    for param, (low, high) in RANGES.items():
        _check(state, state.params, param, param, low, high)
    if state.coat is not None:
        for param, (low, high) in COAT_RANGES.items():
            _check(state, state.coat, param, f"coat.{param}", low, high)
    for role, ref in state.maps.items():
        for param, (low, high, _default) in graph_params(ref["graph"]).items():
            _check(state, ref["params"], param, f"maps.{role}.{param}", low, high)
    return state


def _in_range(value, low: float, high: float) -> bool:
    if type(value) is list:
        return all(type(v) in (int, float) and low <= v <= high for v in value)
    return type(value) in (int, float) and low <= value <= high  # NaN fails both comparisons


def _check(state, holder: dict, param: str, name: str, low: float, high: float) -> None:
    value = holder.get(param)
    if value is None or _in_range(value, low, high):
        return
    fixed = clamp(value, low, high)
    holder[param] = fixed
    steps = state.provenance.get(name, [])
    words = [w.text for s in steps for w in s.words]
    span = _last_span(steps)
    state.note(name, fixed, f"range check: clamped to [{low}, {high}]")
    state.diagnostics.append(warning(span, "W107", f"{name.replace('_', ' ')} {_fmt(value)} is outside "
                                     f"[{low}, {high}] and was clamped to {_fmt(fixed)}",
                                     (f"set by: {' '.join(words)}" if words else "",)))


def _last_span(steps):
    for step in reversed(steps):
        if step.words:
            return step.words[-1].span
    return None


def _fmt(value) -> str:
    if isinstance(value, list):
        return "(" + ", ".join(f"{v:.3g}" for v in value) + ")"
    return f"{value:.3g}"
