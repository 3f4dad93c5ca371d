"""Every export carries a glass's colour as Beer-Lambert absorption through its transmission_depth
(docs/bsdf.md "Absorption"): Mitsuba an absorbing medium inside a colourless dielectric, MaterialX
transmission_color with transmission_depth, the GLSL target cnlm_glass_absorption."""

from __future__ import annotations

import math
import xml.etree.ElementTree as ET

import pytest

from cnlmc.api import compile_source
from cnlmc.api import emit as emit_ir
from cnlmc.backends.exchange.mitsuba_subsurface import METRES_PER_UNIT


def emit(phrase: str, target: str, options: dict | None = None) -> str:
    result = emit_ir(compile_source(phrase + "\n").document, target, options)
    return next(a.content for a in result.artifacts if isinstance(a.content, str))


def test_mitsuba_absorbs_inside_a_colourless_dielectric():
    root = ET.fromstring(emit("red wine", "mitsuba", {"form": "fragment"}))
    bsdf, medium = root.find("bsdf"), root.find("medium")
    assert bsdf is not None and medium is not None
    assert bsdf.get("type") == "dielectric" and bsdf.find("rgb[@name='specular_transmittance']") is None
    sigma = [float(v) for v in medium.find("rgb[@name='sigma_t']").get("value").split(",")]
    scale = float(medium.find("float[@name='scale']").get("value"))
    albedo = [float(v) for v in medium.find("rgb[@name='albedo']").get("value").split(",")]
    # physicallybased.info 'Wine (Red)': (0.31, 0.081, 0.053) through 1 cm; scene unit 5 cm
    for s, c in zip(sigma, (0.31, 0.081, 0.053)):
        assert s * scale == pytest.approx(-math.log(c) / 0.01 * METRES_PER_UNIT, rel=1e-5)
    assert albedo == [0.0, 0.0, 0.0]


def test_a_colourless_glass_has_no_medium():
    root = ET.fromstring(emit("clear glass", "mitsuba", {"form": "fragment"}))
    assert root.find("medium") is None and root.find("bsdf").get("type") == "dielectric"


@pytest.mark.parametrize("surface", ["open_pbr_surface", "standard_surface"])
def test_materialx_states_the_depth(surface):
    text = emit("red wine", "materialx", {"surface": surface})
    assert '<input name="transmission_color" type="color3" value="0.31, 0.081, 0.053"' in text
    assert '<input name="transmission_depth" type="float" value="0.01"' in text


def test_the_glsl_target_absorbs_through_the_depth():
    text = emit("lager", "glsl", {"form": "standalone"})
    assert "uniform float cnlm_transmission_depth = 0.01;" in text
    assert "cnlm_glass_absorption(cnlm_glass_thickness, v_uv)" in text
