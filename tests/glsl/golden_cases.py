"""The golden cases: one phrase per material kind, with the options they are emitted with."""

from __future__ import annotations

from pathlib import Path

GOLDEN_DIR = Path(__file__).parent / "golden"

#: golden stem -> (phrase, options)
GOLDEN_CASES = {
    "diffuse": ("velvet", {}),
    "dielectric": ("glossy red plastic", {}),
    "dielectric_coat": ("red varnished oak", {}),
    "conductor": ("polished gold", {"fresnel": "f82"}),
    "conductor_anisotropic": ("lightly brushed, blue anodized aluminum", {}),
    "conductor_multiscatter": ("steel", {"multiscatter": "on"}),
    "glass": ("frosted glass", {"profile": "es300"}),
    "maps": ("rusty iron", {}),
}
