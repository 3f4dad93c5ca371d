"""Degrees: how adverb weights compose and how a weighted formula stays inside its parameter's range.

The paper's formulas (compiler/formulas.py; paper §3.3, §4.2) with an adverb weight w are kept
exactly where they make sense: for 0 <= w <= 1 the result lies between the current value x and the
adjective's full effect y1 (lightly brushed: m * 1.1, halfway to brushed's m * 1.2). Everything
else happens on a saturating scale, so that no ordinary phrase leaves a parameter's range:

- the full effect y1 of a `mul` or `add` that moves a value toward a bound is taken on the knee
  scale: exact while the result stays KNEE (10 %) of the range away from that bound, beyond it the
  remaining distance shrinks exponentially (continuous, with a continuous slope, never reaching it);
- an intensifier (w > 1) works on the logit of the value's position in its range (L below): for a
  relative formula (mul, add) it extrapolates the step x -> y1, L(y) = L(x) + w (L(y1) - L(x)), so
  "extremely shiny" is shinier than "very shiny", which is shinier than "shiny", and none reaches
  0; for an absolute level (set v on a degree parameter such as roughness) it continues the step
  from an anchor through the level, L(y) = L(a) + w (L(v) - L(a)), where the anchor a is the current
  value when it lies between the range's middle and the level, else the middle: "very glossy" is
  glossier than "glossy" on every material, chrome included; a degree level is "at least" that
  degree (a material already glossier than "glossy" keeps its gloss); a level in the middle half of
  the range is what a process leaves, not a degree ("heavily anodized" = anodized), and other set
  values (an IOR, a colour) are simply set;
- a colour factor below 1 (`mul` on a colour: smoked glass, oiled wood) intensified is applied
  `w` times, f ** w (Beer-Lambert for w times the thickness), so it keeps a neutral hue;
- adverbs compose by exponents (docs/language.md "Degrees and order"): an adverb before another
  adverb raises that adverb's weight to its own weight, so "very lightly" = 0.5 ** 1.5 (lighter
  than "lightly") and "very heavily" = 2 ** 1.5 (heavier than "heavily").
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import Any

from .formulas import apply_op

Bounds = tuple[float, float]

KNEE = 0.1  # the share of a range next to a bound where a step toward it saturates
EDGE = 1e-3  # logit positions are taken at least this share of the range inside a bound
MIDDLE_HALF = 0.25  # a set level closer than this share of the range to its middle is not a degree


LOG_WEIGHT_LIMIT = (
    20.0  # a chain's weight stays within e^-20 .. e^20: 'very very ... glossy' saturates, never overflows
)


def compose_weights(weights: Sequence[float]) -> float:
    """The weight of a chain of adverbs, the last one nearest the adjective: w_n ** (w_1 * ... * w_n-1),
    computed in log space and held within e^±LOG_WEIGHT_LIMIT (fifty 'very's are as strong as the
    scale allows, not a numeric overflow)."""
    if not weights:
        return 1.0
    last = weights[-1]
    if last <= 0.0:
        return 0.0
    log_exponent = sum(math.log(w) for w in weights[:-1] if w > 0.0)
    if any(w <= 0.0 for w in weights[:-1]):
        return 1.0  # a zero weight before it: w_n ** 0
    log_weight = math.log(last) * math.exp(min(log_exponent, LOG_WEIGHT_LIMIT))
    return float(math.exp(max(-LOG_WEIGHT_LIMIT, min(LOG_WEIGHT_LIMIT, log_weight))))


def weighted_formula(
    op: str, x: Any, value: Any, weight: float, amount: float | None, bounds: Bounds | None, degree: bool = False
) -> Any:
    """One lexicon formula at an adverb weight, kept inside `bounds` (per channel for colours).
    `degree`: the parameter is a degree scale (roughness, anisotropy), whose `set` levels intensify."""
    if degree and op == "set" and type(x) is float and bounds is not None and type(value) in (float, int):
        return degree_level(x, float(value), weight, bounds)
    if type(x) is float and weight <= 1.0 and bounds is not None and op in _LINEAR:
        exact = _paper_share(op, x, value, weight, bounds)
        if exact is not None:
            return exact
    if op == "set" and (isinstance(value, str) or x is None):
        return value
    if (
        op in ("blend", "mix") or bounds is None
    ):  # blend never leaves [x, value]; an unbounded value keeps the paper's rule
        return apply_op(op, x, value, weight, amount)
    if op == "set" and weight > 1.0:
        return intensified_level(x, value, weight, bounds) if degree and not isinstance(value, list) else value
    if op == "mul" and isinstance(x, list) and weight > 1.0 and _attenuating(value):
        return repeated_factor(x, value, weight)
    if isinstance(x, list):
        values = value if isinstance(value, list) else [value] * len(x)
        return [_weighted(op, a, b, weight, bounds) for a, b in zip(x, values)]
    return _weighted(op, x, value, weight, bounds)


_LINEAR = ("set", "mul", "add")


def _paper_share(op: str, x: float, value: Any, weight: float, bounds: Bounds) -> float | None:
    """The common case, without the knee: the paper's formula when its full effect stays out of the
    knees (or scales toward a zero bound); None when the saturating path is needed."""
    if type(value) is not float and type(value) is not int:
        return None
    if op == "set":
        return float(value) if weight == 1.0 else x + weight * (value - x)
    full = x * value if op == "mul" else x + value
    lo, hi = bounds
    width = KNEE * (hi - lo)
    if lo + width <= full <= hi - width or (op == "mul" and lo == 0.0 and 0.0 <= value <= 1.0):
        return x + weight * (full - x)
    return None


def _attenuating(value: Any) -> bool:
    factors = value if isinstance(value, list) else [value]
    return all(type(f) in (float, int) and 0.0 < f <= 1.0 for f in factors)


def repeated_factor(x: list[float], value: Any, weight: float) -> list[float]:
    """A colour factor below 1 (an absorber: smoked glass, oil, stain) intensified: applied `weight`
    times, f ** w, as Beer-Lambert gives for w times the thickness; it keeps the hue of a neutral
    factor (a logit step would darken each channel by a different ratio) and never reaches black."""
    factors = value if isinstance(value, list) else [value] * len(x)
    return [a * float(f) ** weight for a, f in zip(x, factors)]


def _weighted(op: str, x: float, value: float, weight: float, bounds: Bounds) -> float:
    full = full_effect(op, x, value, bounds)
    return toward(x, full, weight, bounds)


def degree_level(x: float, level: float, weight: float, bounds: Bounds) -> float:
    """`set level` on a degree scale. A level near the middle (a process's result) is set as the
    paper does; a degree level ("glossy" 0.08, "matte" 0.8) is at least that degree: a material
    already beyond it keeps its value ("glossy chrome" stays as glossy as chrome)."""
    lo, hi = bounds
    middle = (lo + hi) / 2
    if abs(level - middle) < MIDDLE_HALF * (hi - lo):
        return x + weight * (level - x) if weight <= 1.0 else level
    target = x + weight * (level - x) if weight <= 1.0 else intensified_level(x, level, weight, bounds)
    side = 1.0 if level > middle else -1.0
    return target if side * (target - x) >= 0.0 else x


def intensified_level(x: float, level: float, weight: float, bounds: Bounds) -> float:
    """An absolute level intensified: the step from the anchor (x between the middle and the level,
    else the middle) through the level, continued on the logit scale. A level in the middle half of
    the range names what a process leaves (anodized 0.3, sanded 0.55), not a degree: it stays."""
    lo, hi = bounds
    middle = (lo + hi) / 2
    if abs(level - middle) < MIDDLE_HALF * (hi - lo):
        return float(level)
    anchor = x if min(middle, level) <= x <= max(middle, level) else middle
    return toward(anchor, level, weight, bounds)


def word_level(level: float, weight: float, bounds: Bounds) -> float | None:
    """What a rough-side degree level says by itself, whatever the material: 'matte' 0.8, 'very
    matte' beyond it, 'slightly matte' between the middle and it. None for a glossy level or a
    process level (the middle half of the range)."""
    lo, hi = bounds
    middle = (lo + hi) / 2
    if level - middle < MIDDLE_HALF * (hi - lo):
        return None
    return degree_level(middle, level, weight, bounds)


def sigma_of_roughness(roughness: float) -> float:
    """The Oren-Nayar sigma (radians, the spread of facet angles) of a surface with this perceptual
    roughness: alpha = roughness ** 2 is the RMS facet slope (Beckmann; GGX alike), and a slope s
    is a facet angle atan(s), so sigma = atan(roughness ** 2): 'matte' 0.8 -> 0.57, 1.0 -> 0.79."""
    return math.atan(roughness * roughness)


def full_effect(op: str, x: float, value: float, bounds: Bounds) -> float:
    """The formula at weight 1, saturating near the bound it moves toward."""
    if op == "set":
        return float(value)
    linear = float(apply_op(op, x, value))
    if op == "mul" and bounds[0] == 0.0 and 0.0 <= value <= 1.0:
        return linear  # scaling toward zero never crosses it: the paper's number
    return knee_step(x, linear - x, bounds)


def knee_step(x: float, step: float, bounds: Bounds) -> float:
    """x moved by `step`, exact until KNEE of the range before the bound it moves toward, then saturating."""
    if step == 0.0:
        return x
    lo, hi = bounds
    width = KNEE * (hi - lo)
    if step > 0:
        return hi - _knee_down(hi - x, step, width)
    return lo + _knee_down(x - lo, -step, width)


def _knee_down(distance: float, step: float, width: float) -> float:
    """The remaining distance to a bound after a step toward it (distances > 0 on the knee scale)."""
    stretched = distance if distance >= width else width + width * math.log(max(distance, 1e-300) / width)
    left = stretched - step
    return left if left >= width else width * math.exp((left - width) / width)


def toward(x: float, full: float, weight: float, bounds: Bounds) -> float:
    """x moved toward the full effect by `weight`: the paper's linear share for w <= 1, logit beyond."""
    if weight <= 1.0 or full == x:
        return x + weight * (full - x)
    lo, hi = bounds
    span = hi - lo
    start, end = _logit((x - lo) / span), _logit((full - lo) / span)
    return lo + span * _sigmoid(start + weight * (end - start))


def _logit(t: float) -> float:
    t = min(max(t, EDGE), 1.0 - EDGE)
    return math.log(t / (1.0 - t))


def _sigmoid(u: float) -> float:
    if u >= 0:
        return 1.0 / (1.0 + math.exp(-u))
    e = math.exp(u)
    return e / (1.0 + e)


def weighted_map_value(base: float, weight: float, bounds: Bounds | None) -> float:
    """A map parameter scaled by an adverb weight (lightly: half the strokes), saturating in its range."""
    scaled = base * weight
    if bounds is None or weight <= 1.0:
        return scaled
    return knee_step(base, scaled - base, bounds)


def weighted_shade(op: dict[str, Any], weight: float) -> dict[str, Any]:
    """A colour operation applied `weight` times: a share a of the way becomes 1 - (1 - a) ** w, a
    factor s becomes s ** w, so "very dark" is darker than "dark" and never passes black."""
    if weight == 1.0:
        return op
    out = dict(op)
    if "amount" in out and 0.0 <= out["amount"] <= 1.0:
        out["amount"] = 1.0 - (1.0 - out["amount"]) ** weight
    if "scale" in out and out["scale"] > 0:
        out["scale"] = out["scale"] ** weight
    if out["op"] == "mul" and isinstance(out.get("value"), (int, float)) and out["value"] > 0:
        out["value"] = out["value"] ** weight
    return out
