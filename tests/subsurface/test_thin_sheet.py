"""The Mitsuba thin sheet (docs/subsurface.md, "The reference"): a waxy cuticle on both faces (the
IR's interface, IOR and alpha, over the diffuse base) blended with the Kubelka–Munk sheet's diffuse
transmission. The sheet's BSDF is loaded from the exported fragment and sampled directly: it
reflects a glossy highlight and more at grazing incidence (Fresnel), transmits the slab's T, and
returns at most what it gets at every incidence (no sheet creates light), as it does in a white
world."""

from __future__ import annotations

import math
import xml.etree.ElementTree as ET

import numpy as np
import pytest

from tests.helpers import require

mi = require("mitsuba", "mitsuba")
pytestmark = pytest.mark.mitsuba

from cnlmc.api import compile_source, emit  # noqa: E402
from cnlmc.backends.exchange.mitsuba_subsurface import sheet_transmittance  # noqa: E402
from cnlmc.material import Material  # noqa: E402

SAMPLES = 4000
WHITE_WORLD_SHEET = (
    '<emitter type="constant"><rgb name="radiance" value="1, 1, 1"/></emitter>\n    '
    '<shape type="sphere"><float name="radius" value="0.7"/><ref id="{id}"/></shape>'
)


def thin_ir(phrase: str) -> dict:
    result = compile_source(phrase)
    assert result.ok, result.diagnostics
    assert result.ir["materials"][0]["model"]["subsurface"] == "thin", phrase
    return result.ir


def fragment(ir: dict) -> str:
    return emit(ir, "mitsuba", {"form": "fragment"}).artifacts[0].content


def sheet_bsdf(ir: dict, part: str = "bsdf"):
    """The material's BSDF (or the element at `part` in the fragment), loaded by Mitsuba."""
    mi.set_variant("scalar_rgb")
    element = ET.fromstring(fragment(ir)).find(part)
    assert element is not None, part
    element.set("version", "3.0.0")
    element.attrib.pop("id", None)
    return mi.load_string(ET.tostring(element, encoding="unicode"))


def incidence(theta_deg: float):
    theta = math.radians(theta_deg)
    si = mi.SurfaceInteraction3f()
    si.wi = mi.Vector3f(math.sin(theta), 0.0, math.cos(theta))
    si.sh_frame = mi.Frame3f(mi.Vector3f(0, 0, 1))
    return si


def albedo(bsdf, theta_deg: float, seed: int = 1) -> tuple[np.ndarray, np.ndarray]:
    """(reflected, transmitted) share of light arriving at theta, by sampling the BSDF."""
    si, ctx, rng = incidence(theta_deg), mi.BSDFContext(), np.random.default_rng(seed)
    reflected, transmitted = np.zeros(3), np.zeros(3)
    for u in rng.random((SAMPLES, 3)):
        sample, weight = bsdf.sample(ctx, si, float(u[0]), mi.Point2f(float(u[1]), float(u[2])))
        value = np.array([weight[0], weight[1], weight[2]], np.float64)
        if sample.wo[2] > 0:
            reflected += value
        else:
            transmitted += value
    return reflected / SAMPLES, transmitted / SAMPLES


def brdf(bsdf, wi_deg: float, wo_deg: float) -> float:
    """The green channel of f cos, wo in the plane of incidence (negative: the mirror side)."""
    si, wo = incidence(wi_deg), math.radians(wo_deg)
    value = bsdf.eval(mi.BSDFContext(), si, mi.Vector3f(math.sin(wo), 0.0, math.cos(wo)))
    return float(value[1])


@pytest.mark.parametrize("phrase", ["white leaf", "thin white wax"])
def test_a_white_sheet_returns_at_most_what_it_gets_at_every_incidence(phrase):
    bsdf = sheet_bsdf(thin_ir(phrase))
    for theta in (0.0, 45.0, 75.0, 88.0):
        reflected, transmitted = albedo(bsdf, theta)
        total = reflected + transmitted
        assert total.max() <= 1.0 + 0.02, (theta, reflected, transmitted)
        # a white sheet loses only what Mitsuba's roughplastic does with a white base (about 0.2)
        assert total.min() > 0.7, (theta, total)


