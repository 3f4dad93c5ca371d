"""The preview scene with a translucent material for Mitsuba 3, the reference of the preview's
subsurface approximation (bench/preview_chart.py's translucent class, bench/subsurface_sheet.py,
tests/preview/test_subsurface.py).

The material is the Mitsuba export's (backends/exchange/mitsuba_subsurface.py, docs/subsurface.md):
a volume is a dielectric or rough dielectric boundary around a homogeneous medium (the dipole
inversion of the IR's colour and radius, its scale METRES_PER_UNIT metres a unit), a thin sheet
its blend of a two-sided diffuse front and a diffuse transmitter. The preview scene (mitsuba_scene.export_scene: camera, mesh, environment,
key light) gets the medium as its shape's interior and the `volpathmis` integrator the export
uses for media (spectral MIS: `volpath` is biased dark for a chromatic medium).

The key light. The preview's key is a directional (delta) light; Mitsuba cannot connect a delta
light through a smooth (delta) dielectric boundary to the medium behind it, so with it a smooth
body (milk) rendered the same with the key light on or off. Here the key light is a small far
disk (`key_disk`): half-angle KEY_HALF_ANGLE_DEG, at KEY_DISTANCE scene units, radiance
L = E / (pi sin^2 theta) so that its irradiance on a surface facing it equals the directional
light's E (a uniform disk of angular radius theta gives E = pi L sin^2 theta). Paths that leave the
body through the smooth boundary hit it by BSDF sampling; surfaces that can sample it (a rough
boundary, an opaque material) do so as before (tests/subsurface/test_reference_key_light.py)."""

from __future__ import annotations

import re
from pathlib import Path

import numpy as np

from .mitsuba_scene import export_scene, medium_id, render_scene
from .scene import Scene
from .shader import MaterialLike, as_material

INTEGRATOR = "volpathmis"
#: a probe scene's path depth (probe_scene): unbounded, as the export's (a bright medium needs
#: ~1/(3(1 - alpha')) events a path)
VOLUME_MAX_DEPTH_PROBE = -1
#: Measured: Mitsuba's `ldsampler` at 4 and 16 spp returns pixels of 1e35 for milk's deep paths
#: (96 and 36 of 32x32 pixels above 50; `independent` at 8 and 32 spp: none above 65), so the
#: volumetric reference samples independently at every count.
SAMPLER = "independent"
INTEGRATOR_OPEN = re.compile(r'<integrator type="\w+">(\s*<integer name="max_depth" value="-?\d+"/>)?')
DIRECTIONAL = re.compile(r'\s*<emitter type="directional">.*?</emitter>', re.S)
#: our choice: 4 degrees (the sun is 0.27): small enough that an opaque surface's highlight and
#: terminator match the preview's delta light (white plastic, tests), large enough that paths
#: leaving a smooth body find it by BSDF sampling at a chart's sample counts
KEY_HALF_ANGLE_DEG = 4.0
#: scene units (the preview's objects fit a unit sphere): the irradiance across an object varies by
#: (1 +- 1/KEY_DISTANCE)^2, 0.2 %; inside the camera's far clip only for secondary rays
KEY_DISTANCE = 1000.0
KEY_DISK = """
    <shape type="disk">
        <transform name="to_world">
            <scale value="{radius:.9g}"/>
            <lookat origin="{origin}" target="0, 0, 0" up="{up}"/>
        </transform>
        <emitter type="area"><rgb name="radiance" value="{radiance:.9g}"/></emitter>
    </shape>"""


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
    path = export_scene(typed, scene, out, width, height, spp=spp, seed=seed, sampler=SAMPLER)
    xml = path.read_text()  # a volume: export_scene wrote its medium as the interior and volpathmis
    if medium_id(out / "materials.xml") is None:  # a thin sheet: the volume path tracer all the same
        depth = f'\n        <integer name="max_depth" value="{VOLUME_MAX_DEPTH}"/>'
        xml = INTEGRATOR_OPEN.sub(f'<integrator type="{INTEGRATOR}">{depth}', xml, count=1)
    path.write_text(with_key_disk(xml, scene))
    return path


def key_disk(scene: Scene) -> str:
    """The scene's key light as a far disk emitter of the same irradiance (module docstring)."""
    towards = scene.env.key.unit
    theta = np.radians(KEY_HALF_ANGLE_DEG)
    irradiance = scene.env.key.irradiance * scene.env_intensity
    up = (1.0, 0.0, 0.0) if abs(towards[1]) > 0.99 else (0.0, 1.0, 0.0)
    return KEY_DISK.format(
        radius=KEY_DISTANCE * np.tan(theta),
        origin=", ".join(f"{x:.9g}" for x in towards * KEY_DISTANCE),
        up=", ".join(f"{x:.9g}" for x in up),
        radiance=irradiance / (np.pi * np.sin(theta) ** 2),
    )


def with_key_disk(xml: str, scene: Scene) -> str:
    """The exported preview scene with its directional key light replaced by the far disk
    (none when the key light is off)."""
    disk = key_disk(scene) if scene.env.key.irradiance * scene.env_intensity > 0 else ""
    if not DIRECTIONAL.search(xml):
        raise ValueError("the preview scene has no directional key light to replace")
    return DIRECTIONAL.sub(lambda _: disk, xml, count=1)


def render_subsurface(
    material: MaterialLike, scene: Scene, out_dir, size: int, spp: int, seed: int = 0
) -> tuple[np.ndarray, float]:
    """(linear RGBA premultiplied by coverage, top row first; seconds of the render call)."""
    path = export_subsurface_scene(material, scene, out_dir, size, size, spp, seed)
    return render_scene(path, spp=spp, seed=seed, variant="vectorized")


PROBE_SCENE = """<?xml version="1.0" encoding="utf-8"?>
<scene version="3.0.0">
    <include filename="materials.xml"/>
    <integrator type="{integrator}"><integer name="max_depth" value="{max_depth}"/></integrator>
    <sensor type="perspective">
        <float name="fov" value="{fov:.9g}"/>
        <transform name="to_world"><lookat origin="{origin}" target="{target}" up="0, 1, 0"/></transform>
        <sampler type="{sampler}"><integer name="sample_count" value="{spp}"/></sampler>
        <film type="hdrfilm"><integer name="width" value="{size}"/><integer name="height" value="{size}"/></film>
    </sensor>
    {content}
</scene>
"""


def probe_scene(
    content: str,
    *,
    origin: str,
    fov: float,
    size: int,
    spp: int,
    target: str = "0, 0, 0",
    max_depth: int = VOLUME_MAX_DEPTH_PROBE,
) -> str:
    """A small Mitsuba scene around a materials.xml fragment (the tests' backlit sheets and white
    furnace, bench/subsurface_look.py): `content` holds the emitters and shapes; a square
    perspective camera at `origin` looking at `target`, the volume path tracer, independent samples."""
    return PROBE_SCENE.format(
        integrator=INTEGRATOR,
        max_depth=max_depth,
        fov=fov,
        origin=origin,
        target=target,
        sampler=SAMPLER,
        spp=spp,
        size=size,
        content=content,
    )
