"""Baked maps as image files an exchange document references: role, relative path, encoding.

The images come from the one map-baking service (cnlmc.backends.maps.service)."""

from __future__ import annotations

from collections.abc import Collection
from dataclasses import dataclass
from pathlib import PurePosixPath

from cnlmc.material import Material

from ..base import Artifact, Options
from ..maps.service import Derive, bake_artifacts

COLOUR_ROLES = ("base_color",)
FOLDER = "textures"


@dataclass(frozen=True)
class Texture:
    """One baked image: its role, its path relative to the output folder, how it is encoded."""

    role: str
    path: str
    encoding: str  # "srgb" (8/16-bit PNG colour), "linear" (EXR colour) or "raw" (data)

    @property
    def is_colour(self) -> bool:
        return self.encoding in ("srgb", "linear")


Textures = dict[str, Texture]


def texture_encoding(role: str, fmt: str) -> str:
    if role in COLOUR_ROLES:
        return "srgb" if fmt.startswith("png") else "linear"
    return "raw"


def bake_textures(
    material: Material,
    ident: str,
    options: Options,
    roles: Collection[str] | None = None,
    derive: Derive | None = None,
) -> tuple[Textures, list[Artifact]]:
    """Bake the material's maps (the roles given, default all) into image Artifacts under textures/.

    `derive(arrays) -> arrays` may add roles computed from the baked ones (e.g. Mitsuba's
    alpha = roughness^2). Returns role -> Texture and the artifacts (bytes) to write.
    """
    if options.maps == "none" or not any(roles is None or role in roles for role in material.maps):
        return {}, []
    artifacts = bake_artifacts(
        material, options.map_size, options.map_format, options.seed, ident, FOLDER, roles, derive
    )
    textures = {}
    for artifact in artifacts:
        role = PurePosixPath(artifact.name).stem[len(ident) + 1 :]
        textures[role] = Texture(role, artifact.name, texture_encoding(role, options.map_format))
    return textures, artifacts
