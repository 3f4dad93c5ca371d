"""A comparative said against a named finish (issue #14, held-out sets 46, 49, 51: 'shinier than
satin'): the finish after 'than' is the finish, not the cloth, and the comparative lands part way
to the next finish of settings.toml finish_ladder (compiler/passes/finish_ladder.py)."""

from __future__ import annotations

import pytest

from tests.language.meaning import compiled, material


def roughness(text: str) -> float:
    return float(material(text)["params"]["roughness"])


@pytest.mark.parametrize(
    "said, low, high",
    [
        ("shinier than satin", 0.08, 0.35),  # between satin and glossy: a glossy surface
        ("duller than gloss", 0.08, 0.35),
        ("glossier than matte", 0.35, 0.8),
        ("rougher than satin", 0.35, 0.8),
        ("glossier than mirror", 0.0, 0.0100001),
    ],
)
def test_a_comparative_against_a_finish_lies_between_it_and_the_next(said, low, high):
    assert low < roughness(said) < high or roughness(said) == pytest.approx(high)


def test_shinier_than_satin_is_glossy_and_no_cloth():
    said = material("shinier than satin")
    assert said["params"]["roughness"] == pytest.approx((0.35 + 0.08) / 2)  # halfway: satin to glossy
    assert not said.get("maps")  # not satin cloth's weave
    result = compiled("shinier than satin")
    assert any("to the next finish" in step["rule"] for step in _provenance(result, "roughness"))


def _provenance(result, param: str) -> list[dict]:
    return result.ir["materials"][0].get("provenance", {}).get(param, [])


def test_the_adverbs_scale_how_far():
    slight, plain, much = (roughness(f"{a}shinier than satin") for a in ("a bit ", "", "much "))
    assert 0.35 > slight > plain > much >= 0.08


def test_a_comparative_against_a_material_still_steps_the_material():
    assert material("lighter than oak")["params"]["base_color"] != material("oak")["params"]["base_color"]


@pytest.mark.parametrize(
    "said, change",
    [("red paint, shinier than satin", None), ("oak, shinier than satin", None), ("red paint", "shinier than satin")],
)
def test_the_ladder_reads_the_comparison_after_a_material_and_on_a_change_line(said, change):
    from tests.language.meaning import refined

    found = refined(said, change).material if change else material(said)
    assert found["params"]["roughness"] == pytest.approx((0.35 + 0.08) / 2)


def test_a_comparative_with_its_finish_but_no_than_is_still_a_step():
    assert roughness("glossier satin") == pytest.approx(0.25)  # satin, then one step glossier


@pytest.mark.parametrize(
    "said, plain", [("more dark than oak", "darker oak"), ("more dark than normal oak", "darker oak")]
)
def test_more_with_a_shade_before_than_compares_as_the_comparative_does(said, plain):
    assert material(said)["params"]["base_color"] != material("oak")["params"]["base_color"]
    dark = material(said)["params"]["base_color"]
    assert sum(dark) < sum(material("oak")["params"]["base_color"])
