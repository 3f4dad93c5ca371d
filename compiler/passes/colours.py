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
    An adverb's `weight` goes to the shades: "very dark grey" is grey made dark 1.5 times (also when
    the survey names "dark grey" itself); a plain colour at a weight below 1 ("slightly red", "almost
    black") is that share of the way from `start` to the colour in OKLab (a linear blend left
    'almost black' paint a mid grey, L 0.5)."""
    shades, base = c.shades, c.base
    if base is None and shades and ctx.lexicon.entry("colours", shades[-1].key) is not None:
        shades, base = shades[:-1], shades[-1]
    rgb = list(ctx.lexicon.require("colours", base.key).get("rgb")) if base else list(start or NEUTRAL)
    if weight != 1.0 and base is not None and not shades:
        return _weighted_plain(rgb, base.key, ctx, start, weight)
    for word in reversed(shades):  # the shade nearest the colour applies first
        rgb = shade(rgb, _ops(ctx, word.key, weight))
    return rgb


def _ops(ctx: Context, shade_key: str, weight: float) -> list[dict[str, Any]]:
    ops: list[dict[str, Any]] = ctx.lexicon.require("shades", shade_key).get("ops")
    return ops if weight == 1.0 else [weighted_shade(op, weight) for op in ops]


def _weighted_plain(rgb: list[float], key: str, ctx: Context, start: list[float] | None, weight: float) -> list[float]:
    """A colour word without separate shades at an adverb weight: a shaded survey name ("dark teal")
    takes its shade once more ('very dark grey'), or lies that share of the way from the plain
    colour to it in OKLab ('fairly dark grey': three quarters of the way from grey to the survey's
    dark grey, so it stays dark); any other colour is simply itself, or part of the way to it."""
    shaded = _shaded_name(key, ctx)
    if shaded is not None:
        shade_key, plain_key = shaded
        if weight > 1.0:
            return shade(rgb, _ops(ctx, shade_key, weight - 1.0))
        return colour.mix_oklab(list(ctx.lexicon.require("colours", plain_key).get("rgb")), rgb, weight)
    if weight < 1.0 and start is not None:  # in OKLab: 'almost black' is nearly black to the eye
        return colour.mix_oklab(start, rgb, weight)
    return rgb


def _shaded_name(key: str, ctx: Context) -> tuple[str, str] | None:
    """('dark', 'teal') for the survey's "dark teal" when both halves are known, else None."""
    head, _, rest = key.partition(" ")
    if rest and ctx.lexicon.entry("shades", head) is not None and ctx.lexicon.entry("colours", rest) is not None:
        return head, rest
    return None


def opposed_shades(c: ast.Colour, ctx: Context) -> tuple[str, str] | None:
    """The first two shade words of a colour that pull opposite ways (lighter and darker, or more and
    less chroma: "light dark beech", "pale deep cherry"), inner one first; else None. The shade word
    that opens a two-word colour name counts as the innermost ("pale dark grey", "dark pale green":
    the survey's "dark grey" and "pale green") when it says lightness, by its lightness only ("pale
    dusty pink" agrees); a longer name is a name ("pale dark slate grey" is a
    pale version of that colour)."""
    words = [(w.text, w.key) for w in reversed(c.shades)]  # nearest the colour first, as applied
    pulls = [(text, _pull(ctx, key)) for text, key in words if ctx.lexicon.entry("shades", key) is not None]
    named = c.base.text.lower().split() if c.base is not None else []
    if len(named) == 2 and named[0] in _lightness_shades() and ctx.lexicon.entry("shades", named[0]) is not None:
        pulls.insert(0, (named[0], (_pull(ctx, named[0])[0], 0.0)))  # its lightness only ('pale dusty pink' agrees)
    for i, (inner, a) in enumerate(pulls):
        for outer, b in pulls[i + 1 :]:
            if any(x * y < 0 for x, y in zip(a, b)):
                return inner, outer
    return None


def _lightness_shades() -> frozenset[str]:
    """The shades that say lightness (colour_rules.toml [shade_directions]: dark, deep, light, pale)."""
    from ..lexicon_load import colour_rules

    return frozenset(colour_rules()["shade_directions"])


def _pull(ctx: Context, shade_key: str) -> tuple[float, float]:
    """Which way a shade moves lightness and chroma (+1, -1 or 0 each), from its operations."""
    light = chroma = 0.0
    for op in _ops(ctx, shade_key, 1.0):
        if op["op"] == "lightness":
            light = 1.0 if op["toward"] > 0.5 else -1.0
        elif op["op"] == "chroma":
            chroma = 0.0 if op["scale"] == 1 else (1.0 if op["scale"] > 1 else -1.0)
    return light, chroma


def colour_text(c: ast.Colour) -> str:
    return " ".join([w.text for w in c.words])
