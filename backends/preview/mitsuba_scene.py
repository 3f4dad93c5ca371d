"""The preview scene for Mitsuba 3: the same camera, mesh (a PLY we write), environment (an EXR
in Mitsuba's envmap convention), key light (`directional`) and the material as the Mitsuba
backend's BSDF (`form=fragment`, included by id). Used by bench/preview_chart.py as the
reference renderer.
"""

from __future__ import annotations

import math
from pathlib import Path
from xml.sax.saxutils import quoteattr

import numpy as np

from ..base import as_document
from ..exchange import mitsuba, mitsuba_cnlm
from ..exchange.mitsuba_subsurface import VOLUME_MAX_DEPTH, medium_entry, roulette_depth
from . import reference_glass
from .environment import mitsuba_rows, write_exr
from .mesh_io import write_ply
from .scene import Scene
from .shader import MaterialLike, as_material

SCENE_TEMPLATE = """<?xml version="1.0" encoding="utf-8"?>
<!-- cnlmc preview scene for Mitsuba 3 (backends/preview/mitsuba_scene.py) -->
<scene version="3.0.0">
    <default name="spp" value="{spp}"/>
    <default name="resx" value="{width}"/>
    <default name="resy" value="{height}"/>
    <include filename="materials.xml"/>
    <integrator type="{integrator}">
        <boolean name="hide_emitters" value="{hide}"/>{max_depth}
    </integrator>
    <sensor type="perspective">
        <float name="fov" value="{fov:.9g}"/>
        <string name="fov_axis" value="y"/>
        <float name="near_clip" value="{near:.9g}"/>
        <float name="far_clip" value="{far:.9g}"/>
        <transform name="to_world">
            <lookat origin="{eye}" target="{target}" up="{up}"/>
        </transform>
        <sampler type="{sampler}">
            <integer name="sample_count" value="$spp"/>
            <integer name="seed" value="{seed}"/>
        </sampler>
        <film type="hdrfilm">
            <integer name="width" value="$resx"/>
            <integer name="height" value="$resy"/>
            <string name="pixel_format" value="rgba"/>
            <rfilter type="box"/>
        </film>
    </sensor>
    <emitter type="envmap">
        <string name="filename" value="environment.exr"/>
        <float name="scale" value="{env_scale:.9g}"/>
    </emitter>
    <emitter type="directional">
        <vector name="direction" value="{light_dir}"/>
        <rgb name="irradiance" value="{irradiance:.9g}"/>
    </emitter>
    <shape type="ply">
        <string name="filename" value="mesh.ply"/>
        <ref id={bsdf_id}/>{interior}
    </shape>
</scene>
"""


#: Glass is rendered with the `path` integrator (`direct` stops at the first surface: a glass
#: would show its reflection only, and the preview's transmission would not be measured);
#: depth 8 follows a view ray in, through up to five internal reflections, and out.
GLASS_MAX_DEPTH = 8


def integrator_for(material: MaterialLike, medium: bool = False) -> tuple[str, str]:
    """(integrator type, its extra properties) for the material: `path` for glass (`volpathmis`
    when it has an absorbing medium inside: a tinted glass), `volpathmis` to any depth for a body
    with a scattering medium (milk, wax: Russian roulette ends its paths), else `direct`."""
    if as_material(material).model.base == "glass":
        depth = f'\n        <integer name="max_depth" value="{GLASS_MAX_DEPTH}"/>'
        return ("volpathmis" if medium else "path"), depth
    if medium:
        return "volpathmis", f'\n        <integer name="max_depth" value="{VOLUME_MAX_DEPTH}"/>' + _roulette(material)
    return "direct", ""


def _roulette(material: MaterialLike) -> str:
    """The integrator's `rr_depth` for a body's medium (mitsuba_subsurface.VOLUME_RR_DEPTH_MAX)."""
    entry = medium_entry(as_material(material), "body")
    depth = roulette_depth([entry] if entry is not None else [])
    return f'\n        <integer name="rr_depth" value="{depth}"/>'


#: Mitsuba's sampler: low-discrepancy over each pixel's samples ("ldsampler"). With
#: "independent", the random one-sample choice between the BSDF's lobes (a metal's 10 % cosine
#: share) adds binomial noise; FLIP between two seeds at 256 spp, 256x256: gold's rim 0.020 ->
#: 0.007, mirror chrome 0.0038 -> 0.0011 (ldsampler). ldsampler takes 4, 16, 64, 256, ... spp
#: only (it rounds any other count up, 1 to 4, 32 to 64): other counts get "independent".
SAMPLER = "ldsampler"


def sampler_for(spp: int) -> str:
    """The sampler that renders exactly `spp` samples per pixel, low-discrepancy when it can."""
    power = 4
    while power < spp:
        power *= 4
    return SAMPLER if spp >= 4 and power == spp else "independent"


def _vec(v) -> str:
    return ", ".join(f"{float(x):.9g}" for x in v)


