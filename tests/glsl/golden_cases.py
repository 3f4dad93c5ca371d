"""The golden cases: one phrase per material kind, with the options they are emitted with
(rewrite the files with pytest --update-goldens tests/glsl, then review the diff)."""

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


def golden_files(stem: str, emitted: dict[str, str]) -> dict[str, str]:
    """{golden file name: text} kept for one case: every emitted file, the vertex shader only
    once (it is the same for every material but its name)."""
    return {f"{stem}.{suffix}": text for suffix, text in emitted.items() if suffix != "vert" or stem == "dielectric"}
