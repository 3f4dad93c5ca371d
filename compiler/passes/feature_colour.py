"""A colour named for a feature that has a colour of its own: "a green patina", "gold veins".

The feature's map has its own colour (the graph's color_r/g/b defaults: the patina's verdigris,
the veins' and speckles' grey). A survey colour is a flat, saturated swatch; painted over a
natural texture it looks like a toy. So a named colour meets the own colour in OKLCh
(features.toml `hue_family`, `keep_own`):

- a named colour without chroma (grey, black, white) says how light: it is used as it is;
- a named colour in the own colour's hue family (hue angles within `hue_family` degrees) agrees
  with it: the own colour is kept, and only the clause's shades act on it ("a dark green patina"
  is a dark verdigris);
- any other colour gives its hue; lightness and chroma move from the own colour toward the named
  one, keeping the share `keep_own` of the own ("a brown patina" is as pale as verdigris is,
  "gold veins" are a muted gold as mineral veins are).

The colour word meets the own colour; its shades come after, also those inside a survey name
("dark brown" is 'dark' on the brown patina, so it is darker than "brown").
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass

from .. import ast
from ..colour import apply_ops, linear_to_oklab, oklab_to_linear_in_gamut
from ..state import Context

# OKLCh chroma below which a colour reads as a grey (the survey's "grey" has 0.007, "beige" 0.06);
# our choice: between the two, so the greys, black and white count as colourless
ACHROMATIC_CHROMA = 0.04


@dataclass(frozen=True)
class Meeting:
    """How a named colour met the map's own colour: 'named' (used as it is), 'own' (the own
    colour kept, shades on it), or 'mixed' (the named hue, lightness and chroma partly the own)."""

    how: str
    rgb: list[float]


def lch(rgb: Sequence[float]) -> tuple[float, float, float]:
    """OKLCh of a linear RGB colour: lightness, chroma, hue in degrees."""
    L, a, b = linear_to_oklab(rgb)
    return L, math.hypot(a, b), math.degrees(math.atan2(b, a)) % 360.0


def hue_distance(h1: float, h2: float) -> float:
    """The angle between two hues, 0 to 180 degrees."""
    d = abs(h1 - h2) % 360.0
    return min(d, 360.0 - d)


def meet(own: Sequence[float], named: Sequence[float], hue_family: float, keep_own: float) -> Meeting:
    """The named colour against the own colour, by the rules above (`rgb` is the result for
    'named' and 'mixed'; for 'own' the caller applies the clause's shades to the own colour)."""
    own_l, own_c, own_h = lch(own)
    named_l, named_c, named_h = lch(named)
    if named_c < ACHROMATIC_CHROMA:
        return Meeting("named", list(named))
    if own_c >= ACHROMATIC_CHROMA and hue_distance(own_h, named_h) <= hue_family:
        return Meeting("own", list(own))
    lightness = named_l + keep_own * (own_l - named_l)
    chroma = named_c + keep_own * (own_c - named_c)
    hue = math.radians(named_h)
    lab = (lightness, chroma * math.cos(hue), chroma * math.sin(hue))
    return Meeting("mixed", oklab_to_linear_in_gamut(lab))


@dataclass(frozen=True)
class PlainColour:
    """A clause's colour word without its shades: its text, linear RGB, and the shade keys that
    come after it meets the own colour (outermost first, as written)."""

    word: str
    rgb: list[float]
    shades: tuple[str, ...]


def plain_colour(ctx: Context, colour: ast.Colour) -> PlainColour | None:
    """The colour word of a clause's colour ('green' of 'dark green', also of the survey's one name
    "dark green"; a noun's own colour: 'a bronze patina'); None for shades alone ('a dark patina')."""
    shades = tuple(w.key for w in colour.shades)
    if colour.noun is not None:
        entry = None if colour.noun.unknown else ctx.lexicon.entry("nouns", colour.noun.key)
        if entry is None or colour.base is not None:
            return None
        return PlainColour(colour.noun.text, list(entry.get("base_color")), shades)
    if colour.base is not None:
        word, key = colour.base.text, colour.base.key
    elif shades and ctx.lexicon.entry("colours", shades[-1]) is not None:  # 'a greenish patina'
        word, key, shades = colour.shades[-1].text, shades[-1], shades[:-1]
    else:
        return None
    head, _, rest = key.partition(" ")
    if rest and ctx.lexicon.entry("shades", head) is not None and ctx.lexicon.entry("colours", rest) is not None:
        word, key, shades = rest, rest, (*shades, head)  # the survey's "dark brown": 'dark' on brown
    return PlainColour(word, list(ctx.lexicon.require("colours", key).get("rgb")), shades)


def with_shades(ctx: Context, rgb: Sequence[float], shades: tuple[str, ...]) -> list[float]:
    """The shades on a colour, the one nearest the colour word first."""
    out = list(rgb)
    for key in reversed(shades):
        out = apply_ops(out, ctx.lexicon.require("shades", key).get("ops"))
    return out
