"""The preview scene with a translucent material for Mitsuba 3, the reference of the preview's
subsurface approximation (bench/preview_chart.py's translucent class, bench/subsurface_sheet.py,
tests/preview/test_subsurface.py).

The material is the Mitsuba export's (backends/exchange/mitsuba_subsurface.py, docs/subsurface.md):
a volume is a dielectric or rough dielectric boundary around a homogeneous medium (the dipole
inversion of the IR's colour and radius, its scale METRES_PER_UNIT metres a unit), a thin sheet
its blend of a two-sided diffuse front and a diffuse transmitter. The preview scene (mitsuba_scene.export_scene: camera, mesh, environment,
key light) gets the medium as its shape's interior and the `volpathmis` integrator the export
uses for media (spectral MIS: `volpath` is biased dark for a chromatic medium)."""

from __future__ import annotations

import re
import xml.etree.ElementTree as ET
from pathlib import Path

import numpy as np

from .mitsuba_scene import export_scene, render_scene
from .scene import Scene
from .shader import MaterialLike, as_material

INTEGRATOR = "volpathmis"
SHAPE_REF = re.compile(r'(<shape type="ply">\s*<string name="filename" value="mesh.ply"/>\s*<ref id=[^>]*/>)')
INTEGRATOR_OPEN = re.compile(r'<integrator type="\w+">(\s*<integer name="max_depth" value="-?\d+"/>)?')


def medium_id(materials_xml: Path) -> str | None:
    """The id of the medium the export wrote (a volume's), None for a thin sheet."""
    for child in ET.parse(materials_xml).getroot():
        if child.tag == "medium" and child.get("id"):
            return child.get("id")
    return None


def export_subsurface_scene(
    material: MaterialLike, scene: Scene, out_dir, width: int, height: int, spp: int = 64, seed: int = 0
) -> Path:
    """Write the preview scene with the material's boundary and medium (or sheet) and the
    volume path tracer; returns scene.xml."""
    from ..exchange.mitsuba_subsurface import VOLUME_MAX_DEPTH

    typed = as_material(material)
    if typed.model.subsurface is None:
        raise ValueError(f"{typed.name}: the material has no subsurface body")
    out = Path(out_dir)
    path = export_scene(typed, scene, out, width, height, spp=spp, seed=seed)
    xml = path.read_text()
    medium = medium_id(out / "materials.xml")
    if medium is not None:
        xml = SHAPE_REF.sub(lambda m: f'{m.group(1)}\n        <ref name="interior" id="{medium}"/>', xml, count=1)
    depth = f'\n        <integer name="max_depth" value="{VOLUME_MAX_DEPTH}"/>'
    xml = INTEGRATOR_OPEN.sub(f'<integrator type="{INTEGRATOR}">{depth}', xml, count=1)
    path.write_text(xml)
    return path


def render_subsurface(
    material: MaterialLike, scene: Scene, out_dir, size: int, spp: int, seed: int = 0
) -> tuple[np.ndarray, float]:
    """(linear RGBA premultiplied by coverage, top row first; seconds of the render call)."""
    path = export_subsurface_scene(material, scene, out_dir, size, size, spp, seed)
    return render_scene(path, spp=spp, seed=seed, variant="vectorized")
