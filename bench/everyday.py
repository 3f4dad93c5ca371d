"""Everyday language: how many of the phrases designers really type compile, and to something plausible.

Reads tests/language/everyday.toml (the phrases, their categories and abstract expectations; the
expectation vocabulary and its thresholds are defined in that file's header), compiles every phrase
through the real compiler (cnlmc.api), checks each stated expectation against the IR and prints,
per category: the number of phrases, accepted % (compiled without an error), plausible % (accepted
and every stated expectation met) and clean % (accepted without any warning); then the
refinement sequences; then every failure grouped by reason.

    .venv/bin/python bench/everyday.py              # the table and the failures
    .venv/bin/python bench/everyday.py --summary    # the table only
    .venv/bin/python bench/everyday.py --json out.json

The checking functions (`apparent_colour`, `oklab`, `hue_family`, `band`, `effective_roughness`,
`map_features`, `check_material`, `direction`) are pure functions of an IR material dict so that
tests/language/test_everyday_set.py can test the measurement itself on hand-built IR.

Colour science used here (implemented below, no dependency):
- sRGB transfer function: IEC 61966-2-1.
- OKLab: Björn Ottosson, "A perceptual color space for image processing" (2020),
  https://bottosson.github.io/posts/oklab/ (the M1/M2 matrices are his published numbers).
- CIELAB (D65) and CIEDE2000: CIE 15:2004; G. Sharma, W. Wu, E. N. Dalal, "The CIEDE2000
  color-difference formula: implementation notes, supplementary test data, and mathematical
  observations", Color Res. Appl. 30(1), 2005.
"""

from __future__ import annotations

import argparse
import functools
import json
import math
import re
import sys
import time
import tomllib
from collections import Counter, defaultdict
from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

ROOT = Path(__file__).resolve().parents[1]
SET_PATH = ROOT / "tests" / "language" / "everyday.toml"

# --------------------------------------------------------------------------------------------
# colour science

RGB = tuple[float, float, float]


def srgb_to_linear(c: float) -> float:
    """One sRGB-encoded channel in [0, 1] -> linear (IEC 61966-2-1)."""
    return c / 12.92 if c <= 0.04045 else ((c + 0.055) / 1.055) ** 2.4


def linear_to_srgb(c: float) -> float:
    """One linear channel -> sRGB-encoded (clipped to [0, 1])."""
    c = min(max(c, 0.0), 1.0)
    return 12.92 * c if c <= 0.0031308 else 1.055 * c ** (1 / 2.4) - 0.055


def hex_to_linear(h: str) -> RGB:
    h = h.lstrip("#")
    r, g, b = (int(h[i : i + 2], 16) / 255 for i in (0, 2, 4))
    return (srgb_to_linear(r), srgb_to_linear(g), srgb_to_linear(b))


def linear_to_hex(rgb: Sequence[float]) -> str:
    return "#" + "".join(f"{round(linear_to_srgb(c) * 255):02x}" for c in rgb)


def oklab(rgb: Sequence[float]) -> RGB:
    """Linear sRGB (Rec.709 primaries, D65) -> OKLab (L, a, b); Ottosson 2020's matrices."""
    r, g, b = (max(float(c), 0.0) for c in rgb)
    l_ = 0.4122214708 * r + 0.5363325363 * g + 0.0514459929 * b
    m_ = 0.2119034982 * r + 0.6806995451 * g + 0.1073969566 * b
    s_ = 0.0883024619 * r + 0.2817188376 * g + 0.6299787005 * b
    l_, m_, s_ = (math.copysign(abs(v) ** (1 / 3), v) for v in (l_, m_, s_))
    return (
        0.2104542553 * l_ + 0.7936177850 * m_ - 0.0040720468 * s_,
        1.9779984951 * l_ - 2.4285922050 * m_ + 0.4505937099 * s_,
        0.0259040371 * l_ + 0.7827717662 * m_ - 0.8086757660 * s_,
    )


