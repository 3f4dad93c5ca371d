"""The sheen a fibre noun (velvet, cloth) gives its material, in the IR (docs/bsdf.md, "Sheen").

The lexicon gives a noun's sheen as the colour a white fibre would scatter (`sheen_color`) and
its roughness. The fibres are dyed with the base colour, but the light the pile scatters at
grazing passes through less dye than the light the bulk returns, so the sheen is a lighter,
less saturated version of the base colour (our choice, after Filament's cloth model, whose
sheen colour defaults to sqrt(base colour)): sheen = lexicon sheen ⊙ (base / max(base))^DYE_POWER.
DYE_POWER = 0.75 rather than Filament's 0.5: with 0.5 a deep red velvet's rim looked pink
(looked at in the preview; 0.75 keeps it a lighter red).
A colour word on the noun ('navy blue velvet') thus tints the rim as it tints the body.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

from .formulas import round6_list, rounded
from .params import Params

SHEEN_PARAMS = ("sheen_color", "sheen_roughness")
DYE_POWER = 0.75


def fibre_sheen(white_sheen: list[float], base_color: list[float]) -> list[float]:
    """The sheen colour of fibres dyed `base_color` whose undyed sheen is `white_sheen`."""
    top = max(base_color)
    if top <= 0.0:
        return [0.0, 0.0, 0.0]
    return [s * (max(c, 0.0) / top) ** DYE_POWER for s, c in zip(white_sheen, base_color, strict=True)]


def sheen_params(params: Mapping[str, Any]) -> dict[str, Any]:
    """The IR's sheen entries for a material's working params: none when its noun has no sheen."""
    if params.get("sheen_color") is None:
        return {}
    return {
        "sheen_color": round6_list(fibre_sheen(list(params["sheen_color"]), list(params["base_color"]))),
        "sheen_roughness": rounded(params.get("sheen_roughness", Params.sheen_roughness)),
    }
