"""Baked maps as image files an exchange document references: role, relative path, encoding.

The images come from the one map-baking service (cnlmc.backends.maps.service). They go into the
folder that belongs to the document's main file, `textures/<main file name>/<material>_<role>.ext`
(cnlmc.output.texture_folder: `-o out/wood.mtlx` -> `out/textures/wood.mtlx/`), so two documents
compiled into one folder never share a texture, and the writer's manifest there lets the next
compile of the same document remove the textures it no longer has. A name too long for a file is
shortened with a hash (cnlmc.filenames.fit_name)."""

from __future__ import annotations

from collections.abc import Collection
from dataclasses import dataclass

from cnlmc.material import Material
from cnlmc.output import texture_folder

from ..base import Artifact, Options
from ..maps.service import Derive, bake_images

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
    *,
    main: str,
    folder: str | None = None,
) -> tuple[Textures, list[Artifact]]:
    """Bake the material's maps (the roles given, default all) into image Artifacts in the folder of
    the document's main file (`main`: its name when -o names a folder, e.g. "materials.mtlx").

    `derive(arrays) -> arrays` may add roles computed from the baked ones (e.g. Mitsuba's
    alpha = roughness^2). `folder` replaces the main file's folder (a usdz keeps its textures
    inside the package, under a folder whose name holds no `.usdz`). Returns role -> Texture and
    the artifacts (bytes) to write.
    """
    if options.maps == "none" or not any(roles is None or role in roles for role in material.maps):
        return {}, []
    folder = texture_folder(options.output, main) if folder is None else folder
    images = bake_images(material, options.map_size, options.map_format, options.seed, ident, folder, roles, derive)
    textures = {
        role: Texture(role, image.name, texture_encoding(role, options.map_format)) for role, image in images.items()
    }
    return textures, list(images.values())
