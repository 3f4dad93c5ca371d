"""The flakes a word gives a paint or plastic, in the IR (docs/bsdf.md, "Flakes").

Words that ask for flakes ('metallic', 'pearlescent', 'glittery', 'with metallic flakes': the
lexicon, stdlib/lexicon/adjectives_flakes.toml) set `flake_color` and the flakes' density, spread
and size as effects. The IR carries the four only when the flakes are there: a colour and a
density above zero; a material without such a word has none of them (its IR is unchanged).
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

from .formulas import round6_list, rounded
from .params import Params

FLAKE_PARAMS = ("flake_color", "flake_density", "flake_roughness", "flake_size")


def has_flakes(params: Mapping[str, Any]) -> bool:
    """Whether working params carry visible flakes."""
    color = params.get("flake_color")
    return color is not None and max(color) > 0.0 and float(params.get("flake_density", 0.0)) > 0.0


def flake_params(params: Mapping[str, Any]) -> dict[str, Any]:
    """The IR's flake entries for a material's working params: none without flakes."""
    if not has_flakes(params):
        return {}
    return {
        "flake_color": round6_list(list(params["flake_color"])),
        "flake_density": rounded(params["flake_density"]),
        "flake_roughness": rounded(params.get("flake_roughness", Params.flake_roughness)),
        "flake_size": rounded(params.get("flake_size", Params.flake_size)),
    }
