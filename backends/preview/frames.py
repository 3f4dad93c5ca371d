"""The IR's materials rendered (one Renderer for them all) into frames, composed into one image
(a sheet when there are several), written as a PNG: what the target and the CLI share."""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

from cnlmc.material import Document, Material
from cnlmc.output import destination, write_atomic

from ..base import as_document
from .options import PreviewOptions, choose_tier, parse_options
from .render import Frame, Renderer
from .resources import Resources
from .scene import Scene
from .sheet import groups_of, label, png_bytes, sheet

Rendered = list[tuple[Material, Frame]]
IR = Document | Mapping[str, Any]  # the typed document, or its JSON form


def render_ir(ir: IR, options: Mapping[str, object] | None = None, resources: Resources | None = None) -> Rendered:
    """Render every material of the IR: [(material, Frame)]. With `resources` what is made is
    kept there; without, it is released at the end."""
    opts = parse_options(options)
    with Renderer(opts.size, msaa=opts.msaa, resources=resources) as renderer:
        return render_materials(renderer, as_document(ir), opts)


def render_materials(renderer: Renderer, document: Document, opts: PreviewOptions) -> Rendered:
    """Every material of the document, in the scene the options describe."""
    scene = preview_scene(renderer, opts)
    return [(material, render_material(renderer, scene, material, opts)) for material in document.materials]


def preview_scene(renderer: Renderer, opts: PreviewOptions) -> Scene:
    """The scene the options describe (mesh, environment, background, exposure)."""
    scene = renderer.scene(opts.mesh, opts.env)
    scene.background, scene.exposure, scene.glass = opts.background, opts.exposure, opts.glass
    return scene


def render_material(renderer: Renderer, scene: Scene, material: Material, opts: PreviewOptions) -> Frame:
    """One material in the scene, at the options' tier (or the best one within the time budget)."""
    tier, timings = choose_tier(renderer, scene, material, opts)
    frame = renderer.render(material, tier=tier, glsl_options=opts.glsl, scene=scene)
    if timings:
        frame.notes.append(
            f"preview: budget {opts.budget_ms:.1f} ms: measured "
            f"{', '.join(f'{k} {v:.1f}' for k, v in timings.items())} -> {tier.name}"
        )
    return frame


def compose(frames: Rendered) -> np.ndarray:
    """One image: a single material as is; several as a labelled sheet, one row per variant group."""
    if len(frames) == 1:
        return frames[0][1].rgba
    by_name = {m.name: f for m, f in frames}
    rows = []
    for group in groups_of([m for m, _ in frames]):
        rows.append([label(by_name[m.name].rgba, (m.variant.name if m.variant else "") or m.name) for m in group])
    if all(len(r) == 1 for r in rows):  # no variants: one row of everything
        rows = [[r[0] for r in rows]]
    return sheet(rows)


@dataclass
class PreviewReport:
    path: Path
    frames: list
    notes: list


def preview_command(
    ir: IR,
    out_path: str | Path,
    options: Mapping[str, object] | None = None,
    resources: Resources | None = None,
    protect: Sequence[str | Path] = (),
) -> PreviewReport:
    """Render the IR and write one PNG to `out_path` (a sheet when there are several materials);
    `resources` as for render_ir; `protect`: the input files, never overwritten (cnlmc.output).

    Raises PreviewOptionError (usage error), MeshError / EnvironmentError (bad input file),
    PreviewUnavailable (no OpenGL here)."""
    out_path = Path(out_path)
    destination(out_path, protect)  # refused before the render, not after it
    frames = render_ir(ir, options, resources)
    write_atomic(out_path, png_bytes(compose(frames)), protect)
    notes = [n for _, f in frames for n in f.notes]
    return PreviewReport(out_path, frames, notes)
