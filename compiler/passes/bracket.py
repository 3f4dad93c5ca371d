"""The bracket rule (paper §4.2, docs/refinement.md) as a search that never traps.

Each target (a parameter such as `roughness`, a colour, a map parameter) keeps the interval the
user has narrowed it to: "less" makes the current value the upper bound, "more" the lower one;
with the other bound known the value moves towards it (halfway: the paper's midpoint), else it
takes one step. Three rules keep the search from freezing:

- a bracket holds only while the target still has the value the bracket gave it: when another
  word (or a refinement of another axis of the same colour) changed it since, the bounds are
  forgotten and the next refinement steps again;
- a bracket narrower than 1/16 of a step is reopened: the far bound is dropped and the value
  steps past it (the user who keeps saying "more" wants more than the old bound);
- a parameter's range ends are bounds the user never has to say: a step that would leave the
  range stops halfway to its end, so no refinement is clamped (W107) and every value can move
  back; a value already out of its range moves back from the range's end.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

from ..formulas import apply_op, invert_op, midpoint

Value = Any  # a number or an RGB list
Step = Callable[[Value], Value]

REOPEN_BELOW = 1 / 16  # a bracket narrower than this fraction of a step is reopened


@dataclass
class Bracket:
    """The interval one target has been narrowed to, and the value the bracket last gave it."""

    lo: Value = None
    hi: Value = None
    last: Value = None


@dataclass(frozen=True)
class Move:
    """One refinement of one target: `direction` +1 raises it, -1 lowers it (in its own units)."""

    direction: int
    step: Step  # one step in that direction, already scaled by the refinement's adverbs
    weight: float = 1.0  # the adverbs' weight: 1 moves halfway to the other bound
    limits: tuple[float, float] | None = None  # the target's range
    saturate: bool = True  # a step that would leave the range stops halfway to its end


def bracket_move(brackets: dict[str, Bracket], key: str, current: Value, move: Move) -> Value:
    """The next value for `key` (the bracket in `brackets` is updated)."""
    current = _inside(current, move)
    bracket = brackets.get(key)
    if bracket is None or not _same(bracket.last, current):
        bracket = brackets[key] = Bracket()
    if move.direction > 0:
        bracket.lo, other = current, bracket.hi
    else:
        bracket.hi, other = current, bracket.lo
    stepped = move.step(current)
    if other is not None and _open(current, other, stepped, move.direction):
        new = _towards(current, other, move.weight)
    else:
        if move.direction > 0:
            bracket.hi = None
        else:
            bracket.lo = None
        new = _within(current, stepped, move)
    bracket.last = new
    return new


def _inside(current: Value, move: Move) -> Value:
    """A number beyond its range reads as the range's end when the move points back inside."""
    if move.limits is None or isinstance(current, list) or not isinstance(current, (int, float)):
        return current
    low, high = move.limits
    if current > high and (move.saturate or move.direction < 0):
        return high
    if current < low and (move.saturate or move.direction > 0):
        return low
    return current


def _open(current: Value, other: Value, stepped: Value, direction: int) -> bool:
    """Whether the bracket still has room: the other bound lies ahead and is not too close."""
    if not isinstance(current, list) and (other - current) * direction <= 0:
        return False  # a bound behind the move (stale data): step instead
    return _distance(current, other) >= REOPEN_BELOW * _distance(current, stepped)


def _towards(current: Value, other: Value, weight: float) -> Value:
    """Halfway to the other bound for weight 1 (the paper's midpoint); w/(1+w) of the way in general."""
    if weight == 1.0:
        return midpoint(current, other)
    t = weight / (1.0 + weight)
    return apply_op("blend", current, other, 1.0, t)


def _within(current: Value, new: Value, move: Move) -> Value:
    """A step that would leave the range stops halfway to the range's end."""
    if move.limits is None or not move.saturate:
        return new
    low, high = move.limits
    if isinstance(new, list):
        return [_channel_within(c, n, low, high) for c, n in zip(current, new)]
    return _channel_within(current, new, low, high)


def _channel_within(current: float, new: float, low: float, high: float) -> float:
    if new > high:
        return (current + high) / 2 if current < high else high
    if new < low:
        return (current + low) / 2 if current > low else low
    return new


def _same(a: Value, b: Value) -> bool:
    if a is None or b is None:
        return False
    return _distance(a, b) <= 1e-12


def _distance(a: Value, b: Value) -> float:
    if isinstance(a, list):
        return max((abs(x - y) for x, y in zip(a, b)), default=0.0)
    d = abs(a - b)
    return d if math.isfinite(d) else math.inf


# ---------------------------------------------------------------- steps


def scaled_steps(step: dict[str, Any], weight: float = 1.0) -> tuple[Step, Step]:
    """(up, down) for a lexicon step table taken `weight` times: 'much' (2) is two steps,
    'slightly' (0.5) half of one. add d -> w d; mul f -> f^w; blend t -> 1 - (1 - t)^w of the way."""
    op, value = step["op"], step["value"]
    if op == "blend":
        to = step.get("to", [1.0, 1.0, 1.0])
        t = value if weight == 1.0 else 1.0 - (1.0 - value) ** weight
        return (lambda x: apply_op("blend", x, to, 1.0, t), lambda x: invert_op("blend", x, to, 1.0, t))
    if op == "mul" and weight != 1.0:
        factor = float(value) ** weight
        return (lambda x: apply_op("mul", x, factor), lambda x: invert_op("mul", x, factor))
    if op == "add" and weight != 1.0:
        delta = value * weight
        return (lambda x: apply_op("add", x, delta), lambda x: invert_op("add", x, delta))
    return (lambda x: apply_op(op, x, value), lambda x: invert_op(op, x, value))
