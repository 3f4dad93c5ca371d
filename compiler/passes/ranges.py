"""Range checks: clamp values into their documented ranges, with a warning naming the words."""

from __future__ import annotations

import math
import sys
from collections.abc import Iterable, Mapping, Sequence
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


def check_values(state: MaterialState, ctx: Context) -> MaterialState:
    """check_ranges, then check_finite. The range check looks at every parameter, coat and map value
    anyway: where it clamps nothing it also tells whether they are all finite (a value in its range
    is), so that check_finite's own look at them is not needed, only at the provenance steps."""
    if _checked_ranges(state) and _steps_finite(state):
        return state  # the common case: nothing to replace or report
    return check_finite(state, ctx)


def check_ranges(state: MaterialState, ctx: Context) -> MaterialState:
    _checked_ranges(state)
    return state


def _checked_ranges(state: MaterialState) -> bool:
    """check_ranges; whether every parameter, coat and map value is now known to be finite (False:
    maybe not, check_finite sees)."""
    finite = _check_all(state, state.params, RANGES, "")
    if state.coat is not None:
        finite = _check_all(state, state.coat, COAT_RANGES, "coat.") and finite
    for role, ref in state.maps.items():
        if ref["params"]:  # a map without parameters of its own has nothing to check
            finite = _check_all(state, ref["params"], graph_params(ref["graph"]), f"maps.{role}.") and finite
    return finite


def _check_all(
    state: MaterialState, holder: dict[str, Any], ranges: Mapping[str, Sequence[float]], prefix: str
) -> bool:
    """`ranges`: param -> (low, high, ...). Clamps are made in the order of `ranges`. True when
    nothing was clamped and every value is finite (_finite): a value in its range is; one without
    a range is looked at here; False after a clamp."""
    finite = True
    for param, value in holder.items():  # the common case, one pass over what is set: nothing to clamp
        bounds = ranges.get(param)
        if bounds is None:
            if finite:  # check_finite's test of a value (_finite); a name or a flag is no number, no call
                kind = type(value)
                if kind is float:
                    finite = -BIGGEST <= value <= BIGGEST  # NaN fails both
                elif kind is list or kind is dict:
                    finite = _finite(value)
            continue
        if value is None:
            continue
        kind = type(value)
        if kind is float:
            if bounds[0] <= value <= bounds[1]:
                continue
            break
        if kind is list:  # a colour: _in_range's list case, without its call
            low, high = bounds[0], bounds[1]
            for v in value:
                if not ((type(v) is float or type(v) is int) and low <= v <= high):
                    break
            else:
                continue
            break
        if not _in_range(value, bounds[0], bounds[1]):
            break
    else:
        return finite
    for param, bounds in ranges.items():
        value = holder.get(param)
        if value is None or (type(value) is float and bounds[0] <= value <= bounds[1]):
            continue  # absent, or a number in range: the common cases, checked without a call
        if not _in_range(value, bounds[0], bounds[1]):
            _clamp(state, holder, param, prefix + param, bounds[0], bounds[1])
    return False


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
    words = _set_by(steps)
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


BIGGEST = sys.float_info.max  # the largest finite float: where an unranged infinity is clamped to
DEFAULTS: dict[str, Any] = {s.name: s.default for s in PARAMS}
COAT_DEFAULTS: dict[str, Any] = {s.name: s.default for s in COAT_PARAMS}


def check_finite(state: MaterialState, ctx: Context) -> MaterialState:
    """Every number that reaches the IR is finite (docs/ir.md, "Finite numbers"): after the range
    pass, a NaN or infinity left anywhere (an unranged parameter, a map parameter without a range,
    a provenance step's value) is replaced, with a W109 naming the words of the step that made it.
    Within a range: +inf -> high, -inf and NaN -> low. Without one: +-inf -> +-the largest finite
    float (the limit the words were heading to), NaN -> the parameter's default (it has no direction)."""
    params, coat, big = state.params, state.coat, BIGGEST
    if _all_finite(state):
        return state  # the common case: nothing to replace or report
    for param, value in params.items():
        if not ((type(value) is float and -big <= value <= big) or _finite(value)):
            params[param] = fixed = _fixed(value, RANGES.get(param), DEFAULTS.get(param))
            _report(state, param, value, fixed)
    if coat is not None:
        for param, value in coat.items():
            if not ((type(value) is float and -big <= value <= big) or _finite(value)):
                coat[param] = fixed = _fixed(value, COAT_RANGES.get(param), COAT_DEFAULTS.get(param))
                _report(state, "coat." + param, value, fixed)
    for role, ref in state.maps.items():
        held = ref["params"]
        for param, value in held.items():
            if not ((type(value) is float and -big <= value <= big) or _finite(value)):
                bounds = graph_params(ref["graph"]).get(param)  # looked up only for a value to fix
                held[param] = fixed = _fixed(value, bounds[:2] if bounds else None, bounds[2] if bounds else None)
                _report(state, f"maps.{role}.{param}", value, fixed)
    for name, steps in state.provenance.items():
        for step in steps:
            value = step.value
            if not ((type(value) is float and -big <= value <= big) or _finite(value)):
                step.value = _fixed(value, *_bounds_of(state, name))
                _report(state, name, value, step.value, step)
    return state


def _all_finite(state: MaterialState) -> bool:
    """Whether every number check_finite looks at is finite (False: maybe not; check_finite sees)."""
    if not _values_finite(state.params.values()):
        return False
    if state.coat is not None and not _values_finite(state.coat.values()):
        return False
    for ref in state.maps.values():
        if not _values_finite(ref["params"].values()):
            return False
    return _steps_finite(state)


