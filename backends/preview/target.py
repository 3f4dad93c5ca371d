"""The preview as a target: the IR's materials rendered (one Renderer for them all), written as
PNGs, or composed into one image for the CLI."""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

from cnlmc.output import write_atomic

from ..base import Artifact
from ..capabilities import EmitResult, check_material
from .options import PreviewOptions, choose_tier, parse_options
from .render import Renderer
from .sheet import groups_of, label, png_bytes, sheet

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


def render_ir(ir: dict, options: dict | None = None, resources=None) -> list[tuple[dict, object]]:
    """Render every material of the IR: [(material, Frame)]. With `resources` (a
    resources.Resources) what is made is kept there; without, it is released at the end."""
    opts = parse_options(options)
    with Renderer(opts.size, msaa=opts.msaa, resources=resources) as renderer:
        return _render_materials(renderer, ir, opts)


def _render_materials(renderer, ir: dict, opts: PreviewOptions) -> list[tuple[dict, object]]:
    scene = renderer.scene(opts.mesh, opts.env)
    scene.background, scene.exposure = opts.background, opts.exposure
    frames = []
    for material in ir["materials"]:
        tier, timings = choose_tier(renderer, scene, material, opts)
        frame = renderer.render(material, tier=tier, glsl_options=opts.glsl, scene=scene)
        if timings:
            frame.notes.append(
                f"preview: budget {opts.budget_ms:.1f} ms: measured "
                f"{', '.join(f'{k} {v:.1f}' for k, v in timings.items())} -> {tier.name}"
            )
        frames.append((material, frame))
    return frames


def compose(frames: list[tuple[dict, object]]):
    """One image: a single material as is; several as a labelled sheet, one row per variant group."""
    if len(frames) == 1:
        return frames[0][1].rgba
    by_name = {m["name"]: f for m, f in frames}
    rows = []
    for group in groups_of([m for m, _ in frames]):
        rows.append([label(by_name[m["name"]].rgba, (m.get("variant") or {}).get("name") or m["name"]) for m in group])
    if all(len(r) == 1 for r in rows):  # no variants: one row of everything
        rows = [[r[0] for r in rows]]
    return sheet(rows)


@dataclass
class PreviewReport:
    path: Path
    frames: list
    notes: list


def preview_command(ir: dict, out_path, options: dict | None = None, resources=None) -> PreviewReport:
    """Render the IR and write one PNG to `out_path` (a sheet when there are several materials);
    `resources` as for render_ir.

    Raises PreviewOptionError (usage error), MeshError / EnvironmentError (bad input file),
    PreviewUnavailable (no OpenGL here)."""
    frames = render_ir(ir, options, resources)
    out_path = Path(out_path)
    write_atomic(out_path, png_bytes(compose(frames)))
    notes = [n for _, f in frames for n in f.notes]
    return PreviewReport(out_path, frames, notes)


def emit(ir: dict, options: dict) -> EmitResult:
    notes: list = []
    for material in ir["materials"]:
        check_material(notes, NAME, CAPABILITIES, material)
    frames = render_ir(ir, options)
    artifacts = [Artifact(f"{m['name']}.png", png_bytes(f.rgba), "binary") for m, f in frames]
    if any(m.get("variant") for m, _ in frames):
        artifacts.append(Artifact("sheet.png", png_bytes(compose(frames)), "binary"))
    return EmitResult(artifacts, notes)
