"""The Mitsuba volumetric reference, rendered at low spp (docs/subsurface.md).

A backlit thin leaf glows and a thick block of the same medium does not; the `principledthin`
sheet transmits about what the exact volumetric sheet does; a medium lit by a white world returns
no more light than it gets (no medium creates light); the exported scene loads and uses volpathmis."""

from __future__ import annotations

import copy
import re

import numpy as np
import pytest

from tests.helpers import require

mi = require("mitsuba", "mitsuba")
pytestmark = pytest.mark.mitsuba

from cnlmc.api import compile_source, emit  # noqa: E402

LIGHT_BEHIND = """<shape type="rectangle">
        <transform name="to_world"><scale value="1.5"/><translate z="-2"/></transform>
        <emitter type="area"><rgb name="radiance" value="1, 1, 1"/></emitter>
    </shape>"""
SHEET = '<shape type="rectangle"><transform name="to_world"><scale value="3"/></transform><ref id="{id}"/></shape>'
SLAB = (
    '<shape type="cube"><transform name="to_world"><scale x="3" y="3" z="{half}"/></transform>'
    '<ref id="{id}"/><ref name="interior" id="{id}_medium"/></shape>'
)
UNIT_M = 0.01  # one scene unit is a centimetre here: the sheet and the block are 6 cm wide


def ir_of(phrase: str) -> dict:
    result = compile_source(phrase)
    assert result.ok, result.diagnostics
    return result.ir


def as_volume(ir: dict) -> dict:
    """The same medium as a thick body: model.subsurface 'volume', no sheet thickness."""
    thick = copy.deepcopy(ir)
    for material in thick["materials"]:
        material["model"]["subsurface"] = "volume"
        material["params"]["subsurface"]["thickness"] = None
    return thick


def fragment(ir: dict, folder) -> str:
    xml = emit(ir, "mitsuba", {"form": "fragment", "unit_metres": str(UNIT_M)}).artifacts[0].content
    (folder / "materials.xml").write_text(xml)
    return ir["materials"][0]["name"]


def render(folder, shape: str) -> np.ndarray:
    from cnlmc.backends.preview.subsurface_reference import probe_scene

    mi.set_variant("scalar_rgb")
    scene = probe_scene(f"{LIGHT_BEHIND}\n    {shape}", origin="0, 0, 6", fov=8, size=16, spp=16, max_depth=256)
    (folder / "scene.xml").write_text(scene)
    return np.asarray(mi.render(mi.load_file(str(folder / "scene.xml"))))


def backlit_sheet(ir: dict, folder) -> np.ndarray:
    ident = fragment(ir, folder)
    return render(folder, SHEET.format(id=ident)).mean(axis=(0, 1))


def backlit_slab(ir: dict, folder, thickness_m: float) -> np.ndarray:
    ident = fragment(as_volume(ir), folder)
    half = thickness_m / UNIT_M / 2
    return render(folder, SLAB.format(id=ident, half=f"{half:.6g}")).mean(axis=(0, 1))


def test_a_backlit_thin_leaf_glows_and_a_thick_block_of_it_does_not(tmp_path):
    leaf = ir_of("backlit leaf")
    assert leaf["materials"][0]["model"]["subsurface"] == "thin"
    sheet = backlit_sheet(leaf, tmp_path)
    block = backlit_slab(leaf, tmp_path, 0.02)  # 2 cm of leaf tissue
    assert sheet[1] > 0.1, sheet  # green light through the sheet
    assert sheet[1] > sheet[2], sheet  # yellow-green, not white
    assert block.max() < 0.01, block
    assert sheet[1] > 20 * max(block[1], 1e-4)


def test_the_thin_sheet_transmits_about_what_the_exact_volumetric_sheet_does(tmp_path):
    """principledthin (Kubelka-Munk weights) against a 0.3 mm slab of the medium inside a dielectric."""
    leaf = ir_of("leaf")
    thickness = leaf["materials"][0]["params"]["subsurface"]["thickness"]
    approximate = backlit_sheet(leaf, tmp_path)
    exact = backlit_slab(leaf, tmp_path, thickness)
    assert exact[1] > 0.05, exact
    ratio = approximate[1] / exact[1]
    assert 0.4 < ratio < 2.5, (approximate, exact)


WHITE_WORLD = (
    '<emitter type="constant"><rgb name="radiance" value="1, 1, 1"/></emitter>\n    '
    '<shape type="sphere"><float name="radius" value="0.7"/><ref id="{id}"/><ref name="interior" id="{id}_medium"/></shape>'
)


@pytest.mark.parametrize("phrase", ["white milk", "white translucent plastic"])
def test_no_medium_creates_light_in_a_white_furnace(tmp_path, phrase):
    """Inside a uniform white world a medium under a clear boundary returns at most what it gets
    (the brightest media cnlmc makes: albedo 1), and, being nearly lossless, close to it (a rough
    boundary, plastic's roughdielectric, loses what its single-scattering GGX lobe misses: 0.90 in blue)."""
    ir = ir_of(phrase)
    medium = ir["materials"][0]["params"]["subsurface"]
    assert min(medium["color"]) > 0.95, medium
    ident = ir["materials"][0]["name"]
    xml = emit(ir, "mitsuba", {"form": "fragment", "unit_metres": "0.000001"}).artifacts[0].content
    (tmp_path / "materials.xml").write_text(xml)
    from cnlmc.backends.preview.subsurface_reference import probe_scene

    furnace = probe_scene(WHITE_WORLD.format(id=ident), origin="0, 0, 6", fov=20, size=8, spp=256, max_depth=1024)
    (tmp_path / "scene.xml").write_text(furnace)
    mi.set_variant("scalar_rgb")
    image = np.asarray(mi.render(mi.load_file(str(tmp_path / "scene.xml"))))
    centre = image[2:6, 2:6].mean(axis=(0, 1))
    assert centre.max() <= 1.0 + 0.04, centre
    assert centre.min() > 0.85, centre


def test_the_exported_scene_uses_volpathmis_and_loads(tmp_path):
    ir = ir_of("wax\njade")
    xml = emit(ir, "mitsuba", {"spp": "1", "resolution": "8"}).artifacts[0].content
    assert '<integrator type="volpathmis">' in xml
    assert xml.count('<medium type="homogeneous"') == 2
    assert re.search(r'<ref name="interior" id="wax_medium"/>', xml)
    (tmp_path / "scene.xml").write_text(xml)
    mi.set_variant("scalar_rgb")
    scene = mi.load_file(str(tmp_path / "scene.xml"), spp=1, resx=8, resy=8, max_depth=16)
    assert np.isfinite(np.asarray(mi.render(scene))).all()


def test_a_scene_without_a_medium_keeps_the_path_integrator():
    xml = emit(ir_of("white plastic"), "mitsuba", {"spp": "1"}).artifacts[0].content
    assert '<integrator type="path">' in xml and "<medium" not in xml
