"""The flakes a word gives a paint or plastic, in the IR (docs/bsdf.md, "Flakes").

Words that ask for flakes ('metallic', 'pearlescent', 'glittery', 'with metallic flakes': the
lexicon, stdlib/lexicon/adjectives_flakes.toml) set `flake_color` and the flakes' density, spread
and size as effects. The IR carries the four only when the flakes are there: a colour and a
density above zero; a material without such a word has none of them (its IR is unchanged).

The flakes sit in the pigmented basecoat, so the light they mirror passes through the pigment:
the IR's flake colour is the lexicon's (a bare aluminium flake's F0) tinted by the base colour's
chromaticity, flake = lexicon flake ⊙ base / max(base) (our choice: the hue of the pigment, not
its darkness — a transparent pigment of a metallic red tints the flakes red; the grey 0.1 of plain
'car paint' leaves them silver). Looked at: untinted flakes made 'red paint with metallic flakes'
a pale pink.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

from .formulas import round6_list, rounded
from .params import Params

FLAKE_PARAMS = ("flake_color", "flake_density", "flake_roughness", "flake_size")
#: a working flag (never in the IR): the flake colour was named ('with gold flakes', 'gold flecks'),
#: flakes of that metal or colour laid in the finish, seen as named rather than through the pigment
OWN_FLAKE_COLOUR = "flake_color_named"


def has_flakes(params: Mapping[str, Any]) -> bool:
    """Whether working params carry visible flakes."""
    color = params.get("flake_color")
    return color is not None and max(color) > 0.0 and float(params.get("flake_density", 0.0)) > 0.0


def tinted_flakes(flake_color: list[float], base_color: list[float]) -> list[float]:
    """The flakes' colour seen through a pigment of `base_color` (its chromaticity)."""
    top = max(base_color)
    if top <= 0.0:
        return list(flake_color)
    return [f * max(c, 0.0) / top for f, c in zip(flake_color, base_color, strict=True)]


def flake_params(params: Mapping[str, Any]) -> dict[str, Any]:
    """The IR's flake entries for a material's working params: none without flakes."""
    if not has_flakes(params):
        return {}
    own = params.get(OWN_FLAKE_COLOUR, False)  # 'gold flecks': named flakes are not under the pigment
    colour = (
        list(params["flake_color"]) if own else tinted_flakes(list(params["flake_color"]), list(params["base_color"]))
    )
    return {
        "flake_color": round6_list(colour),
        "flake_density": rounded(params["flake_density"]),
        "flake_roughness": rounded(params.get("flake_roughness", Params.flake_roughness)),
        "flake_size": rounded(params.get("flake_size", Params.flake_size)),
    }
