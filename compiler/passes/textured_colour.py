"""A colour word on a material whose colour is a procedural pattern tints the pattern's palette and
keeps its variation (issue #14: "black granite keeps its speckles"; #15 item 3: "colour words wipe
textures", "red brick is fire-engine red over mortar").

The stdlib graphs multiply their palette by the material's base colour (granite, marble, wood,
brick, leather: `blend … mode = "multiply"` with the base_color input) and keep their other
features in their own colours (brick's mortar). So the named colour is made one the pattern can
carry, in OKLab:

* its lightness is held inside the lexicon's band `textured_colour_min_lightness` ..
  `textured_colour_max_lightness` (settings.toml), narrowed by the graph's `palette.lightness`, so
  black granite is a near-black stone whose crystals still show, white marble a white whose veins
  still show;
* its chroma is capped at the graph's `palette.max_chroma` (stdlib/graphs/NAME.toml), so 'red
  brick' is a brick red, not a paint red, and its hue is kept, except on a graph whose own colours
  lie in a `palette.hue_range` (fired clay: the iron oxides' reds to buffs): a hue within
  `palette.hue_reach` degrees of the range moves to its nearer end, one further away is kept as a
  tint of at most `palette.off_hue_max_chroma` ('blue brick' a blue-grey engineering brick);
* a colour darker than `palette.dark_below` sets the graph parameters `palette.dark_params` that a
  clause has not set: the white calcite veins of a black marble, the pale flecks of a black granite.

A colour word that names a coating (a paint, a lacquer) colours the coat, not the pattern: this pass
sees only the base colour. `cnlmc explain` shows each step (provenance), not a diagnostic.
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from typing import Any, NamedTuple

from .. import ast
from ..colour import darkened_yellow, linear_to_oklab, oklab_to_linear_in_gamut
from ..graphs import graph_palette
from ..lexicon import LexiconCaches
from ..state import Context, MaterialState

__all__ = ["keep_pattern_visible"]

DEFAULT_BAND = (0.0, 1.0)  # a lexicon without the setting leaves colours as named
ACHROMATIC = 1e-3  # OKLab chroma below which a colour has no hue to move (white, black, a grey)


def keep_pattern_visible(
    state: MaterialState, ctx: Context, rgb: list[float], words: Sequence[ast.Word], noun_text: str
) -> list[float]:
    """`rgb` as the pattern's palette can carry it when the base colour feeds a pattern map."""
    ref = state.maps.get("base_color")
    if ref is None:
        return rgb
    graph = str(ref.get("graph", ""))
    palette = graph_palette(graph)
    carried = _carried_colour(ctx, rgb, graph, palette)
    _set_dark_params(state, graph, palette, carried.was, words, noun_text)
    if carried.colour is None:
        return rgb
    rgb = list(carried.colour)
    state.note("base_color", rgb, _rule(words, carried, noun_text), tuple(words))
    return rgb


class Carried(NamedTuple):
    """What the pattern does to a named colour: OKLab lightness before and held, chroma and its
    factor, the OKLCh hue it was moved to (None: kept), the colour (None: `rgb` as it is)."""

    was: float
    held: float
    chroma: float
    factor: float
    hue: float | None
    colour: tuple[float, ...] | None


def _carried_colour(ctx: Context, rgb: list[float], graph: str, palette: Mapping[str, Any]) -> Carried:
    """The OKLab lightness of `rgb`, the lightness held in the band, its chroma, the chroma factor and
    the colour the pattern carries (None: `rgb` as it is); made once per lexicon, colour and graph."""
    key = tuple(rgb)
    if 0.0 in key:  # -0.0 == 0.0 as a key, but its sign may reach the numbers
        key += tuple([math.copysign(1.0, v) for v in key])
    memo = ctx.lexicon.caches.pattern_colours
    found: Carried | None = memo.get((key, graph))
    if found is None:
        if len(memo) >= LexiconCaches.MAX_ENTRIES:
            memo.clear()
        found = memo[key, graph] = _carry(ctx, rgb, palette)
    return found


def _carry(ctx: Context, rgb: list[float], palette: Mapping[str, Any]) -> Carried:
    low, high = _lightness_band(ctx.settings, palette)
    lab = linear_to_oklab(rgb)
    held = _held_lightness(lab[0], low, high, palette)
    chroma = math.hypot(lab[1], lab[2])
    a, b, cap = _in_hue_range(lab[1], lab[2], palette)
    factor = cap / chroma if chroma > cap else 1.0
    hue = None if (a, b) == (lab[1], lab[2]) else math.degrees(math.atan2(b, a)) % 360.0
    if abs(held - lab[0]) < 1e-6 and factor == 1.0 and hue is None:
        return Carried(lab[0], held, chroma, factor, hue, None)
    a, b = darkened_yellow(lab[0], held, a * factor, b * factor)
    return Carried(lab[0], held, chroma, factor, hue, tuple(oklab_to_linear_in_gamut([held, a, b])))


