"""A colour word keeps a pattern visible (issue #14 item 1: "black granite keeps its speckles"):
the named colour's OKLab lightness is held inside the lexicon's band when the base colour feeds a
procedural map, and the baked colour map still varies."""

from __future__ import annotations

import pytest

from cnlmc import api, colour


def _compiled(phrase: str):
    result = api.compile_source(phrase, "<phrase>")
    assert not [d for d in result.diagnostics if d.severity.value in ("error", "warning")], result.diagnostics
    return result


@pytest.mark.parametrize("phrase", ["black granite", "polished black granite", "black marble", "jet black slate"])
def test_black_on_a_pattern_is_a_near_black_with_a_note(phrase: str) -> None:
    result = _compiled(phrase)
    lightness = colour.linear_to_oklab(result.materials[0]["params"]["base_color"])[0]
    assert lightness == pytest.approx(0.3, abs=0.01)
    steps = result.materials[0]["provenance"]["base_color"]
    assert any("stays visible" in str(step) for step in steps)


@pytest.mark.parametrize("phrase", ["black plastic", "black rubber", "white paint"])
def test_a_colour_on_a_uniform_material_is_as_named(phrase: str) -> None:
    result = _compiled(phrase)
    assert not any("stays visible" in str(step) for step in result.materials[0]["provenance"]["base_color"])
    lightness = colour.linear_to_oklab(result.materials[0]["params"]["base_color"])[0]
    assert lightness < 0.05 or lightness > 0.99


def test_the_baked_colour_map_of_black_granite_still_varies() -> None:
    from cnlmc.backends.maps.service import bake_arrays

    material = _compiled("black granite").document.materials[0]
    arrays = bake_arrays(material, size=64, seed=0, roles=["base_color"])
    luma = arrays["base_color"][..., :3].mean(axis=-1)
    assert luma.max() > 1e-3 and luma.std() > 0.2 * luma.mean()  # crystals, not one flat value
