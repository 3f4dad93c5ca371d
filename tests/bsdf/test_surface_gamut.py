"""Pointer's gamut of real surface colours (bench/surface_gamut.py, stdlib/data/pointer_gamut.toml):
the table as data, the adaptation D65 -> C, the chroma limit at kept L* and hue, which colours of a
compiled material it touches, and that measured colours of real materials lie inside it."""

import json
import math
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from tests.helpers import bench_modules

ROOT = Path(__file__).resolve().parents[2]
MEASURED = ROOT.parent / "shared" / "data" / "physicallybased_materials.json"


@pytest.fixture(scope="module")
def bench():
    return bench_modules("surface_gamut", "calibration")


@pytest.fixture(scope="module")
def gamut(bench):
    return bench[0].pointer_gamut()


def test_the_table_is_pointers_grid_under_illuminant_c(gamut):
    assert gamut.max_chroma.shape == (16, 36)
    assert list(gamut.lightness) == list(range(15, 95, 5))
    assert list(gamut.hue) == list(range(0, 360, 10))
    # Pointer's largest chroma: a yellow at L* 75-80, h 80 (C* 115); illuminant C's white
    assert gamut.max_chroma.max() == 115 == gamut.bound(75.0, 80.0)
    np.testing.assert_allclose(gamut.white, [0.98071, 1.0, 1.18225], atol=1e-4)


def test_bradford_carries_d65_white_to_the_tables_white(bench, gamut):
    sg = bench[0]
    np.testing.assert_allclose(sg.bradford(sg.D65_XYZ, gamut.white) @ sg.D65_XYZ, gamut.white, atol=1e-12)
    lightness, chroma, _ = gamut.lch((1.0, 1.0, 1.0))
    assert lightness == pytest.approx(100.0, abs=0.01) and chroma < 0.01


def test_the_bound_is_bilinear_periodic_in_hue_and_zero_at_black_and_white(gamut):
    assert gamut.bound(50.0, 45.0) == pytest.approx((93 + 100) / 2)  # between h 40 and 50 at L* 50
    assert gamut.bound(52.5, 40.0) == pytest.approx((93 + 88) / 2)  # between L* 50 and 55 at h 40
    assert gamut.bound(50.0, 355.0) == pytest.approx(gamut.bound(50.0, -5.0))
    assert gamut.bound(50.0, 355.0) == pytest.approx((84 + 77) / 2)  # wraps from h 350 to h 0
    assert gamut.bound(0.0, 120.0) == 0.0 and gamut.bound(100.0, 120.0) == 0.0


@settings(max_examples=60, deadline=None)
@given(st.tuples(*(st.floats(0.0, 1.0) for _ in range(3))))
def test_a_colour_keeps_lightness_and_hue_and_its_chroma_ends_within_the_bound(gamut, rgb):
    lightness, chroma, hue = gamut.lch(rgb)
    out = gamut.to_surface_gamut(rgb)
    if chroma <= gamut.bound(lightness, hue):
        assert out == rgb
        return
    if not all(1e-9 < c < 1.0 - 1e-9 for c in out):
        return  # clipped to the RGB cube: L*, h no longer exact
    l2, c2, h2 = gamut.lch(out)
    assert l2 == pytest.approx(lightness, abs=1e-6)
    assert c2 == pytest.approx(gamut.bound(lightness, hue), abs=1e-6)
    if c2 > 1e-3:
        assert abs((h2 - hue + 180) % 360 - 180) < 1e-4


def test_display_blue_is_outside_real_surfaces_and_comes_back_duller(gamut):
    blue = (0.000911, 0.056128, 0.73791)  # the xkcd survey's "blue", linear
    _, chroma, _ = gamut.lch(blue)
    out = gamut.to_surface_gamut(blue)
    assert gamut.lch(out)[1] < chroma - 10
    assert all(math.isfinite(c) and 0.0 <= c <= 1.0 for c in out)


def test_only_pigment_colours_of_pigmented_surfaces_move(bench):
    sg, cal = bench

    def compiled(phrase):
        material, error = cal.compile_phrase(phrase)
        assert material is not None, error
        return material

    rubber = compiled("blue rubber")
    assert sg.in_surface_gamut(rubber)["params"]["base_color"] != rubber["params"]["base_color"]
    assert rubber["params"]["base_color"] == compiled("blue rubber")["params"]["base_color"]  # a copy
    paint = compiled("blue metallic paint")
    assert sg.in_surface_gamut(paint)["params"]["flake_color"] == paint["params"]["flake_color"]
    for metal in ("gold", "copper"):
        assert sg.in_surface_gamut(compiled(metal)) == compiled(metal)
    glass = compiled("blue glass")
    assert sg.in_surface_gamut(glass) == glass


@pytest.mark.skipif(not MEASURED.exists(), reason="../shared/data/physicallybased_materials.json not present")
def test_measured_opaque_colours_lie_within_pointers_bound(bench, gamut):
    _, cal = bench
    items = json.loads(MEASURED.read_text("utf-8"))["data"]
    opaque = [i for i in items if not i.get("metalness") and not i.get("transmission") and cal.srgb_linear(i)]
    assert len(opaque) > 40
    ratios = []
    for item in opaque:
        lightness, chroma, hue = gamut.lch(cal.srgb_linear(item))
        if chroma > 5.0:
            ratios.append(chroma / gamut.bound(lightness, hue))
    assert len(ratios) > 20 and max(ratios) < 1.1  # ketchup, the most saturated, at 1.03