def oklab_to_linear(lab: Sequence[float]) -> RGB:
    """OKLab -> linear sRGB (the inverse matrices, Ottosson 2020)."""
    L, a, b = lab
    l_ = (L + 0.3963377774 * a + 0.2158037573 * b) ** 3
    m_ = (L - 0.1055613458 * a - 0.0638541728 * b) ** 3
    s_ = (L - 0.0894841775 * a - 1.2914855480 * b) ** 3
    return (
        4.0767416621 * l_ - 3.3077115913 * m_ + 0.2309699292 * s_,
        -1.2684380046 * l_ + 2.6097574011 * m_ - 0.3413193965 * s_,
        -0.0041960863 * l_ - 0.7034186147 * m_ + 1.7076147010 * s_,
    )


def oklch(rgb: Sequence[float]) -> RGB:
    """Linear sRGB -> (L, C, h in degrees [0, 360)) in OKLab's polar form."""
    L, a, b = oklab(rgb)
    return (L, math.hypot(a, b), math.degrees(math.atan2(b, a)) % 360.0)


_D65 = (0.95047, 1.0, 1.08883)


def cielab(rgb: Sequence[float]) -> RGB:
    """Linear sRGB -> CIELAB (D65 white, 2° observer; IEC 61966-2-1 matrix, CIE 15:2004)."""
    r, g, b = (max(float(c), 0.0) for c in rgb)
    xyz = (
        0.4124564 * r + 0.3575761 * g + 0.1804375 * b,
        0.2126729 * r + 0.7151522 * g + 0.0721750 * b,
        0.0193339 * r + 0.1191920 * g + 0.9503041 * b,
    )
    d = 6 / 29

    def f(t: float) -> float:
        return t ** (1 / 3) if t > d**3 else t / (3 * d * d) + 4 / 29

    fx, fy, fz = (f(v / n) for v, n in zip(xyz, _D65))
    return (116 * fy - 16, 500 * (fx - fy), 200 * (fy - fz))


def delta_e2000(lab1: Sequence[float], lab2: Sequence[float]) -> float:
    """CIEDE2000 colour difference of two CIELAB colours (Sharma, Wu & Dalal 2005), kL = kC = kH = 1."""
    L1, a1, b1 = lab1
    L2, a2, b2 = lab2
    c_bar = (math.hypot(a1, b1) + math.hypot(a2, b2)) / 2
    g = 0.5 * (1 - math.sqrt(c_bar**7 / (c_bar**7 + 25.0**7)))
    a1p, a2p = a1 * (1 + g), a2 * (1 + g)
    c1p, c2p = math.hypot(a1p, b1), math.hypot(a2p, b2)
    h1p = math.degrees(math.atan2(b1, a1p)) % 360 if c1p else 0.0
    h2p = math.degrees(math.atan2(b2, a2p)) % 360 if c2p else 0.0
    dLp, dCp = L2 - L1, c2p - c1p
    if c1p * c2p == 0:
        dhp = 0.0
    elif abs(h2p - h1p) <= 180:
        dhp = h2p - h1p
    elif h2p - h1p > 180:
        dhp = h2p - h1p - 360
    else:
        dhp = h2p - h1p + 360
    dHp = 2 * math.sqrt(c1p * c2p) * math.sin(math.radians(dhp / 2))
    Lp_bar, Cp_bar = (L1 + L2) / 2, (c1p + c2p) / 2
    if c1p * c2p == 0:
        hp_bar = h1p + h2p
    elif abs(h1p - h2p) <= 180:
        hp_bar = (h1p + h2p) / 2
    elif h1p + h2p < 360:
        hp_bar = (h1p + h2p + 360) / 2
    else:
        hp_bar = (h1p + h2p - 360) / 2
    t = (
        1
        - 0.17 * math.cos(math.radians(hp_bar - 30))
        + 0.24 * math.cos(math.radians(2 * hp_bar))
        + 0.32 * math.cos(math.radians(3 * hp_bar + 6))
        - 0.20 * math.cos(math.radians(4 * hp_bar - 63))
    )
    d_theta = 30 * math.exp(-(((hp_bar - 275) / 25) ** 2))
    rc = 2 * math.sqrt(Cp_bar**7 / (Cp_bar**7 + 25.0**7))
    sl = 1 + 0.015 * (Lp_bar - 50) ** 2 / math.sqrt(20 + (Lp_bar - 50) ** 2)
    sc = 1 + 0.045 * Cp_bar
    sh = 1 + 0.015 * Cp_bar * t
    rt = -math.sin(math.radians(2 * d_theta)) * rc
    return math.sqrt((dLp / sl) ** 2 + (dCp / sc) ** 2 + (dHp / sh) ** 2 + rt * (dCp / sc) * (dHp / sh))