def _in_hue_range(a: float, b: float, palette: Mapping[str, Any]) -> tuple[float, float, float]:
    """OKLab a, b with the hue moved into the palette's `hue_range` when it lies within `hue_reach`
    degrees of it, and the chroma cap: `max_chroma` in (or moved into) the range, `off_hue_max_chroma`
    beyond the reach; a graph without a range keeps every hue under `max_chroma`."""
    cap = float(palette.get("max_chroma", math.inf))
    if "hue_range" not in palette or math.hypot(a, b) < ACHROMATIC:
        return a, b, cap
    start, end = (float(h) for h in palette["hue_range"])
    hue = math.degrees(math.atan2(b, a)) % 360.0
    before, after = (start - hue) % 360.0, (hue - end) % 360.0
    if (hue - start) % 360.0 <= (end - start) % 360.0:
        return a, b, cap
    nearer, distance = (start, before) if before <= after else (end, after)
    if distance > float(palette.get("hue_reach", 0.0)):
        return a, b, min(cap, float(palette.get("off_hue_max_chroma", cap)))
    chroma, turned = math.hypot(a, b), math.radians(nearer)
    return chroma * math.cos(turned), chroma * math.sin(turned), cap


def _held_lightness(lightness: float, low: float, high: float, palette: Mapping[str, Any]) -> float:
    """The named colour's OKLab lightness inside the band: clamped, or, for a graph whose palette
    has a `lightness_curve` (a material whose own colours span the band, fired clay), placed in it
    as the named colour stands among colours: low + (high - low) * L^curve (white: the band's top,
    black: its bottom)."""
    curve = palette.get("lightness_curve")
    if curve is None:
        return min(max(lightness, low), high)
    return float(low + (high - low) * min(max(lightness, 0.0), 1.0) ** float(curve))


def _lightness_band(settings: Mapping[str, Any], palette: Mapping[str, Any]) -> tuple[float, float]:
    """The lexicon's band narrowed by the graph's own lightness range."""
    low = float(settings.get("textured_colour_min_lightness", DEFAULT_BAND[0]))
    high = float(settings.get("textured_colour_max_lightness", DEFAULT_BAND[1]))
    graph_low, graph_high = palette.get("lightness", DEFAULT_BAND)
    return max(low, float(graph_low)), min(high, float(graph_high))


def _set_dark_params(
    state: MaterialState,
    graph: str,
    palette: Mapping[str, Any],
    lightness: float,
    words: Sequence[ast.Word],
    noun_text: str,
) -> None:
    """A named colour darker than `palette.dark_below`: the graph's `dark_params` on every map of
    that graph (a value a clause set stays)."""
    settings = palette.get("dark_params") or {}
    if not settings or lightness >= float(palette.get("dark_below", 0.0)):
        return
    for role, ref in state.maps.items():
        if ref.get("graph") != graph:
            continue
        params = ref.setdefault("params", {})
        for name, value in settings.items():
            params.setdefault(name, float(value))
        text = " ".join(w.text for w in words)
        rule = f"stdlib/graphs/{graph}.toml palette.dark_params: '{text}' on {noun_text} keeps its light features"
        state.note(f"maps.{role}", dict(params), rule, tuple(words))


def _rule(words: Sequence[ast.Word], carried: Carried, noun_text: str) -> str:
    """The provenance rule `cnlmc explain` shows (a quiet adjustment, not a diagnostic)."""
    text = " ".join(w.text for w in words)
    parts = []
    if abs(carried.held - carried.was) >= 1e-6:
        direction = "raised" if carried.held > carried.was else "lowered"
        parts.append(f"OKLab lightness {direction} to {carried.held:.2f} (from {carried.was:.2f})")
    if carried.hue is not None:
        parts.append(f"hue {carried.hue:.0f} (the pattern's own hues)")
    if carried.factor < 1.0:
        parts.append(f"chroma {carried.chroma * carried.factor:.2f} (from {carried.chroma:.2f})")
    return (
        f"settings.textured_colour_*_lightness and the pattern's palette: '{text}' on {noun_text}'s pattern, "
        f"{' and '.join(parts)} so the pattern stays visible"
    )
