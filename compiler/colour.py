"""Colour arithmetic in linear Rec.709 (the IR's colour space)."""

from __future__ import annotations

from collections.abc import Iterable, Sequence

LUMA = (0.2126, 0.7152, 0.0722)  # Rec.709 luminance weights


def srgb_to_linear(c: float) -> float:
    """IEC 61966-2-1 decoding of one sRGB-encoded channel in [0, 1]."""
    return c / 12.92 if c <= 0.04045 else ((c + 0.055) / 1.055) ** 2.4


def linear_to_srgb(c: float) -> float:
    c = min(max(c, 0.0), 1.0)
    return c * 12.92 if c <= 0.0031308 else 1.055 * c ** (1 / 2.4) - 0.055


def hex_to_linear(hex_code: str) -> list[float]:
    """'#0000ff' -> [0.0, 0.0, 1.0], rounded to 6 decimals so output is stable."""
    h = hex_code.lstrip("#")
    return [round(srgb_to_linear(int(h[i : i + 2], 16) / 255), 6) for i in (0, 2, 4)]


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
