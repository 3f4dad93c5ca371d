"""Colour arithmetic in linear Rec.709 (the IR's colour space)."""

from __future__ import annotations

import re
from collections.abc import Iterable, Sequence

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
