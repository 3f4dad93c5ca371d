"""A colour word on a material whose colour is a procedural pattern keeps the pattern (issue #14:
"black granite keeps its speckles"; #15: "colour words wipe textures").

The stdlib graphs multiply their palette by the material's base colour (granite, marble, wood,
brick, leather: `blend … mode = "multiply"` with the base_color input), so a named colour at
OKLab lightness 0 ('black') or 1 ('white') would flatten every crystal, vein or grain line into one
flat value. The named colour keeps its hue and chroma; its OKLab lightness is held inside the
lexicon's band `textured_colour_min_lightness` .. `textured_colour_max_lightness` (settings.toml), so black granite is a near-black stone
whose light crystals still show, white marble a white whose veins still show. `cnlmc explain` shows the step.
"""

from __future__ import annotations

from collections.abc import Sequence

from .. import ast
from ..colour import linear_to_oklab, oklab_to_linear_in_gamut
from ..state import Context, MaterialState

__all__ = ["keep_pattern_visible"]

DEFAULT_BAND = (0.0, 1.0)  # a lexicon without the setting leaves colours as named


def keep_pattern_visible(
    state: MaterialState, ctx: Context, rgb: list[float], words: Sequence[ast.Word], noun_text: str
) -> list[float]:
    """`rgb` with its OKLab lightness inside the band when the base colour feeds a pattern map."""
    if "base_color" not in state.maps:
        return rgb
    low = ctx.settings.get("textured_colour_min_lightness", DEFAULT_BAND[0])
    high = ctx.settings.get("textured_colour_max_lightness", DEFAULT_BAND[1])
    lab = linear_to_oklab(rgb)
    held = min(max(lab[0], low), high)
    if abs(held - lab[0]) < 1e-6:
        return rgb
    rgb = oklab_to_linear_in_gamut([held, lab[1], lab[2]])
    state.note("base_color", rgb, _rule(words, lab[0], held, noun_text), tuple(words))
    return rgb


def _rule(words: Sequence[ast.Word], was: float, held: float, noun_text: str) -> str:
    """The provenance rule `cnlmc explain` shows (a quiet adjustment, not a diagnostic)."""
    text = " ".join(w.text for w in words)
    direction = "raised" if held > was else "lowered"
    return (
        f"settings.textured_colour_*_lightness: '{text}' on {noun_text}'s pattern, OKLab lightness "
        f"{direction} to {held:.2f} (from {was:.2f}) so the pattern stays visible"
    )
