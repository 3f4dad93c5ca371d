"""Colour words to linear RGB: a named colour, then its shades in order ("pale blue")."""

from __future__ import annotations

from typing import Any

from .. import ast, colour
from ..degrees import weighted_shade
from ..state import Context

NEUTRAL = [1.0, 1.0, 1.0]


def shade(rgb: list[float], ops: list[dict[str, Any]]) -> list[float]:
    return colour.apply_ops(rgb, ops)


def resolve_colour(c: ast.Colour, ctx: Context, start: list[float] | None = None, weight: float = 1.0) -> list[float]:
    """RGB of a colour phrase; shades alone ("dark wood") act on `start`, but a last shade that is
    also a colour ("reddish" in "reddish plastic", "dark reddish oak") is that colour, as "red" would be.
    An adverb's `weight` goes to the shades: "very dark grey" is grey made dark 1.5 times."""
    shades, base = c.shades, c.base
    if base is None and shades and ctx.lexicon.entry("colours", shades[-1].key) is not None:
        shades, base = shades[:-1], shades[-1]
    rgb = list(ctx.lexicon.require("colours", base.key).get("rgb")) if base else list(start or NEUTRAL)
    for word in reversed(shades):  # the shade nearest the colour applies first
        ops = ctx.lexicon.require("shades", word.key).get("ops")
        rgb = shade(rgb, ops if weight == 1.0 else [weighted_shade(op, weight) for op in ops])
    return rgb


def colour_text(c: ast.Colour) -> str:
    return " ".join(w.text for w in c.words)
