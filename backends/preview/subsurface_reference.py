"""The preview scene with a translucent material for Mitsuba 3, rendered exactly: a dielectric (or
rough dielectric) boundary around a homogeneous participating medium, `volpath` integrator.
The reference of the preview's subsurface approximation (bench/preview_chart.py's translucent
class, bench/subsurface_sheet.py, tests/preview/test_subsurface.py).

The medium from the IR's (albedo c, mean free path l): sigma_t = 1 / l and the single-scattering
albedo from c by the Christensen-Burley inversion (Christensen & Burley 2015, "Approximate
Reflectance Profiles for Efficient Subsurface Scattering", the fit of the van de Hulst multiple-
scattering albedo): alpha = 1 - (4.09712 + 4.20863 c - sqrt(9.59217 + 41.6808 c + 17.7126 c^2))^2.
A thin wall is a shell: the mesh and a copy moved inward by the wall's thickness (its triangles
reversed), the medium between them, a dielectric boundary on both sides.
Lengths: metres / metres_per_unit (data/subsurface.toml), the preview's own scale."""

from __future__ import annotations

import re
from dataclasses import replace
from pathlib import Path

import numpy as np

from .mesh import Mesh
from .mesh_io import write_ply
from .mitsuba_scene import export_scene
from .scene import Scene
from .shader import MaterialLike, as_material
from .subsurface import TranslucentBody, settings, single_scattering_albedo, subsurface_of

#: volpath's path depth (scattering events count): measured, unbounded and 64 give the same
#: sphere mean within the noise (< 1 %) for mean free paths of 1-4 mm at 2.5 cm; 1024 is margin.
MAX_DEPTH = 1024
#: the boundary's least GGX alpha. A smooth dielectric is a delta BSDF and the key light a delta
#: emitter: no path connects them, the body would never see the key light (volpath samples
#: lights at a surface only through a BSDF it can evaluate). Our choice: 0.1, the least that
#: keeps the key light's paths through the boundary converging at 64 spp.
MIN_ALPHA = 0.1
BOUNDARY_ID = "sss_boundary"
MEDIUM_ID = "sss_body"


def medium_coefficients(body: TranslucentBody) -> tuple[np.ndarray, np.ndarray]:
    """(sigma_t per scene unit, single-scattering albedo) of the body's medium."""
    per_unit = float(settings()["scene"]["metres_per_unit"])
    sigma_t = per_unit / np.maximum(np.asarray(body.radius, np.float64), 1e-9)
    return sigma_t, np.clip(single_scattering_albedo(body.color), 0.0, 0.999999)


def _rgb(values) -> str:
    return ", ".join(f"{float(x):.9g}" for x in values)


def materials_xml(material: MaterialLike, body: TranslucentBody, channel: int | None = None) -> str:
    """The boundary BSDF and the medium (Mitsuba 3 XML, included by the scene); `channel` 0, 1, 2:
    a grey medium with that channel's coefficients (see render_subsurface)."""
    typed = as_material(material)
    ax = max(float(typed.params.alpha[0]) if typed.params.alpha is not None else 0.0, MIN_ALPHA)
    sigma_t, albedo = medium_coefficients(body)
    if channel is not None:
        sigma_t, albedo = np.full(3, sigma_t[channel]), np.full(3, albedo[channel])
    scale = float(sigma_t.max())  # Mitsuba reads an RGB as a reflectance (0..1): the scale carries the size
    return f"""<?xml version="1.0" encoding="utf-8"?>
<scene version="3.0.0">
    <bsdf type="roughdielectric" id="{BOUNDARY_ID}">
        <float name="int_ior" value="{body.ior:.9g}"/>
        <float name="ext_ior" value="1.0"/>
        <float name="alpha" value="{ax:.9g}"/>
    </bsdf>
    <medium type="homogeneous" id="{MEDIUM_ID}">
        <rgb name="albedo" value="{_rgb(albedo)}"/>
        <rgb name="sigma_t" value="{_rgb(sigma_t / scale)}"/>
        <float name="scale" value="{scale:.9g}"/>
        <phase type="hg">
            <float name="g" value="{body.anisotropy:.9g}"/>
        </phase>
    </medium>
</scene>
"""


def inner_wall(mesh: Mesh, depth: float) -> Mesh:
    """The mesh moved `depth` inward along its normals, triangles reversed (normals facing in)."""
    positions = (mesh.positions - mesh.normals * depth).astype(np.float32)
    return replace(mesh, positions=positions, normals=-mesh.normals, indices=mesh.indices[:, ::-1].copy())


SHAPE = re.compile(r'<shape type="ply">\s*<string name="filename" value="mesh.ply"/>\s*<ref id=[^>]*/>\s*</shape>')


def shape_xml(filename: str) -> str:
    return (
        f'<shape type="ply">\n        <string name="filename" value="{filename}"/>\n'
        f'        <ref id="{BOUNDARY_ID}"/>\n        <ref name="interior" id="{MEDIUM_ID}"/>\n    </shape>'
    )


def export_subsurface_scene(
    material: MaterialLike,
    scene: Scene,
    out_dir,
    width: int,
    height: int,
    spp: int = 64,
    seed: int = 0,
    channel: int | None = None,
) -> Path:
    """Write the preview scene (mitsuba_scene.export_scene: camera, mesh, environment, key light)
    with the material's boundary and medium and the volpath integrator; returns scene.xml."""
    body = subsurface_of(as_material(material))
    if body is None:
        raise ValueError(f"{as_material(material).name}: the material has no subsurface body")
    out = Path(out_dir)
    path = export_scene(material, scene, out, width, height, spp=spp, seed=seed)
    (out / "materials.xml").write_text(materials_xml(material, body, channel))
    shapes = shape_xml("mesh.ply")
    if body.thin:
        per_unit = float(settings()["scene"]["metres_per_unit"])
        write_ply(inner_wall(scene.mesh, body.wall() / per_unit), out / "inner.ply", flip_v=True)
        shapes += "\n    " + shape_xml("inner.ply")
    xml = SHAPE.sub(lambda _: shapes, path.read_text(), count=1)
    xml = re.sub(r'<integrator type="\w+">', '<integrator type="volpath">', xml, count=1)
    xml = xml.replace(
        '<integrator type="volpath">',
        f'<integrator type="volpath">\n        <integer name="max_depth" value="{MAX_DEPTH}"/>',
    )
    xml = re.sub(r'\s*<integer name="max_depth" value="\d+"/>(?=\s*<integer name="max_depth")', "", xml)
    path.write_text(xml)
    return path


def render_subsurface(material: MaterialLike, scene: Scene, out_dir, size: int, spp: int, seed: int = 0):
    """(linear RGBA, seconds): the reference rendered one colour channel at a time, each with a
    grey medium. Mitsuba's RGB volpath samples distances with one channel's coefficients and
    weights the others (spectral MIS): with mean free paths 4x apart its images speckle (measured at
    48^2: RGB at 256 spp, FLIP to the preview 0.105, visibly speckled; three grey renders of 128 spp,
    0.078, with FLIP 0.06 between two seeds).
    """
    from .mitsuba_scene import render_scene

    image, seconds = None, 0.0
    for channel in range(3):
        path = export_subsurface_scene(material, scene, Path(out_dir) / f"c{channel}", size, size, spp, seed, channel)
        part, t = render_scene(path, spp=spp, seed=seed, variant="vectorized")
        seconds += t
        if image is None:
            image = part.copy()
        image[..., channel] = part[..., channel]
    assert image is not None
    return image, seconds
