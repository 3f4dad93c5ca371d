"""The maps a GLSL library samples, baked to image files beside the shaders (option maps=bake,
the default): `textures/<first material>.glsl/<material>_<role>.png`, colour sRGB-encoded (upload
as GL_SRGB8), data raw. The sidecar names each sampler's file."""

from __future__ import annotations

from cnlmc.material import Material

from ..base import Artifact, Options
from ..exchange.textures import bake_textures
from .plan import SHADER_ROLES


def bake_sampled_maps(material: Material, options: Options, main: str) -> tuple[dict[str, str], list[Artifact]]:
    """role -> file (relative to the output folder) and the image artifacts, for the roles the
    shader samples; nothing with maps=none."""
    textures, images = bake_textures(material, material.name, options, roles=SHADER_ROLES, main=main)
    return {role: texture.path for role, texture in textures.items()}, images
