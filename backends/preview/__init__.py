"""The 'preview' target: offscreen moderngl (EGL) renders of the GLSL backend's BSDF on a
preview mesh under a key light and an HDR environment (docs/preview.md).

    preview_command(ir, out_path, options) -> PreviewReport     (for the CLI)
    render_ir(ir, options) -> [(material, Frame)]
    emit(ir, options) -> EmitResult  (one PNG per material, plus sheet.png for 'or' variants)

Options (strings, as from `--option key=value`): size (512), mesh (sphere | shader_ball |
teapot | path to .obj/.ply/.gltf/.glb), tier (see tiers.TIERS; default splitsum), budget_ms (pick the best
tier that fits), env (studio | sky | sun | path to .hdr/.exr), background (env | transparent),
exposure (1.0), msaa (0: off, an edge filter in the tone map; 2 or 4 cost 3-4x the frame on llvmpipe), fresnel / multiscatter (the GLSL backend's options), seed.
"""

from __future__ import annotations

from .options import OPTIONS, PreviewOptionError, PreviewOptions, choose_tier, parse_options
from .target import CAPABILITIES, DESCRIPTION, NAME, PreviewReport, compose, emit, preview_command, render_ir

__all__ = [
    "NAME",
    "DESCRIPTION",
    "CAPABILITIES",
    "OPTIONS",
    "emit",
    "preview_command",
    "render_ir",
    "compose",
    "choose_tier",
    "parse_options",
    "PreviewOptions",
    "PreviewOptionError",
    "PreviewReport",
]