def _steps_finite(state: MaterialState) -> bool:
    """Whether every provenance step's value is finite (False: maybe not; check_finite sees). Both
    callers have found every parameter value finite first, so a step whose value is its parameter's
    value itself (the step that set it last, most often) is not looked at again."""
    big, params = BIGGEST, state.params
    for name, steps in state.provenance.items():
        current = params.get(name)
        for step in steps:
            value = step.value
            if value is current:
                continue
            kind = type(value)
            if kind is float:
                if not -big <= value <= big:  # NaN fails both
                    return False
            elif kind is list:
                try:
                    total = sum(value)  # a colour: _values_finite's list case, without its call
                except TypeError:
                    if not _values_finite(value):
                        return False
                    continue
                if not -big <= total <= big:
                    return False
            elif kind is dict and not _values_finite(value.values()):
                return False
    return True


def _values_finite(values: Iterable[Any]) -> bool:
    """_finite of each value, its common cases written out (False where it is not sure: a sum
    that overflows)."""
    big = BIGGEST
    for value in values:
        kind = type(value)
        if kind is float:
            if not -big <= value <= big:  # NaN fails both
                return False
        elif kind is list:
            try:
                total = sum(value)  # one C loop: a NaN or an infinity anywhere makes the sum one too
            except TypeError:  # not all numbers (a coat's aliases): each one
                if not _values_finite(value):
                    return False
                continue
            if not -big <= total <= big:
                return False
        elif kind is dict and not _values_finite(value.values()):
            return False
    return True


def _finite(value: Any) -> bool:
    """No NaN or infinity in a number, a list or a dict of them (anything else is not a number)."""
    kind = type(value)
    if kind is float:
        finite: bool = -BIGGEST <= value <= BIGGEST  # NaN fails both
        return finite
    if kind is list:
        try:
            total = sum(value)  # one C loop: a NaN or an infinity anywhere makes the sum one too
        except TypeError:  # not all numbers
            return all(_finite(v) for v in value)
        return -BIGGEST <= total <= BIGGEST or all(_finite(v) for v in value)  # (or the sum overflowed)
    if kind is dict:
        return all(_finite(v) for v in value.values())
    return True


def _fixed(value: Any, bounds: Sequence[float] | None, default: Any) -> Any:
    """`value` with its NaNs and infinities replaced (check_finite's rule)."""
    kind = type(value)
    if kind is list:
        if isinstance(default, (list, tuple)):
            if len(default) == len(value):
                return [_fixed(v, bounds, d) for v, d in zip(value, default, strict=True)]
            default = None
        return [_fixed(v, bounds, default) for v in value]
    if kind is dict:
        return {k: _fixed(v, bounds, None) for k, v in value.items()}
    if kind is not float or _finite(value):
        return value
    if bounds is not None:
        return float(bounds[1]) if value > 0 else float(bounds[0])  # NaN > 0 is false: the low end
    if math.isnan(value):
        return float(default) if type(default) in (int, float) and math.isfinite(default) else 0.0
    return BIGGEST if value > 0 else -BIGGEST


def _bounds_of(state: MaterialState, name: str) -> tuple[Sequence[float] | None, Any]:
    """The range and default of a provenance name: a parameter, 'coat.X' or 'maps.ROLE.X'."""
    if name.startswith("coat."):
        key = name[5:]
        return COAT_RANGES.get(key), COAT_DEFAULTS.get(key)
    if name.startswith("maps."):
        role, _, key = name[5:].partition(".")
        ref = state.maps.get(role)
        bounds = graph_params(ref["graph"]).get(key) if ref is not None else None
        return (bounds[:2], bounds[2]) if bounds else (None, None)
    return RANGES.get(name), DEFAULTS.get(name)


def _report(state: MaterialState, name: str, value: Any, fixed: Any, step: Step | None = None) -> None:
    """A W109 for `name`, naming the words of `step` (or of the last step that set it); once per name."""
    for d in state.diagnostics:
        if d.code == "W109" and d.message.startswith(f"{name.replace('_', ' ')} "):
            return
    steps = [step] if step is not None else state.provenance.get(name, [])[-1:]
    words = _set_by(steps)
    state.diagnostics.append(
        warning(
            _last_span(steps),
            "W109",
            f"{name.replace('_', ' ')} {_fmt(value)} is not a finite number and was replaced by {_fmt(fixed)}",
            (f"set by: {' '.join(words)}" if words else "",),
        )
    )


def _set_by(steps: list[Step]) -> list[str]:
    """The words of the steps in order; a step repeated on consecutive lines ('more grain' on
    1,751 lines) is named once, with its count, so the hint stays short."""
    groups: list[list[Any]] = []  # [text, count]
    for step in steps:
        text = " ".join([w.text for w in step.words])
        if not text:
            continue
        if groups and groups[-1][0] == text:
            groups[-1][1] += 1
        else:
            groups.append([text, 1])
    return [text if n == 1 else f"{text} ({n} times)" for text, n in groups]


def _last_span(steps: list[Step]) -> Span | None:
    for step in reversed(steps):
        if step.words:
            return step.words[-1].span
    return None


def _fmt(value: Any) -> str:
    if isinstance(value, list):
        return "(" + ", ".join(_fmt(v) for v in value) + ")"
    if isinstance(value, dict):
        return "{" + ", ".join(f"{k}: {_fmt(v)}" for k, v in value.items()) + "}"
    return f"{value:.3g}" if isinstance(value, (int, float)) else str(value)