# --------------------------------------------------------------------------------------------
# the expectation vocabulary (the header of everyday.toml explains each; the bands are data there)

BOOLEAN_KEYS = ("conductor", "transmissive", "coat", "anisotropic", "warns")
BAND_KEYS = ("lightness", "roughness")
HUE_FAMILIES = ("red", "orange", "yellow", "green", "cyan", "blue", "purple", "pink", "brown", "neutral")
EXPECTATION_KEYS = (*BOOLEAN_KEYS, *BAND_KEYS, "hue", "maps")
ENTRY_KEYS = ("text", "category", "lexicon", "note", "same_as", *EXPECTATION_KEYS)
DIRECTIONS = ("up", "down", "same", "changed")
DIRECTION_KEYS = ("roughness", "lightness", "chroma", "anisotropy", "maps", "hue")

NEUTRAL_CHROMA = 0.04  # OKLab chroma below this is a grey (white, black)

# map features: a feature is present when some map of the material uses one of these graphs
MAP_FEATURES: dict[str, tuple[str, ...]] = {
    "grain": ("wood",),
    "veins": ("marble", "veins"),
    "speckle": ("granite", "terrazzo", "speckle"),
    "brushed": ("brushed",),
    "hammered": ("hammered",),
    "rust": ("rust",),
    "patina": ("patina", "rust"),
    "scratches": ("scratched",),
    "weave": ("fabric", "weave"),
    "leather": ("leather",),
    "bricks": ("brick",),
    "tiles": ("tiles", "tile", "brick"),
    "planks": ("planks", "wood"),
    "cracks": ("cracked",),
    "mottle": ("concrete", "stone", "sandblasted"),
    "flakes": ("flakes", "metal_flakes", "sparkle"),
    "any": (),  # any map at all
}


def hue_family(rgb: Sequence[float]) -> str:
    """The everyday hue family of a linear sRGB colour, from its OKLCh (L, C, h).

    neutral: C < 0.04. Otherwise by hue angle h (degrees):
      [0, 40)    pink when L >= 0.72 or (L >= 0.62 and C < 0.12), else red
      [40, 100)  brown when L < 0.62 or (C < 0.1 and L < 0.82); else orange (h < 75) or yellow
      [100, 115) yellow when L >= 0.7, else green (olive)
      [115, 170) green;  [170, 225) cyan;  [225, 290) blue
      [290, 320) purple; [320, 360) pink when L >= 0.55, else purple
    """
    L, C, h = oklch(rgb)
    if C < NEUTRAL_CHROMA:
        return "neutral"
    if h < 40:
        return "pink" if L >= 0.72 or (L >= 0.62 and C < 0.12) else "red"
    if h < 100:
        if L < 0.62 or (C < 0.1 and L < 0.82):
            return "brown"
        return "orange" if h < 75 else "yellow"
    if h < 115:
        return "yellow" if L >= 0.7 else "green"
    if h < 170:
        return "green"
    if h < 225:
        return "cyan"
    if h < 290:
        return "blue"
    if h < 320:
        return "purple"
    return "pink" if L >= 0.55 else "purple"


