"""Colour arithmetic in linear Rec.709 (the IR's colour space)."""

from __future__ import annotations

import math
import re
from collections.abc import Iterable, Mapping, Sequence
from typing import Any

LUMA = (0.2126, 0.7152, 0.0722)  # Rec.709 luminance weights


def srgb_to_linear(c: float) -> float:
    """IEC 61966-2-1 decoding of one sRGB-encoded channel in [0, 1]."""
    return c / 12.92 if c <= 0.04045 else ((c + 0.055) / 1.055) ** 2.4


def linear_to_srgb(c: float) -> float:
    c = min(max(c, 0.0), 1.0)
    return c * 12.92 if c <= 0.0031308 else 1.055 * c ** (1 / 2.4) - 0.055


HEX_COLOUR = re.compile(r"#?([0-9a-fA-F]{3}|[0-9a-fA-F]{6})")


def parse_hex(hex_code: str) -> tuple[int, int, int] | None:
    """'#0000ff', '0000ff' or the CSS shorthand '#00f' -> (0, 0, 255); None if it is not one of these."""
    match = HEX_COLOUR.fullmatch(hex_code)
    if match is None:
        return None
    digits = match.group(1)
    if len(digits) == 3:
        digits = "".join(d * 2 for d in digits)
    return int(digits[0:2], 16), int(digits[2:4], 16), int(digits[4:6], 16)


def hex_to_linear(hex_code: str) -> list[float]:
    """'#0000ff' (or '#00f') -> [0.0, 0.0, 1.0], rounded to 6 decimals so output is stable.
    ValueError for text that is not a hex colour."""
    channels = parse_hex(hex_code)
    if channels is None:
        raise ValueError(f"{hex_code!r} is not a hex colour ('#rrggbb' or '#rgb')")
    return [round(srgb_to_linear(c / 255), 6) for c in channels]


def linear_to_hex(rgb: Iterable[float]) -> str:
    return "#" + "".join(f"{round(linear_to_srgb(c) * 255):02x}" for c in rgb)


def luminance(rgb: Iterable[float]) -> float:
    return sum(w * c for w, c in zip(LUMA, rgb))


def saturate(rgb: Sequence[float], amount: float) -> list[float]:
    """Move away from (amount > 0) or towards (amount < 0) the grey of equal luminance."""
    y = luminance(rgb)
    return [y + (c - y) * (1 + amount) for c in rgb]


def blend(a: Iterable[float], b: Iterable[float], t: float) -> list[float]:
    return [x + t * (y - x) for x, y in zip(a, b)]


def clamp01(rgb: Iterable[float]) -> list[float]:
    return [min(max(c, 0.0), 1.0) for c in rgb]


# ---------------------------------------------------------------- OKLab (Ottosson 2020)
# https://bottosson.github.io/posts/oklab/ : a perceptual space on linear sRGB (= linear Rec.709).
# Colour shifts ("dark", "light", "-ish") are defined here, so "dark X" is darker than X by
# construction: L is what changes, and a colour outside the gamut loses chroma, never lightness.


def linear_to_oklab(rgb: Sequence[float]) -> list[float]:
    r, g, b = rgb
    lms = (
        0.4122214708 * r + 0.5363325363 * g + 0.0514459929 * b,
        0.2119034982 * r + 0.6806995451 * g + 0.1073969566 * b,
        0.0883024619 * r + 0.2817188376 * g + 0.6299787005 * b,
    )
    l_, m_, s_ = (math.copysign(abs(v) ** (1 / 3), v) for v in lms)
    return [
        0.2104542553 * l_ + 0.7936177850 * m_ - 0.0040720468 * s_,
        1.9779984951 * l_ - 2.4285922050 * m_ + 0.4505937099 * s_,
        0.0259040371 * l_ + 0.7827717662 * m_ - 0.8086757660 * s_,
    ]


def oklab_to_linear(lab: Sequence[float]) -> list[float]:
    L, a, b = lab
    l_ = (L + 0.3963377774 * a + 0.2158037573 * b) ** 3
    m_ = (L - 0.1055613458 * a - 0.0638541728 * b) ** 3
    s_ = (L - 0.0894841775 * a - 1.2914855480 * b) ** 3
    return [
        4.0767416621 * l_ - 3.3077115913 * m_ + 0.2309699292 * s_,
        -1.2684380046 * l_ + 2.6097574011 * m_ - 0.3413193965 * s_,
        -0.0041960863 * l_ - 0.7034186147 * m_ + 1.7076147010 * s_,
    ]


def _in_gamut(rgb: Sequence[float], eps: float = 1e-7) -> bool:
    return all(-eps <= c <= 1 + eps for c in rgb)


def oklab_to_linear_in_gamut(lab: Sequence[float]) -> list[float]:
    """Linear RGB of an OKLab colour; outside [0, 1] it keeps L and hue and loses chroma (bisection)."""
    L = min(max(lab[0], 0.0), 1.0)
    a, b = lab[1], lab[2]
    rgb = oklab_to_linear((L, a, b))
    if _in_gamut(rgb):
        return clamp01(rgb)
    low, high = 0.0, 1.0  # the fraction of the chroma kept
    for _ in range(24):
        mid = (low + high) / 2
        if _in_gamut(oklab_to_linear((L, a * mid, b * mid))):
            low = mid
        else:
            high = mid
    return clamp01(oklab_to_linear((L, a * low, b * low)))


