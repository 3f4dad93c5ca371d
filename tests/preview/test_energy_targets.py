"""One energy budget across targets (issue #15 item 6): under a uniform white sky (radiance 1, no
key light) a sphere's pixel at view cosine mu shows the directional albedo A(mu). The preview's
mean radiance over the pixels fully inside the sphere is within 5 % of the IR's (the numpy
reference's A(mu) at the same pixels), and never above 1. The full table, Mitsuba included, is
`bench/furnace.py --all`.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from tests.helpers import load_module

from .conftest import SMALL, material_of

SIZE = SMALL  # the session renderer's size
SUBSET = [
    "white plastic",
    "gold",
    "brushed aluminium",
    "white varnished oak",
    "steel with a clear coat",
    "red car paint",
    "black anodized aluminium",
    "matte black metal",
]
# Mitsuba's native plugins agree for these (Oren-Nayar as a Lambert of the lobe's albedo); a coat
# over paint (roughplastic) is within 5-16 %, over a metal (principled) 3x off: bench/furnace.py
MITSUBA_AGREES = ["white plastic", "white paper", "gold", "silver", "rough iron"]


@pytest.fixture(scope="module")
def furnace():
    return load_module("furnace_bench", Path(__file__).parents[2] / "bench" / "furnace.py")


@pytest.fixture(scope="module")
def white(furnace, gl_available):
    scene = furnace.white_scene(SIZE)
    return scene, furnace.view_cosines(scene, SIZE)


@pytest.mark.parametrize("phrase", SUBSET)
def test_the_preview_agrees_with_the_ir_under_a_white_sky(renderer, furnace, white, phrase):
    scene, mus = white
    m = material_of(phrase)
    ir, preview = furnace.agreement(
        furnace.ir_image(m, mus, 512), mus, *furnace.preview_image(renderer, scene, m, "fis64")
    )
    assert preview == pytest.approx(ir, rel=0.05), (phrase, ir, preview)
    assert preview <= 1.0 and ir <= 1.0


def test_the_check_sees_a_wrong_material(renderer, furnace, white):
    """A white plastic against the IR of a grey one is far outside 5 %: the comparison is live."""
    scene, mus = white
    grey = furnace.ir_image(material_of("grey plastic"), mus, 512)
    ir, preview = furnace.agreement(
        grey, mus, *furnace.preview_image(renderer, scene, material_of("white plastic"), "fis64")
    )
    assert abs(preview / ir - 1) > 0.2


@pytest.mark.parametrize("phrase", MITSUBA_AGREES)
def test_mitsuba_agrees_with_the_ir_under_a_white_sky(furnace, white, phrase):
    pytest.importorskip("mitsuba")
    scene, mus = white
    m = material_of(phrase)
    ir, mitsuba = furnace.agreement(furnace.ir_image(m, mus, 512), mus, *furnace.mitsuba_image(scene, m, SIZE, 16))
    assert mitsuba == pytest.approx(ir, rel=0.05), (phrase, ir, mitsuba)
    assert np.isfinite(mitsuba) and mitsuba <= 1.0