def apparent_colour(m: Mapping[str, Any], mixture: bool = False) -> RGB:
    """The colour a person sees: base_color, times the measured F0 for a conductor (its tint),
    times a coat's round-trip transmittance tint (params.coat.color: a black lacquer is black); a
    metal's colour map without a mask is a tint over its reflectance (a tarnish): its mean. A
    layer drawn over the surface by a mask (rust, patina) is named when it covers most of it: the
    mean colour of the layer (its baked colour weighted by the mask, MASK_TEXELS² texels) when the
    mask's mean is at least LAYER_NAMED (clearly most of the surface; at half and half either may be
    named), else the surface's own colour. (Not the mean of the two: green patina over pink copper
    averages to a grey no one sees.) `mixture`: the mean of the two instead, for telling whether a
    colour changed at all (a patina over half the surface changes the hue a person sees)."""
    p = m["params"]
    base = [float(c) for c in p.get("base_color", (1.0, 1.0, 1.0))]
    if m["model"]["base"] == "glass" and p.get("transmission_depth"):
        base = seen_through_the_body(base, float(p["transmission_depth"]))
    maps = m.get("maps") or {}
    if m["model"]["base"] == "conductor" and "base_color" in maps and "mask" not in maps:
        base = _map_mean(json.dumps({"base_color": maps["base_color"]}, sort_keys=True), tuple(base))  # a tarnish
    if m["model"]["base"] == "conductor" and p.get("f0"):
        base = [b * float(f) for b, f in zip(base, p["f0"])]
    coat = p.get("coat") or {}
    if coat.get("color"):  # a tinted coat: the light crosses it on the way in and out (its round-trip tint)
        base = [b * float(c) for b, c in zip(base, coat["color"])]
    if "mask" in maps and "base_color" in maps:
        base = _masked_mean(json.dumps(maps, sort_keys=True), tuple(base), mixture)
    return (min(base[0], 1.0), min(base[1], 1.0), min(base[2], 1.0))


def seen_through_the_body(colour: Sequence[float], depth: float) -> list[float]:
    """A clear body's colour as the preview shows it: base_color is the transmittance through
    transmission_depth (Beer-Lambert); seen head-on, the preview's sphere (radius one unit,
    METRES_PER_UNIT metres) is crossed along a chord of 2·r·√(1 − b²) at a distance b from the
    centre, so the colour seen is the mean transmittance over its disc (b² uniform): a glass of
    cola is near black in the middle and brown at the rim, a glass of water clear."""
    from cnlmc.backends.exchange.mitsuba_subsurface import METRES_PER_UNIT

    rings = [(i + 0.5) / DISC_RINGS for i in range(DISC_RINGS)]  # b², uniform over the disc
    chords = [2.0 * METRES_PER_UNIT * math.sqrt(1.0 - s) for s in rings]
    return [sum(max(float(c), 0.0) ** (chord / depth) for chord in chords) / DISC_RINGS for c in colour]


DISC_RINGS = 64
MASK_TEXELS = 64
LAYER_NAMED = 0.6


@functools.lru_cache(maxsize=256)
def _map_mean(maps_json: str, own: tuple[float, ...]) -> list[float]:
    """The mean of a baked colour map over a material of colour `own` (a metal's tint map: the film
    of a tarnish over its own colour)."""
    from cnlmc.backends.maps.bake import bake

    baked = bake(json.loads(maps_json), {"base_color": list(own)}, size=MASK_TEXELS)["base_color"]
    return [float(c) for c in baked.reshape(-1, 3).mean(axis=0)]


@functools.lru_cache(maxsize=256)
def _masked_mean(maps_json: str, own: tuple[float, ...], mixture: bool) -> list[float]:
    """The colour of a masked layer over a surface of colour `own` (see apparent_colour)."""
    import numpy as np

    from cnlmc.backends.maps.bake import bake

    baked = bake(json.loads(maps_json), size=MASK_TEXELS)
    mask = baked["mask"].reshape(-1)
    if mixture:
        seen = mask[:, None] * baked["base_color"].reshape(-1, 3) + (1.0 - mask[:, None]) * np.asarray(own)
        return [float(c) for c in seen.mean(axis=0)]
    if float(mask.mean()) < LAYER_NAMED:
        return list(own)
    layer = (mask[:, None] * baked["base_color"].reshape(-1, 3)).sum(axis=0) / float(mask.sum())
    return [float(c) for c in np.asarray(layer)]


def effective_roughness(m: Mapping[str, Any]) -> float:
    """Perceptual roughness of the surface a person sees: the coat's when there is one, 1.0 for a
    diffuse-only model (no highlight at all), else params.roughness."""
    p = m["params"]
    if p.get("coat"):
        return float(p["coat"]["roughness"])
    if m["model"]["base"] == "diffuse" or "roughness" not in p:
        return 1.0
    return float(p["roughness"])


