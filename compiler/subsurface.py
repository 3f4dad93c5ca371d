"""Light inside the body (docs/subsurface.md): the IR's `model.subsurface` and `params.subsurface`.

The working state keeps the medium as `state.params["subsurface"]`, a dict
{"model", "color", "radius", "anisotropy", "thickness"} (radius in metres); this module turns it
into the IR's nested object, rounded and clamped to the parameter table's ranges.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

from .formulas import round6_list, rounded
from .params import SUBSURFACE_PARAMS

#: the IR keys of params.subsurface, in IR order (the table's order)
MEDIUM_KEYS = tuple(s.name for s in SUBSURFACE_PARAMS)
RANGES = {s.name: s.range for s in SUBSURFACE_PARAMS if s.range is not None}
#: the base models a medium may sit under: a dielectric boundary (a conductor lets no light in;
#: glass is already transmissive, its interior is its transmittance tint)
HOSTS = ("diffuse", "dielectric")


def medium_of(params: Mapping[str, Any]) -> dict[str, Any] | None:
    """The working medium, or None when no word asked for one."""
    medium = params.get("subsurface")
    return medium if isinstance(medium, dict) else None


def subsurface_model(params: Mapping[str, Any]) -> str | None:
    medium = medium_of(params)
    return None if medium is None else str(medium["model"])


def _clamp(value: float, name: str) -> float:
    low, high = RANGES[name]
    return min(max(float(value), low), high)


def subsurface_ir(params: Mapping[str, Any]) -> dict[str, Any]:
    """The IR's `params.subsurface` entry for a material's working params: none when it has no medium."""
    medium = medium_of(params)
    if medium is None:
        return {}
    thin = medium["model"] == "thin"
    thickness = medium.get("thickness") if thin else None
    return {
        "subsurface": {
            "color": round6_list([_clamp(c, "color") for c in medium["color"]]),
            "radius": round6_list([_clamp(r, "radius") for r in medium["radius"]]),
            "anisotropy": rounded(_clamp(medium.get("anisotropy", 0.0), "anisotropy")),
            "thickness": None if thickness is None else rounded(_clamp(thickness, "thickness")),
        }
    }