def export_scene(
    material: MaterialLike,
    scene: Scene,
    out_dir,
    width: int,
    height: int,
    spp: int = 64,
    seed: int = 0,
    hide_background: bool = True,
    bsdf: str = "native",
    sampler: str | None = None,
) -> Path:
    """Write scene.xml, materials.xml (+ baked textures), mesh.ply and environment.exr.
    `bsdf="cnlm"` uses cnlmc's own BSDF through the `cnlm` plugin (backends/exchange/mitsuba_cnlm.py).
    `sampler`: default `sampler_for(spp)` (render at that spp: ldsampler rounds others up)."""
    out = Path(out_dir)
    out.mkdir(parents=True, exist_ok=True)
    document = as_document({"materials": [as_material(material).to_ir()]})
    result = mitsuba.emit(document, {"form": "fragment", "bsdf": bsdf})
    for artifact in result.artifacts:
        path = out / artifact.name
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_bytes(artifact.content if isinstance(artifact.content, bytes) else artifact.content.encode())
    if bsdf == "cnlm":  # rough glass with the light its facets block given back (reference_glass.py)
        materials = out / "materials.xml"
        materials.write_text(reference_glass.wrap_materials_xml(materials.read_text("utf-8")), "utf-8")
    bsdf_id, medium = fragment_ids(out / "materials.xml")
    # a tinted glass's absorption; a volume's body in the native export (the chart's cnlm reference
    # draws the surface model, whose colour is the body's: preview_chart_translucent.py has the volume)
    if as_material(material).model.base != "glass" and bsdf == "cnlm":
        medium = None
    write_ply(scene.mesh, out / "mesh.ply", flip_v=True)  # Mitsuba: bitmap top row at v = 0
    write_exr(out / "environment.exr", mitsuba_rows(scene.env.image))  # Mitsuba's row positions
    cam = scene.camera
    distance = float(np.linalg.norm(np.subtract(cam.eye, cam.target)))
    integrator, max_depth = integrator_for(material, medium is not None)
    xml = SCENE_TEMPLATE.format(
        integrator=integrator,
        max_depth=max_depth,
        spp=int(spp),
        width=int(width),
        height=int(height),
        hide="true" if hide_background else "false",
        fov=cam.fov_y,
        near=max(distance * 0.01, 1e-3),
        far=distance * 10,
        eye=_vec(cam.eye),
        target=_vec(cam.target),
        up=_vec(cam.up),
        seed=int(seed),
        sampler=sampler or sampler_for(spp),
        env_scale=scene.env_intensity,
        light_dir=_vec(-scene.env.key.unit),
        irradiance=scene.env.key.irradiance * scene.env_intensity,
        bsdf_id=quoteattr(bsdf_id),
        interior="" if medium is None else f'\n        <ref name="interior" id={quoteattr(medium)}/>',
    )
    (out / "scene.xml").write_text(xml)
    return out / "scene.xml"


def fragment_ids(materials_xml: Path) -> tuple[str, str | None]:
    """The ids of the fragment's first BSDF and of its medium (a tinted glass's absorption, a
    volume's body), if any: one read of the file."""
    import xml.etree.ElementTree as ET

    found: dict[str, str] = {}
    for child in ET.parse(materials_xml).getroot():
        ident = child.get("id")
        if child.tag in ("bsdf", "medium") and ident:
            found.setdefault(child.tag, ident)
    if "bsdf" not in found:
        raise ValueError(f"{materials_xml}: no BSDF with an id")
    return found["bsdf"], found.get("medium")


def medium_id(materials_xml: Path) -> str | None:
    """The id of the fragment's medium, if any (see fragment_ids)."""
    return fragment_ids(materials_xml)[1]


def render_scene(
    path, spp: int | None = None, seed: int = 0, variant: str | None = None, warm: bool = False
) -> tuple[np.ndarray, float]:
    """Render with Mitsuba: (linear RGBA float32, top row first; seconds of the render call).
    RGB is premultiplied by the alpha (coverage): composite as rgb + background * (1 - alpha).

    `variant`: None keeps the current one (scalar_rgb if none is set); "vectorized" selects
    llvm_ad_rgb (or CUDA) and registers the `cnlm` plugin, which scenes written with
    bsdf="cnlm" need; scenes without it render with Mitsuba's symbolic calls (its fast default).
    `warm=True` renders once untimed first (JIT compilation and kernel caches), so the time
    is the steady-state cost, like the preview's warm frame time."""
    import mitsuba as mi

    if variant != "vectorized":
        if variant:
            mi.set_variant(variant)
        elif mi.variant() is None:
            mi.set_variant("scalar_rgb")
        return _timed_render(path, spp, seed, warm)
    mitsuba_cnlm.register()
    reference_glass.register()
    previous = mitsuba_cnlm.set_symbolic(not uses_plugin(path))
    try:
        return _timed_render(path, spp, seed, warm)
    finally:
        mitsuba_cnlm.restore_symbolic(previous)


def uses_plugin(scene_path) -> bool:
    """Does the exported scene (its materials.xml) use the `cnlm` plugin?"""
    materials = Path(scene_path).parent / "materials.xml"
    text = materials.read_text("utf-8") if materials.exists() else ""
    return 'type="cnlm"' in text or f'type="{reference_glass.PLUGIN}"' in text


def _timed_render(path, spp, seed, warm) -> tuple[np.ndarray, float]:
    import time

    import mitsuba as mi

    scene = mi.load_file(str(path), **({"spp": spp} if spp else {}))
    if warm:
        np.array(mi.render(scene, seed=seed + 1))
    start = time.perf_counter()
    image = np.array(mi.render(scene, seed=seed), np.float32)
    return image, time.perf_counter() - start


def fov_note(scene: Scene) -> str:
    return f"fov_y {scene.camera.fov_y} deg, eye {_vec(scene.camera.eye)}, {math.degrees(0):.0f}"