@pytest.mark.parametrize("phrase", ["thin milk", "thin skin", "thin wax", "thin jade", "backlit leaf"])
def test_the_boosted_cuticle_alone_returns_at_most_what_it_gets(phrase):
    """The blend gives the cuticle weight 1 - w and boosts its interface by up to 1 / (1 - w): the
    boost is bounded so that the cuticle alone stays at or under 1, hence the sheet too (unbounded,
    thin milk's w 0.78 would boost it 4.5x: its cuticle returned 4.15 at 89 degrees)."""
    ir = thin_ir(phrase)
    cuticle, sheet = sheet_bsdf(ir, "bsdf/bsdf"), sheet_bsdf(ir)
    for theta in (0.0, 60.0, 80.0, 89.0):
        reflected, transmitted = albedo(cuticle, theta)
        assert transmitted.max() == 0.0 and reflected.max() <= 1.0 + 0.02, (theta, reflected)
        assert sum(albedo(sheet, theta)).max() <= 1.0 + 0.02, theta


def test_the_leaf_s_interface_reflects_at_full_strength():
    """The leaf's w is 0.5: its cuticle's interface is boosted by 1 / (1 - w), nothing bounds it."""
    xml = ET.fromstring(fragment(thin_ir("backlit leaf")))
    weight = float(xml.find("bsdf/float[@name='weight']").get("value"))
    boost = float(xml.find("bsdf/bsdf/bsdf/float[@name='specular_reflectance']").get("value"))
    assert 0.4 < weight < 0.6 and math.isclose((1.0 - weight) * boost, 1.0, rel_tol=1e-4), (weight, boost)


def test_a_white_sheet_in_a_white_world_returns_at_most_what_it_gets(tmp_path):
    """As tests/subsurface/test_mitsuba_volume.py's furnace: the image of the sheet's sphere."""
    from cnlmc.backends.preview.subsurface_reference import probe_scene

    ir = thin_ir("white leaf")
    (tmp_path / "materials.xml").write_text(fragment(ir))
    scene = probe_scene(
        WHITE_WORLD_SHEET.format(id=ir["materials"][0]["name"]), origin="0, 0, 6", fov=20, size=8, spp=128
    )
    (tmp_path / "scene.xml").write_text(scene)
    mi.set_variant("scalar_rgb")
    image = np.asarray(mi.render(mi.load_file(str(tmp_path / "scene.xml"))))
    centre = image[2:6, 2:6].mean(axis=(0, 1))
    assert centre.max() <= 1.0 + 0.04, centre
    assert centre.min() > 0.7, centre  # roughplastic's own loss, about 0.2


def test_the_leaf_has_its_cuticle_s_glossy_highlight_and_fresnel():
    """A diffuse front (the export before) is flat: the same f cos at the mirror as beside it, and
    less at grazing. The cuticle peaks at the mirror and reflects more at grazing incidence."""
    bsdf = sheet_bsdf(thin_ir("backlit leaf"))
    mirror, beside = brdf(bsdf, 30.0, -30.0), brdf(bsdf, 30.0, 30.0)
    assert mirror > 2.0 * beside, (mirror, beside)
    normal, grazing = albedo(bsdf, 0.0)[0], albedo(bsdf, 80.0)[0]
    assert grazing.mean() > 1.5 * normal.mean(), (normal, grazing)


def test_the_leaf_transmits_the_kubelka_munk_sheet_s_t():
    ir = thin_ir("backlit leaf")
    expected = np.asarray(sheet_transmittance(Material.from_ir(ir["materials"][0])))
    _, transmitted = albedo(sheet_bsdf(ir), 20.0)
    assert np.allclose(transmitted, expected, rtol=0.08, atol=0.01), (transmitted, expected)
    assert transmitted[1] > transmitted[0] > transmitted[2]  # green through the leaf, then red
