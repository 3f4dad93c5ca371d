"""Baked maps as image files an exchange document references: role, relative path, encoding."""

from __future__ import annotations

import tempfile
from dataclasses import dataclass

from ..registry import Artifact

COLOUR_ROLES = ("base_color",)


@dataclass(frozen=True)
class Texture:
    """One baked image: its role, its path relative to the output folder, how it is encoded."""

    role: str
    path: str
    encoding: str  # "srgb" (8/16-bit PNG colour), "linear" (EXR colour) or "raw" (data)

    @property
    def is_colour(self) -> bool:
        return self.encoding in ("srgb", "linear")


def texture_encoding(role: str, fmt: str) -> str:
    if role in COLOUR_ROLES:
        return "srgb" if fmt.startswith("png") else "linear"
    return "raw"


def bake_textures(
    material: dict, ident: str, opts: dict, folder: str = "textures", roles=None, derive=None
) -> tuple[dict[str, Texture], list[Artifact]]:
    """Bake the material's maps (the roles given, default all) into image Artifacts.

    `derive(arrays) -> arrays` may add roles computed from the baked ones (e.g. Mitsuba's
    alpha = roughness^2). Returns role -> Texture and the artifacts (bytes) to write.
    """
    refs = {r: ref for r, ref in (material.get("maps") or {}).items() if roles is None or r in roles}
    if opts["maps"] == "none" or not refs:
        return {}, []
    from cnlmc.backends.maps import MapError, bake, write_maps

    try:
        arrays = bake(refs, material["params"], opts["map_size"], opts["seed"])
        if derive:
            arrays = derive(arrays)
        with tempfile.TemporaryDirectory(prefix="cnlmc-tex-") as tmp:
            paths = write_maps(arrays, tmp, fmt=opts["map_format"], stem=ident)
            files = {p.stem[len(ident) + 1 :]: (p.name, p.read_bytes()) for p in paths}
    except MapError as exc:
        raise ValueError(f"{material['name']}: cannot bake maps: {exc}") from None
    textures, artifacts = {}, []
    for role, (name, data) in files.items():
        rel = f"{folder}/{name}"
        textures[role] = Texture(role, rel, texture_encoding(role, opts["map_format"]))
        artifacts.append(Artifact(rel, data, "binary"))
    return textures, artifacts