def shift_lightness(rgb: Sequence[float], toward: float, amount: float) -> list[float]:
    """OKLab L moved toward `toward` (0 black, 1 white) by `amount`; chroma kept where the gamut
    allows; a yellow made darker keeps the hue people still call yellow (`darkened_yellow`)."""
    L, a, b = linear_to_oklab(rgb)
    lightness = L + (toward - L) * amount
    return oklab_to_linear_in_gamut((lightness, *darkened_yellow(L, lightness, a, b)))


# A yellow darkened at a constant OKLCh hue turns olive: in the xkcd colour survey
# (stdlib/data/colour_names.toml) the names that stay yellow below OKLab L 0.85 ("dark yellow",
# "mustard yellow", "brownish yellow", "yellow ochre", "yellowish brown") lie at hue 87-101, while
# the hue of "yellow" itself (109.7, L 0.97) is named "olive" at L 0.54 (113.9). So the hue at which
# a colour is still yellow falls with its lightness: 110 at L 0.97, 6 degrees less per 0.1 of L,
# never below 88 (tests/test_colour_darkened_yellow.py checks the line against the survey's names).
YELLOW_LINE = (0.97, 110.0, 60.0, 88.0)  # L where the line starts, its hue there, degrees per unit L, least hue
YELLOW_OFFSETS = (8.0, 14.0)  # degrees past the line a yellow may lie (fully turned; not turned: olive, khaki)
YELLOW_LEAST_CHROMA = 0.04  # a grey with a trace of yellow has no hue to keep


def yellow_hue_at(lightness: float) -> float:
    """The OKLCh hue at which the survey still names a colour of this OKLab lightness yellow."""
    start, hue, per_unit, least = YELLOW_LINE
    return max(least, min(hue, hue - per_unit * (start - lightness)))


def darkened_yellow(was: float, lightness: float, a: float, b: float) -> tuple[float, float]:
    """OKLab a, b of a colour whose lightness went from `was` down to `lightness`. A yellow (a hue on
    or near the survey's line at `was`) turns as the line does, so it stays what the survey calls
    yellow (a mustard, an ochre) instead of an olive; chroma kept. Olives and khakis (well past the
    line), oranges and greens, greys, and a colour made lighter stay as they were."""
    chroma = math.hypot(a, b)
    if lightness >= was or chroma < YELLOW_LEAST_CHROMA:
        return a, b
    hue = math.degrees(math.atan2(b, a)) % 360.0
    goal = yellow_hue_at(lightness)
    offset = hue - yellow_hue_at(was)
    full, none = YELLOW_OFFSETS
    if offset >= none or hue <= goal:
        return a, b
    share = 1.0 if offset <= full else (none - offset) / (none - full)
    turned = math.radians(max(goal, hue - (yellow_hue_at(was) - goal) * share))
    return chroma * math.cos(turned), chroma * math.sin(turned)


def scale_chroma(rgb: Sequence[float], scale: float, keep: float = 0.0) -> list[float]:
    """OKLCh chroma times `scale` at the same L and hue; lowered, never below min(C, keep) (a pale
    tint of a muted colour keeps the chroma its hue is seen at: 'pale oak' stays a wood colour)."""
    L, a, b = linear_to_oklab(rgb)
    chroma = math.hypot(a, b)
    if chroma > 0.0 and scale < 1.0:
        scale = max(scale, min(chroma, keep) / chroma)
    return oklab_to_linear_in_gamut((L, a * scale, b * scale))


def toward_hue(rgb: Sequence[float], target: Sequence[float], amount: float) -> list[float]:
    """OKLab a, b (hue and chroma) moved toward the OKLab `target`'s by `amount`, L kept ("reddish")."""
    L, a, b = linear_to_oklab(rgb)
    return oklab_to_linear_in_gamut((L, a + (target[1] - a) * amount, b + (target[2] - b) * amount))


def mix_oklab(x: Sequence[float], y: Sequence[float], t: float = 0.5) -> list[float]:
    """The OKLab mix of two linear colours ("blue-green": t = 0.5)."""
    p, q = linear_to_oklab(x), linear_to_oklab(y)
    return oklab_to_linear_in_gamut([u + t * (v - u) for u, v in zip(p, q)])


def apply_ops(rgb: Sequence[float], ops: Iterable[Mapping[str, Any]]) -> list[float]:
    """A shade's colour operations (stdlib/lexicon/shades.toml) in order, on linear RGB."""
    out = list(rgb)
    for op in ops:
        kind = op["op"]
        if kind == "saturate":
            out = saturate(out, op["amount"])
        elif kind == "blend":
            out = blend(out, op["value"], op["amount"])
        elif kind == "mul":
            out = [c * op["value"] for c in out]
        elif kind == "lightness":
            out = shift_lightness(out, op["toward"], op["amount"])
        elif kind == "chroma":
            out = scale_chroma(out, op["scale"], op.get("keep", 0.0))
        elif kind == "toward":
            out = toward_hue(out, op["oklab"], op["amount"])
    return clamp01(out)


def hue_gap(x: Sequence[float], y: Sequence[float], least_chroma: float) -> float | None:
    """The OKLCh hue angle between two linear colours in degrees (0..180), or None when either has
    less chroma than `least_chroma` (a grey has no hue to compare)."""
    (_l1, a1, b1), (_l2, a2, b2) = linear_to_oklab(x), linear_to_oklab(y)
    if math.hypot(a1, b1) < least_chroma or math.hypot(a2, b2) < least_chroma:
        return None
    gap = abs(math.degrees(math.atan2(b1, a1) - math.atan2(b2, a2))) % 360.0
    return min(gap, 360.0 - gap)