def effective_alpha(m: Mapping[str, Any]) -> float:
    """The visible lobe's microfacet alpha (mean of alpha_x, alpha_y; the coat's when coated; 1 for diffuse)."""
    p = m["params"]
    if p.get("coat"):
        return float(sum(p["coat"]["alpha"]) / 2)
    if m["model"]["base"] == "diffuse" or "alpha" not in p:
        return 1.0
    return float(sum(p["alpha"]) / 2)


def band(bands: Mapping[str, Sequence[float]], value: float) -> str:
    """The name of the [lo, hi) band holding value (the highest band is closed above)."""
    for name, (lo, hi) in bands.items():
        if lo <= value < hi:
            return name
    return (
        max(bands.items(), key=lambda kv: kv[1][1])[0] if value >= 0 else min(bands.items(), key=lambda kv: kv[1][0])[0]
    )


def map_features(m: Mapping[str, Any]) -> set[str]:
    """The features the material's maps show (MAP_FEATURES), plus 'any' when it has a map, plus
    'flakes' when it has a flake lobe (drawn as a distribution, not a map: docs/bsdf.md)."""
    graphs = {ref["graph"] for ref in (m.get("maps") or {}).values()}
    found = {name for name, gs in MAP_FEATURES.items() if graphs & set(gs)}
    flakes = {"flakes"} if (m.get("params") or {}).get("flake_density", 0) > 0 else set()
    return found | flakes | ({"any"} if graphs else set())


def as_list(value: Any) -> list[Any]:
    return list(value) if isinstance(value, list) else [value]


def observe(m: Mapping[str, Any], bands: Mapping[str, Mapping[str, Sequence[float]]]) -> dict[str, Any]:
    """Every abstract quantity an expectation can name, read from one IR material."""
    colour = apparent_colour(m)
    L, C, h = oklch(colour)
    return {
        "conductor": m["model"]["base"] == "conductor",
        "transmissive": m["model"]["base"] == "glass",
        "coat": bool(m["model"]["coat"]),
        "anisotropic": bool(m["model"]["anisotropic"]),
        "hue": hue_family(colour),
        "lightness": band(bands["lightness"], L),
        "roughness": band(bands["roughness"], effective_roughness(m)),
        "maps": sorted(map_features(m)),
        "_L": round(L, 3),
        "_C": round(C, 3),
        "_h": round(h, 1),
        "_r": round(effective_roughness(m), 3),
        "_hex": linear_to_hex(colour),
    }


def check_material(
    m: Mapping[str, Any],
    expect: Mapping[str, Any],
    bands: Mapping[str, Mapping[str, Sequence[float]]],
    warnings: Iterable[str] = (),
) -> list[tuple[str, str, str]]:
    """The expectations `m` misses: (key, expected, actual) triples; [] when all are met.

    `warnings` are the codes of the warnings compiling gave (for the `warns` key)."""
    seen = observe(m, bands)
    misses: list[tuple[str, str, str]] = []
    for key in EXPECTATION_KEYS:
        if key not in expect:
            continue
        want = expect[key]
        if key == "warns":
            codes = list(warnings)
            if bool(codes) != want:
                misses.append((key, str(want), ",".join(codes) or "none"))
        elif key == "maps":
            have = set(seen["maps"])
            if want == [] and have:
                misses.append((key, "none", ",".join(sorted(have))))
            missing = [f for f in want if f not in have]
            if missing:
                misses.append((key, ",".join(want), ",".join(sorted(have)) or "none"))
        elif key in BOOLEAN_KEYS:
            if seen[key] != want:
                misses.append((key, str(want), str(seen[key])))
        else:
            allowed = as_list(want)
            if seen[key] not in allowed:
                detail = {
                    "hue": f"{seen['hue']} ({seen['_hex']}, h={seen['_h']}, C={seen['_C']}, L={seen['_L']})",
                    "lightness": f"{seen['lightness']} (L={seen['_L']}, {seen['_hex']})",
                    "roughness": f"{seen['roughness']} (r={seen['_r']})",
                }[key]
                misses.append((key, "|".join(allowed), detail))
    return misses


