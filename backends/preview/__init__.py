"""The 'preview' target: offscreen moderngl (EGL) renders of the GLSL backend's BSDF on a
preview mesh under a key light and an HDR environment (docs/preview.md).

    TARGET.emit(document, options) -> EmitResult  (one PNG per material, plus sheet.png for 'or' variants)
    preview_command(ir, out_path, options) -> PreviewReport     (`cnlmc preview`: commands.py)
    render_ir(ir, options) -> [(material, Frame)]
    with Renderer(512) as r: r.render(material, tier="splitsum")  (render.py)

Options: declared in options.OPTIONS (size, mesh, tier, budget_ms, env, background, exposure,
msaa, and the GLSL backend's fresnel and multiscatter), parsed once with did-you-mean.

Modules by job: render (the Renderer facade), resources (what a renderer owns: its GL context and
every cached object), shader (the GLSL backend's library and plan for a material), object_pass,
environment_pass, tonemap, targets, material_textures, scene; albedo_tables (split-sum tables),
tiers; mesh (the mesh type), meshes, mesh_io, gltf; environment, camera; options, frames,
target, commands, live and window (`cnlmc preview --interactive`), sheet, mitsuba_scene.
"""

from __future__ import annotations

from .frames import PreviewReport, compose, preview_command, render_ir
from .options import OPTIONS, PreviewOptionError, PreviewOptions, choose_tier, parse_options
from .target import CAPABILITIES, DESCRIPTION, NAME, TARGET, PreviewTarget, emit

__all__ = [
    "CAPABILITIES",
    "DESCRIPTION",
    "NAME",
    "OPTIONS",
    "TARGET",
    "PreviewOptionError",
    "PreviewOptions",
    "PreviewReport",
    "PreviewTarget",
    "choose_tier",
    "compose",
    "emit",
    "parse_options",
    "preview_command",
    "render_ir",
]
