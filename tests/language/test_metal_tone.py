"""A metal's name as the colour of another metal (issue #14, 'between two metals';
compiler/passes/metal_tone.py): the two metals' optics mixed, no tinted film over the metal.

Phrases here are deliberately not the ones of tests/language/everyday.toml.
"""

import math

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from cnlmc.bsdf.fresnel import f0_conductor

from .conftest import first
from .meaning import compiled

METALS = ["brass", "copper", "gold", "silver", "steel", "nickel", "titanium", "bronze", "aluminum", "zinc"]


def params(compile_text, text):
    return first(compile_text(text))


def test_a_hedged_metal_colour_is_half_way_to_that_metal(compile_text):
    brass, copper = params(compile_text, "brass"), params(compile_text, "copper")
    mixed = params(compile_text, "coppery brass")
    assert mixed["model"]["base"] == "conductor" and not mixed["model"]["coat"]
    for name in ("eta", "k"):
        for own, theirs, got in zip(brass["params"][name], copper["params"][name], mixed["params"][name]):
            assert got == pytest.approx((own + theirs) / 2)
    # what one sees: redder than brass (its green falls toward copper's), not the dark tint it had
    assert copper["params"]["f0"][1] < mixed["params"]["f0"][1] < brass["params"]["f0"][1]
    assert min(mixed["params"]["f0"]) > 0.4
    assert mixed["params"]["base_color"] == [1.0, 1.0, 1.0]


def test_the_plain_name_is_that_metal_and_a_degree_scales_the_share(compile_text):
    gold = params(compile_text, "gold")
    assert params(compile_text, "gold steel")["params"]["f0"] == pytest.approx(gold["params"]["f0"])
    assert params(compile_text, "brass-coloured zinc")["params"]["eta"] == pytest.approx(
        params(compile_text, "brass")["params"]["eta"]
    )
    brass = params(compile_text, "brass")["params"]["eta"][1]
    slightly = params(compile_text, "slightly coppery brass")["params"]["eta"][1]
    plain = params(compile_text, "coppery brass")["params"]["eta"][1]
    copper = params(compile_text, "copper")["params"]["eta"][1]
    assert brass < slightly < plain < copper


def test_f0_and_f82_are_the_exact_fresnel_of_the_mixed_constants(compile_text):
    p = params(compile_text, "silvery gold")["params"]
    for n, k, f0 in zip(p["eta"], p["k"], p["f0"]):
        assert f0 == pytest.approx(f0_conductor(n, k), abs=1e-4)
    assert all(0.0 < v <= 1.0 for v in p["f82"])


def test_between_two_metals_is_a_metal_whichever_is_said_first(compile_text):
    one = compile_text("somewhere between brass and copper")
    two = compile_text("halfway between copper and brass")
    assert one.ok and two.ok
    a, b = one.materials[0], two.materials[0]
    assert a["model"]["base"] == "conductor" and not a["model"]["coat"]
    assert a["params"]["eta"] == pytest.approx(b["params"]["eta"])
    assert any("brass-ish copper" in d.message for d in one.diagnostics)


def test_a_colour_that_names_no_metal_keeps_its_film(compile_text):
    """'blue aluminum' is an anodised or lacquered film, 'black steel' a black oxide: no metal is
    blue or black by its optics (issue #15 item 2)."""
    for text in ("blue aluminum", "black steel", "bronze paint"):
        material = first(compile_text(text))
        if material["model"]["base"] == "conductor":
            assert material["model"]["coat"]


def test_a_plating_said_after_the_colour_wins(compile_text):
    plated = params(compile_text, "titanium plated steel")["params"]["f0"]
    assert plated == params(compile_text, "titanium")["params"]["f0"]


@settings(max_examples=40, deadline=None)
@given(st.sampled_from(METALS), st.sampled_from(METALS), st.sampled_from(["", "somewhat ", "very "]))
def test_any_metal_toward_any_metal_is_a_finite_metal(toward, metal, degree):
    result = compiled(f"{degree}{toward}-ish {metal}")
    assert result.ok, [d.message for d in result.diagnostics]
    material = result.materials[0]
    assert material["model"]["base"] == "conductor"
    assert not material["model"]["coat"]
    for name in ("f0", "f82", "eta", "k"):
        assert all(math.isfinite(v) and v >= 0.0 for v in material["params"][name])
    assert all(v <= 1.0 for v in material["params"]["f0"] + material["params"]["f82"])


def test_a_hedged_colour_on_a_metal_is_a_cast_that_keeps_the_metal_hue(compile_text):
    """'bluish steel': half way from the metal's own colour to the word's, in OKLab; 'blue steel'
    keeps the full film colour (a blued or anodised film)."""
    cast = params(compile_text, "bluish titanium")["params"]["base_color"]
    full = params(compile_text, "blue titanium")["params"]["base_color"]
    assert cast[2] > cast[0] and min(cast) > min(full) + 0.1


def test_oxidised_iron_rusts_and_oxidised_silver_is_blackened(compile_text):
    iron = params(compile_text, "oxidised cast iron")
    assert iron["maps"]["base_color"]["graph"] == "rust"
    silver = params(compile_text, "oxidized silver")["params"]["base_color"]
    assert max(silver) < 0.3
    copper = params(compile_text, "oxidized copper")
    assert "base_color" not in (copper.get("maps") or {})  # darkened, no rust on copper