def quantity(m: Mapping[str, Any], key: str) -> Any:
    """The value a refinement direction is measured on. A diffuse-only surface's roughness is read
    on its Oren-Nayar sigma (how flat its shading is), above every surface with a highlight: 1 + sigma."""
    if key == "roughness":
        if m["model"]["base"] == "diffuse" and not m["params"].get("coat"):
            return 1.0 + float(m["params"].get("diffuse_roughness", 0.0))
        return effective_roughness(m)
    if key == "lightness":
        return oklch(apparent_colour(m))[0]
    if key == "chroma":
        return oklch(apparent_colour(m))[1]
    if key == "hue":
        return oklch(apparent_colour(m))[2]
    if key == "anisotropy":
        return float(m["params"].get("anisotropy", 0.0)) if m["model"]["anisotropic"] else 0.0
    if key == "maps":
        return json.dumps(m.get("maps") or {}, sort_keys=True)
    raise KeyError(key)


def direction(before: Any, after: Any, eps: float = 1e-6) -> str:
    """'up', 'down' or 'same' for numbers; 'changed' or 'same' for anything else."""
    if isinstance(before, (int, float)) and isinstance(after, (int, float)):
        if after > before + eps:
            return "up"
        if after < before - eps:
            return "down"
        return "same"
    return "same" if before == after else "changed"


#: a hue moves when its OKLCh angle moves by more than this many degrees (about a just-noticeable hue
#: step at everyday chroma; the IR's six-decimal colours move the angle of a pure step in chroma by
#: ~1e-3 degrees, which is no change of hue). Below HUE_CHROMA an angle means little: there the
#: colour's OKLab (a, b) must move by more than HUE_CHROMA (a grey that gains or loses a tint).
HUE_STEP_DEGREES = 1.0
HUE_CHROMA = 0.005


def hue_direction(before: Mapping[str, Any], after: Mapping[str, Any]) -> str:
    """'changed' or 'same' for the apparent colour's hue (angles compared around the circle)."""
    (_, c0, h0), (_, c1, h1) = oklch(apparent_colour(before, True)), oklch(apparent_colour(after, True))
    if min(c0, c1) < HUE_CHROMA:
        a0, b0 = c0 * math.cos(math.radians(h0)), c0 * math.sin(math.radians(h0))
        a1, b1 = c1 * math.cos(math.radians(h1)), c1 * math.sin(math.radians(h1))
        return "changed" if math.hypot(a1 - a0, b1 - b0) > HUE_CHROMA else "same"
    turn = abs((h1 - h0 + 180.0) % 360.0 - 180.0)
    return "changed" if turn > HUE_STEP_DEGREES else "same"


def direction_met(want: str, got: str) -> bool:
    return got == want or (want == "changed" and got in ("up", "down"))


# --------------------------------------------------------------------------------------------
# the set


def load_set(path: Path = SET_PATH) -> dict[str, Any]:
    with open(path, "rb") as f:
        return tomllib.load(f)


def message_template(message: str) -> str:
    """A diagnostic message with its quoted words replaced, so that failures group by kind."""
    return re.sub(r"'[^']*'", "'…'", message)


@dataclass
class Outcome:
    text: str
    category: str
    accepted: bool
    errors: list[tuple[str, str]] = field(default_factory=list)  # (code, message)
    warnings: list[tuple[str, str]] = field(default_factory=list)
    misses: list[tuple[str, str, str]] = field(default_factory=list)
    hints: list[str] = field(default_factory=list)  # the first error's hints ("did you mean ...")

    @property
    def plausible(self) -> bool:
        return self.accepted and not self.misses


def lexicon(name: str | None) -> Any:
    from cnlmc import api

    return api.lexicon_for([name] if name else [])


