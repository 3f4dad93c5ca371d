"""The preview as a target (the backend contract, cnlmc.backends.base): capabilities, declared
options, the `cnlmc preview` command, and emit: one PNG per material."""

from __future__ import annotations

from collections.abc import Mapping

from cnlmc.material import Document, Material

from ..base import Artifact, OptionError, Options, Target, emit_each
from ..capabilities import EmitResult
from .capability_table import CAPABILITIES
from .commands import PreviewCommand
from .frames import IR, Rendered, compose, preview_scene, render_material
from .options import OPTIONS, PreviewOptionError, preview_options
from .render import Renderer
from .sheet import png_bytes

NAME = "preview"
DESCRIPTION = "PNG previews rendered with OpenGL (moderngl/EGL) from the GLSL backend's BSDF (docs/preview.md)"


class PreviewTarget(Target):
    """The preview as a target: one PNG per material, plus sheet.png when there are variants."""

    name = NAME
    description = DESCRIPTION
    capabilities = CAPABILITIES
    options = OPTIONS
    commands = (PreviewCommand,)

    def emit(self, document: Document, options: Options) -> EmitResult:
        opts = preview_options(options)
        if not document.materials:  # as `cnlmc preview` says it, before a GL context is made
            raise ValueError("preview: the document has no material to render")
        frames: Rendered = []
        with Renderer(opts.size, msaa=opts.msaa) as renderer:
            scene = preview_scene(renderer, opts)

            def one_png(material: Material) -> list[Artifact]:
                frame = render_material(renderer, scene, material, opts)
                frames.append((material, frame))
                return [Artifact(f"{material.name}.png", png_bytes(frame.rgba), "binary")]

            result = emit_each(self, document, one_png)
        if any(m.variant for m, _ in frames):
            result.artifacts.append(Artifact("sheet.png", png_bytes(compose(frames)), "binary"))
        return result


TARGET = PreviewTarget()


def emit(ir: IR, options: Mapping[str, object] | None = None) -> EmitResult:
    """The target on an IR (typed or JSON form) with raw `--option` pairs."""
    try:
        return TARGET.emit_ir(ir, options)
    except OptionError as exc:
        raise PreviewOptionError(str(exc)) from None
