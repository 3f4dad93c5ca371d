"""Clear and frosted plastics are transparent (issues #14, #15): 'clear acrylic' compiles to the
glass model with the plastic's own IOR; a plastic without 'clear' or 'frosted' stays opaque."""

from __future__ import annotations

import pytest

from cnlmc import api


def _material(phrase: str) -> dict:
    result = api.compile_source(phrase, "<phrase>")
    assert not [d for d in result.diagnostics if d.severity.value in ("error", "warning")], result.diagnostics
    return result.materials[0]


@pytest.mark.parametrize(
    "phrase", ["clear acrylic", "transparent polycarbonate", "clear pmma", "transparent white plastic"]
)
def test_a_clear_plastic_is_the_glass_model_with_its_own_ior(phrase: str) -> None:
    m = _material(phrase)
    assert m["model"]["base"] == "glass"
    assert m["params"]["base_color"] == [1.0, 1.0, 1.0]
    noun = phrase.split()[-1]
    assert m["params"]["ior"] == _material(noun)["params"]["ior"]


def test_frosted_plastic_is_translucent_and_takes_a_colour_after_the_frosting() -> None:
    frosted, blue = _material("frosted acrylic"), _material("frosted blue acrylic")
    assert frosted["model"]["base"] == blue["model"]["base"] == "glass"
    assert frosted["params"]["roughness"] == pytest.approx(0.5)
    assert blue["params"]["base_color"][2] > 2 * blue["params"]["base_color"][0]


@pytest.mark.parametrize("phrase", ["white acrylic", "glossy black acrylic", "nylon", "matte abs"])
def test_a_plastic_without_clear_or_frosted_stays_opaque(phrase: str) -> None:
    assert _material(phrase)["model"]["base"] != "glass"
