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

from dataclasses import dataclass, field
from pathlib import Path

from ..capabilities import EmitResult, check_material
from ..registry import Artifact

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
OPTIONS = {
    "size": "512",
    "mesh": "sphere",
    "tier": "",
    "budget_ms": "",
    "env": "studio",
    "background": "env",
    "exposure": "1.0",
    "msaa": "0",
    "fresnel": "exact",
    "multiscatter": "off",
    "seed": "0",
}


class PreviewOptionError(ValueError):
    """An unknown option or a value that cannot be used."""


@dataclass
class PreviewOptions:
    size: int = 512
    mesh: str = "sphere"
    tier: str = ""
    budget_ms: float | None = None
    env: str = "studio"
    background: str = "env"
    exposure: float = 1.0
    msaa: int = 0
    glsl: dict = field(default_factory=dict)


def parse_options(options: dict | None) -> PreviewOptions:
    from ..capabilities import COMPILER_OPTIONS

    options = {k: str(v) for k, v in (options or {}).items() if k in OPTIONS or k not in COMPILER_OPTIONS}
    unknown = sorted(set(options) - set(OPTIONS))
    if unknown:
        raise PreviewOptionError(f"preview: unknown option(s) {', '.join(unknown)}; known: {', '.join(OPTIONS)}")
    o = {**OPTIONS, **options}
    try:
        size, msaa, exposure = int(o["size"]), int(o["msaa"]), float(o["exposure"])
        budget = float(o["budget_ms"]) if o["budget_ms"] else None
    except ValueError as exc:
        raise PreviewOptionError(f"preview: {exc}") from None
    if not 8 <= size <= 8192:
        raise PreviewOptionError(f"preview: size {size} is out of range (8 ... 8192)")
    if o["background"] not in ("env", "transparent"):
        raise PreviewOptionError("preview: background must be env or transparent")
    if o["tier"]:
        from .tiers import parse_tier

        try:
            parse_tier(o["tier"])
        except ValueError as exc:
            raise PreviewOptionError(str(exc)) from None
    return PreviewOptions(
        size,
        o["mesh"],
        o["tier"],
        budget,
        o["env"],
        o["background"],
        exposure,
        msaa,
        {"fresnel": o["fresnel"], "multiscatter": o["multiscatter"]},
    )


def choose_tier(renderer, scene, material: dict, opts: PreviewOptions):
    """The tier option, else the best tier within budget_ms, else the default."""
    from .tiers import DEFAULT_TIER, parse_tier, select_tier

    if opts.tier:
        return parse_tier(opts.tier), {}
    if opts.budget_ms is None:
        return parse_tier(DEFAULT_TIER), {}
    return select_tier(opts.budget_ms, lambda t: renderer.frame_time(scene, material, t, opts.glsl, repeats=3))


def render_ir(ir: dict, options: dict | None = None, resources=None) -> list[tuple[dict, object]]:
    """Render every material of the IR: [(material, Frame)]. With `resources` (a
    resources.Resources) what is made is kept there; without, it is released at the end."""
    from .render import Renderer

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
    from .sheet import groups_of, label, sheet

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
    from cnlmc.output import write_atomic

    from .sheet import png_bytes

    frames = render_ir(ir, options, resources)
    out_path = Path(out_path)
    write_atomic(out_path, png_bytes(compose(frames)))
    notes = [n for _, f in frames for n in f.notes]
    return PreviewReport(out_path, frames, notes)


def emit(ir: dict, options: dict) -> EmitResult:
    from .sheet import png_bytes

    notes: list = []
    for material in ir["materials"]:
        check_material(notes, NAME, CAPABILITIES, material)
    frames = render_ir(ir, options)
    artifacts = [Artifact(f"{m['name']}.png", png_bytes(f.rgba), "binary") for m, f in frames]
    if any(m.get("variant") for m, _ in frames):
        artifacts.append(Artifact("sheet.png", png_bytes(compose(frames)), "binary"))
    return EmitResult(artifacts, notes)


__all__ = [
    "NAME",
    "DESCRIPTION",
    "CAPABILITIES",
    "OPTIONS",
    "emit",
    "preview_command",
    "render_ir",
    "parse_options",
    "PreviewOptionError",
    "PreviewReport",
]
