"""The preview as a target (the backend contract, cnlmc.backends.base): capabilities, declared
options, the `cnlmc preview` command, and emit: one PNG per material."""

from __future__ import annotations

from collections.abc import Mapping

from cnlmc.material import Document

from ..base import Artifact, OptionError, Options, Target
from ..capabilities import EmitResult, check_material
from .commands import PreviewCommand
from .frames import IR, compose, render_materials
from .options import OPTIONS, PreviewOptionError, preview_options
from .render import Renderer
from .sheet import png_bytes

NAME = "preview"
DESCRIPTION = "PNG previews rendered with OpenGL (moderngl/EGL) from the GLSL backend's BSDF (docs/preview.md)"
_BAKED = "procedural map baked with cnlmc.backends.maps and bound as a texture"
CAPABILITIES = {
    "model.diffuse": ("exact", ""),
    "model.dielectric": ("exact", ""),
    "model.conductor": ("exact", ""),
    "model.glass": ("approximate", "reflection only (the GLSL backend renders no transmission)"),
    "distribution.ggx": ("exact", ""),
    "distribution.ward": ("exact", ""),
    "anisotropic": ("exact", "exact in the key light and the mc/fis tiers; split-sum uses sqrt(ax ay)"),
    "diffuse.oren_nayar": ("exact", "exact in the key light and the mc/fis tiers; split-sum uses Lambert"),
    "coat": ("exact", ""),
    "coat.color": ("exact", ""),
    "maps.base_color": ("bake", _BAKED),
    "maps.normal": ("bake", _BAKED),
    "maps.roughness": ("bake", _BAKED),
    "maps.mask": ("bake", _BAKED),
    "maps.metallic": ("drop", "no IR model reads a metallic map"),
}


class PreviewTarget(Target):
    """The preview as a target: one PNG per material, plus sheet.png when there are variants."""

    name = NAME
    description = DESCRIPTION
    capabilities = CAPABILITIES
    options = OPTIONS
    commands = (PreviewCommand,)

    def emit(self, document: Document, options: Options) -> EmitResult:
        opts = preview_options(options)
        notes: list = []
        for material in document.materials:
            check_material(notes, NAME, CAPABILITIES, material)
        with Renderer(opts.size, msaa=opts.msaa) as renderer:
            frames = render_materials(renderer, document, opts)
        artifacts = [Artifact(f"{m.name}.png", png_bytes(f.rgba), "binary") for m, f in frames]
        if any(m.variant for m, _ in frames):
            artifacts.append(Artifact("sheet.png", png_bytes(compose(frames)), "binary"))
        return EmitResult(artifacts, notes)


TARGET = PreviewTarget()


def emit(ir: IR, options: Mapping[str, object] | None = None) -> EmitResult:
    """The target on an IR (typed or JSON form) with raw `--option` pairs."""
    try:
        return TARGET.emit_ir(ir, options)
    except OptionError as exc:
        raise PreviewOptionError(str(exc)) from None
