"""Colour words to linear RGB: a named colour, then its shades in order ("pale blue")."""

from __future__ import annotations

from typing import Any

from .. import ast, colour
from ..state import Context

NEUTRAL = [1.0, 1.0, 1.0]


def shade(rgb: list[float], ops: list[dict[str, Any]]) -> list[float]:
    for op in ops:
        if op["op"] == "saturate":
            rgb = colour.saturate(rgb, op["amount"])
        elif op["op"] == "blend":
            rgb = colour.blend(rgb, op["value"], op["amount"])
        elif op["op"] == "mul":
            rgb = [c * op["value"] for c in rgb]
    return colour.clamp01(rgb)


def resolve_colour(c: ast.Colour, ctx: Context, start: list[float] | None = None) -> list[float]:
    """RGB of a colour phrase; shades alone ("dark wood") act on `start`."""
    rgb = list(ctx.lexicon.require("colours", c.base.key).get("rgb")) if c.base else list(start or NEUTRAL)
    for word in reversed(c.shades):  # the shade nearest the colour applies first
        rgb = shade(rgb, ctx.lexicon.require("shades", word.key).get("ops"))
    return rgb


def colour_text(c: ast.Colour) -> str:
    return " ".join(w.text for w in c.words)
