"""The lexicon's formulas, applied with an adverb weight w (paper §3.3, §4.2).

    set v             x -> x + w (v - x)
    mul f             x -> x (1 + w (f - 1))
    add d             x -> x + w d
    blend v, amount t x -> x + min(1, w t) (v - x)
    mix v, amount t   x -> the same move in OKLab (colours only): a colour fading toward a grey
                      keeps its hue and a share of its chroma ('faded navy' stays blue), where
                      the linear blend toward a lighter grey drains a dark colour's chroma first

Values may be scalars or RGB lists; lists are handled per channel (mix: as one colour).
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

Value = Any  # a number, an RGB list, or (for 'set') a string such as a model name
Channel = Callable[[float, float], float]


def _mix(x: Value, v: Value, t: float) -> Value:
    """x moved t of the way to v in OKLab (t < 0: away from it), kept in the sRGB gamut."""
    from .colour import clamp01, mix_oklab

    return clamp01(mix_oklab(x, v, t))


def _per_channel(fn: Channel, x: Value, v: Value) -> Value:
    if isinstance(x, list):
        vs = v if isinstance(v, list) else [v] * len(x)
        return [fn(a, b) for a, b in zip(x, vs)]
    return fn(x, v)


def _move_towards(a: float, b: float, w: float) -> float:  # set, and blend with w = min(1, w t)
    return a + w * (b - a)


def _scale(a: float, b: float, w: float) -> float:  # mul
    return a * (1 + w * (b - 1))


def _offset(a: float, b: float, w: float) -> float:  # add
    return a + w * b


CHANNEL_OPS: dict[str, Callable[[float, float, float], float]] = {
    "set": _move_towards,
    "mul": _scale,
    "add": _offset,
    "blend": _move_towards,
}


def apply_op(op: str, x: Value, value: Value, weight: float = 1.0, amount: float | None = None) -> Value:
    if op == "set" and (isinstance(value, str) or x is None):
        return value
    if op == "mix":
        return _mix(x, value, min(1.0, weight * (1.0 if amount is None else amount)))
    fn = CHANNEL_OPS.get(op)
    if fn is None:
        raise ValueError(f"unknown formula op '{op}'")
    if op == "blend":
        weight = min(1.0, weight * (1.0 if amount is None else amount))
    if isinstance(x, list):
        vs = value if isinstance(value, list) else [value] * len(x)
        return [fn(a, b, weight) for a, b in zip(x, vs)]
    return fn(x, value, weight)


def invert_op(op: str, x: Value, value: Value, weight: float = 1.0, amount: float | None = None) -> Value:
    """The opposite move of apply_op: used for 'weaker brushing'."""
    if op == "mul":
        return _per_channel(lambda a, b: a / (1 + weight * (b - 1)) if 1 + weight * (b - 1) else a, x, value)
    if op == "add":
        return _per_channel(lambda a, b: a - weight * b, x, value)
    if op == "mix":
        return _mix(x, value, -min(1.0, weight * (1.0 if amount is None else amount)))
    if op in ("set", "blend"):
        t = weight if op == "set" else min(1.0, weight * (1.0 if amount is None else amount))
        return _per_channel(lambda a, b: a - t * (b - a), x, value)
    raise ValueError(f"unknown formula op '{op}'")


OP_SIGNS = {"set": "=", "mul": "*=", "add": "+="}


def describe(effect: dict[str, Any], weight: float) -> str:
    """'roughness *= 1.2' style text for provenance and explain."""
    op, value = effect["op"], effect.get("value")
    if op in OP_SIGNS:
        text = f"{OP_SIGNS[op]} {value}"
    elif op in ("blend", "mix"):
        space = " in OKLab" if op == "mix" else ""
        text = f"blend to {value} by {effect.get('amount', 1.0)}{space}"
    else:
        raise KeyError(op)
    suffix = f" (weight {weight:g})" if weight != 1.0 else ""
    return f"{effect['param']} {text}{suffix}"


def midpoint(a: Value, b: Value) -> Value:
    return _per_channel(lambda x, y: (x + y) / 2, a, b)


ROUNDING = 6755399441055744.0  # 1.5 * 2**52: (y + ROUNDING) - ROUNDING is y rounded to an integer, for |y| < 2**51


def round6(x: float) -> float:
    """round(x, 6), with -0.0 made 0.0. Exactly equal to it, about twice as fast: x * 1e6 is
    off the exact product by under 1.3e-4 when |x| < 1e6, so where it lies at least 0.001 from a
    tie its nearest integer n is the correctly rounded one, and n / 1e6 is the double nearest
    to that decimal, which is what round() returns (a zero n is +0.0). Ties, huge values, inf
    and NaN use round()."""
    y = x * 1e6
    if -1e12 < y < 1e12:
        n = (y + ROUNDING) - ROUNDING
        if -0.499 < y - n < 0.499:
            return n / 1e6
    return round(x, 6) or 0.0


def rounded(value: Any, digits: int = 6) -> Any:
    """Floats rounded to `digits` decimals (and -0.0 made 0.0) so output is stable and small."""
    if digits != 6:
        return _rounded_to(value, digits)
    kind = type(value)
    if kind is float:
        return round6(value)
    if kind is list:
        return round6_list(value)
    if kind is dict:
        out: dict[str, Any] = {}
        for k, v in value.items():
            kind = type(v)
            out[k] = round6(v) if kind is float else rounded(v) if kind is list or kind is dict else v
        return out
    return value


def round6_list(values: list[Any]) -> list[Any]:
    """rounded() of a list, with round6 written out for its floats (colours and optics are lists)."""
    out: list[Any] = []
    for v in values:
        if type(v) is not float:
            out.append(rounded(v))
            continue
        y = v * 1e6
        if -1e12 < y < 1e12:
            n = (y + ROUNDING) - ROUNDING
            if -0.499 < y - n < 0.499:
                out.append(n / 1e6)
                continue
        out.append(round(v, 6) or 0.0)
    return out


def _rounded_to(value: Any, digits: int) -> Any:
    kind = type(value)
    if kind is float:
        return round(value, digits) or 0.0  # 'or' turns -0.0 into 0.0
    if kind is list:
        return [_rounded_to(v, digits) for v in value]
    if kind is dict:
        return {k: _rounded_to(v, digits) for k, v in value.items()}
    return value