def run_phrase(entry: Mapping[str, Any], bands: Mapping[str, Any]) -> Outcome:
    from cnlmc import api

    text, category = entry["text"], entry["category"]
    try:
        result = api.compile_source(text, "<everyday>", lexicon(entry.get("lexicon")))
    except Exception as exc:  # a crash is a rejection too, and worth seeing
        return Outcome(text, category, False, [("CRASH", f"{type(exc).__name__}: {exc}")])
    errors = [(d.code, d.message) for d in result.diagnostics if d.is_error]
    warnings = [(d.code, d.message) for d in result.diagnostics if d.severity.value == "warning"]
    if errors or not result.materials:
        hints = next((list(d.hints) for d in result.diagnostics if d.is_error), [])
        return Outcome(text, category, False, errors or [("E003", "the phrase names no material")], warnings, [], hints)
    expect = {k: entry[k] for k in EXPECTATION_KEYS if k in entry}
    misses = check_material(result.materials[0], expect, bands, [c for c, _ in warnings])
    if "same_as" in entry:
        other = api.compile_source(entry["same_as"], "<everyday>", lexicon(entry.get("lexicon")))
        if not other.ok or not other.materials:
            misses.append(("same_as", entry["same_as"], "that phrase is rejected"))
        else:
            diff = differences(result.materials[0], other.materials[0])
            if diff:
                misses.append(("same_as", entry["same_as"], "; ".join(diff)))
    return Outcome(text, category, True, [], warnings, misses)


def differences(a: Mapping[str, Any], b: Mapping[str, Any], tol: float = 1e-6) -> list[str]:
    """What differs between two IR materials' model, params and maps ('params.roughness 0.3 vs 0.36')."""
    out: list[str] = []

    def walk(x: Any, y: Any, path: str) -> None:
        if isinstance(x, dict) and isinstance(y, dict):
            for k in sorted(set(x) | set(y)):
                walk(x.get(k), y.get(k), f"{path}.{k}" if path else k)
        elif isinstance(x, list) and isinstance(y, list) and len(x) == len(y):
            if any(isinstance(v, (dict, list)) for v in x):
                for i, (u, v) in enumerate(zip(x, y)):
                    walk(u, v, f"{path}[{i}]")
            elif any(not _close(u, v, tol) for u, v in zip(x, y)):
                out.append(f"{path} {_show(x)} vs {_show(y)}")
        elif not _close(x, y, tol):
            out.append(f"{path} {_show(x)} vs {_show(y)}")

    for key in ("model", "params", "maps"):
        walk(a.get(key), b.get(key), key)
    return out


def _close(x: Any, y: Any, tol: float) -> bool:
    if isinstance(x, (int, float)) and isinstance(y, (int, float)) and not isinstance(x, bool):
        return abs(x - y) <= tol
    return bool(x == y)


def _show(v: Any) -> str:
    if isinstance(v, float):
        return f"{v:.4g}"
    if isinstance(v, list):
        return "[" + ", ".join(_show(u) for u in v) + "]"
    return json.dumps(v)


def run_refinement(seq: Mapping[str, Any]) -> list[Outcome]:
    """One outcome per step of a refinement sequence (the first line's failure fails them all)."""
    from cnlmc import api

    name = f"{seq['first']}"
    lex = lexicon(seq.get("lexicon"))
    steps = seq["steps"]
    try:
        session = api.Session(seq["first"], lex)
        first_errors = [(d.code, d.message) for d in session.result.diagnostics if d.is_error]
    except Exception as exc:
        first_errors = [("CRASH", f"{type(exc).__name__}: {exc}")]
    if first_errors or not session.result.materials:
        errs = [("first line", f"{c} {msg}") for c, msg in first_errors] or [("first line", "E003 no material")]
        return [Outcome(f"{name} | {s['line']}", "refinement", False, errs) for s in steps]
    out = []
    for step in steps:
        label = f"{name} | {step['line']}"
        before = session.material
        trial = session.trial(step["line"])
        errors = [(d.code, d.message) for d in trial.diagnostics if d.is_error]
        warnings = [(d.code, d.message) for d in trial.diagnostics if d.severity.value == "warning"]
        if errors or not trial.materials:
            out.append(Outcome(label, "refinement", False, errors or [("E003", "no material")], warnings))
            continue
        session.refine(step["line"])
        after = session.material
        misses = []
        for key, want in step["expect"].items():
            got = (
                hue_direction(before, after) if key == "hue" else direction(quantity(before, key), quantity(after, key))
            )
            if not direction_met(want, got):
                b, a = quantity(before, key), quantity(after, key)
                shown = f"{got} ({b:.3f} -> {a:.3f})" if isinstance(b, float) else got
                misses.append((key, want, shown))
        out.append(Outcome(label, "refinement", True, [], warnings, misses))
    return out


