"""'darker' / 'lighter' on a material whose colour map draws a layer of its own colours over it
(rust, patina: the graph's `[palette] shade`, stdlib/graphs/NAME.toml): the layer's colours move
with the material's, so 'rusty iron' then 'darker' darkens the rust, not only the bare metal
between its patches.

The base colour's step has a ratio r (its luminance after / before, Rec. 709 weights). The layer's
colours c are shown as c (1 − d) (1 − l) + light · l, d = `darken`, l = `lighten` (blend amounts in
[0, 1], both 0 at first). A darker step (r < 1) first takes back lightening, (1 − l) grows by 1/r
at most to 1, and puts what is left into darkening, (1 − d) × r; a lighter step first takes back
darkening, (1 − d) / r at most 1, then lightens, (1 − l) / r. The same bracket step that moved the
base colour moves the layer (docs/refinement.md); where the base colour cannot move (a metal's
tint at 1 under a lighter step), the layer takes the step a mid grey would take.
"""

from __future__ import annotations

from collections.abc import Sequence

from .. import ast
from ..colour import luminance
from ..graphs import graph_palette
from ..state import MaterialState

TINY = 1e-6


def shade_layers(
    state: MaterialState, before: Sequence[float], after: Sequence[float], words: tuple[ast.Word, ...]
) -> bool:
    """Move every colour layer's shade parameters by the base colour's step `before` -> `after`;
    whether a layer moved."""
    was, now = luminance(before), luminance(after)
    if was < TINY or abs(now - was) < TINY:
        return False
    ratio, moved = now / was, False
    for role, ref in state.maps.items():
        shade = graph_palette(str(ref.get("graph", ""))).get("shade")
        if role != "base_color" or not shade:
            continue
        params = ref.setdefault("params", {})
        dark, light = _shaded(float(params.get(shade["darken"], 0.0)), float(params.get(shade["lighten"], 0.0)), ratio)
        was_shade = (params.get(shade["darken"], 0.0), params.get(shade["lighten"], 0.0))
        params[shade["darken"]], params[shade["lighten"]] = round(dark, 6), round(light, 6)
        moved = moved or was_shade != (params[shade["darken"]], params[shade["lighten"]])
        rule = f"stdlib/graphs/{ref['graph']}.toml palette.shade: the layer's own colours step with the material's"
        state.note(f"maps.{role}", dict(params), rule, words)
    return moved


def _shaded(dark: float, light: float, ratio: float) -> tuple[float, float]:
    """The (darken, lighten) amounts after a step of luminance ratio `ratio` (see the module doc)."""
    kept_dark, kept_light = 1.0 - dark, 1.0 - light
    if ratio < 1.0:
        grown = min(1.0, kept_light / ratio)
        ratio *= grown / kept_light if kept_light > TINY else 1.0
        kept_light = grown
        kept_dark *= ratio if ratio < 1.0 else 1.0
    else:
        grown = min(1.0, kept_dark * ratio)
        ratio /= grown / kept_dark if kept_dark > TINY else 1.0
        kept_dark = grown
        kept_light /= ratio if ratio > 1.0 else 1.0
    return _unit(1.0 - kept_dark), _unit(1.0 - kept_light)


def _unit(x: float) -> float:
    return min(max(x, 0.0), 1.0)
