"""The images a GLSL library samples, written beside the shaders: the maps (option maps=bake, the
default) as `textures/<first material>.glsl/<material>_<role>.png`, colour sRGB-encoded (upload as
GL_SRGB8), data raw; and a translucent body's pre-integrated table (`<material>_subsurface_lut.png`,
16-bit; with maps=none no image at all: the library then holds the table as a const array, emit.py
lut_constant). The sidecar names each sampler's file."""

from __future__ import annotations

from cnlmc.interrupts import SignalGuard
from cnlmc.material import Material
from cnlmc.output import texture_folder
from cnlmc.scratch import scratch_folder

from ..base import Artifact, Options
from ..exchange.textures import bake_textures
from ..maps.writer import image_library, write_maps
from .plan import LUT_SAMPLER, SHADER_ROLES, has_body


def bake_sampled_maps(material: Material, options: Options, main: str) -> tuple[dict[str, str], list[Artifact]]:
    """role -> file (relative to the output folder) and the image artifacts, for the roles the
    shader samples (nothing with maps=none) and the body term's table."""
    textures, images = bake_textures(material, material.name, options, roles=SHADER_ROLES, main=main)
    files = {role: texture.path for role, texture in textures.items()}
    table_files, tables = body_table_image(material, options, main)
    return {**files, **table_files}, [*images, *tables]


def body_table_image(material: Material, options: Options, main: str) -> tuple[dict[str, str], list[Artifact]]:
    """The pre-integrated table cnlm_sss_lut of a translucent body as a one-channel 16-bit PNG
    (value = sample / 65535, row 0 at the top: cos(theta) = -1), written by the maps' own writer."""
    if not has_body(material) or options.maps == "none":  # maps=none: the library holds it as a const array
        return {}, []
    from ..preview.subsurface import lut_image

    role = LUT_SAMPLER[1]
    folder = texture_folder(options.output, main)
    image_library()  # before the signal guard (maps.writer.image_library)
    with SignalGuard(), scratch_folder("maps") as tmp:
        [path] = write_maps({role: lut_image()}, tmp, "png16", stem=material.name)
        name = f"{folder}/{path.name}"
        return {role: name}, [Artifact(name, path.read_bytes(), "binary")]