def run_all(data: Mapping[str, Any]) -> list[Outcome]:
    bands = data["bands"]
    outcomes = [run_phrase(e, bands) for e in data["phrase"]]
    for seq in data.get("refinement", []):
        outcomes += run_refinement(seq)
    return outcomes


def pct(n: int, d: int) -> str:
    return f"{100 * n / d:5.1f}" if d else "    -"


def table(outcomes: Sequence[Outcome]) -> str:
    cats: dict[str, list[Outcome]] = defaultdict(list)
    for o in outcomes:
        cats[o.category].append(o)
    rows = [f"{'category':<14} {'n':>4} {'accepted%':>9} {'plausible%':>10} {'clean%':>7}"]
    for name in [*sorted(c for c in cats if c != "refinement"), *(["refinement"] if "refinement" in cats else [])]:
        os_ = cats[name]
        rows.append(row(name, os_))
    phrases = [o for o in outcomes if o.category != "refinement"]
    rows.append(row("ALL phrases", phrases))
    return "\n".join(rows)


def row(name: str, os_: Sequence[Outcome]) -> str:
    n = len(os_)
    acc = sum(o.accepted for o in os_)
    pl = sum(o.plausible for o in os_)
    clean = sum(o.accepted and not o.warnings for o in os_)
    return f"{name:<14} {n:>4} {pct(acc, n):>9} {pct(pl, n):>10} {pct(clean, n):>7}"


def reasons(outcomes: Sequence[Outcome]) -> dict[str, list[str]]:
    """Failure reason -> the phrases (with detail) that fail for it; one phrase may have several."""
    groups: dict[str, list[str]] = defaultdict(list)
    for o in outcomes:
        if not o.accepted:
            code, msg = o.errors[0]
            hint = f"  [{'; '.join(o.hints)}]" if o.hints else "  [no hint]"
            groups[f"rejected {code}: {message_template(msg)}"].append(f"{o.text!r}: {msg}{hint}")
        for key, want, got in o.misses:
            groups[f"expectation {key} = {want}"].append(f"{o.text!r}: got {got}")
    return dict(sorted(groups.items(), key=lambda kv: (-len(kv[1]), kv[0])))


def main(argv: Sequence[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--set", type=Path, default=SET_PATH)
    ap.add_argument("--summary", action="store_true", help="the table only")
    ap.add_argument("--json", type=Path, help="write every outcome as JSON")
    ap.add_argument("--category", help="only this category")
    args = ap.parse_args(argv)
    t0 = time.perf_counter()
    data = load_set(args.set)
    if args.category:
        data = {
            **data,
            "phrase": [e for e in data["phrase"] if e["category"] == args.category],
            "refinement": data.get("refinement", []) if args.category == "refinement" else [],
        }
    outcomes = run_all(data)
    seconds = time.perf_counter() - t0
    print(table(outcomes))
    print(f"({len(outcomes)} items in {seconds:.1f} s)")
    warned = Counter(code for o in outcomes for code, _ in o.warnings)
    print("warnings on accepted phrases:", ", ".join(f"{c}×{n}" for c, n in warned.most_common()) or "none")
    rejected = [o for o in outcomes if not o.accepted and o.category != "refinement"]
    hinted = sum(any("did you mean" in h for h in o.hints) for o in rejected)
    print(
        f"rejected phrases: {len(rejected)}, with a 'did you mean': {hinted}, with no hint at all: {sum(not o.hints for o in rejected)}"
    )
    if not args.summary:
        print("\nFailures by reason (count: reason, then the phrases):")
        for reason, items in reasons(outcomes).items():
            print(f"\n{len(items):4d}  {reason}")
            for item in items:
                print(f"        {item}")
    if args.json:
        args.json.write_text(
            json.dumps([o.__dict__ | {"plausible": o.plausible} for o in outcomes], indent=1, ensure_ascii=False)
        )
    return 0


if __name__ == "__main__":
    sys.exit(main())
