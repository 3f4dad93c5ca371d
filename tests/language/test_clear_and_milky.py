"""'clear' is see-through: untinted and smooth, the opposite of frosted ('make it clearer' takes
frost off); coffee with milk is opaque (milk's scattering medium), black coffee a clear liquid."""

from __future__ import annotations

from cnlmc.api import compile_source


def last(text: str):
    return compile_source(text, "c.cnl").ir["materials"][-1]


def test_clearer_takes_the_frost_off():
    frosted = last("frosted glass\n")["params"]["roughness"]
    assert last("frosted glass\nmake it clearer\n")["params"]["roughness"] < frosted
    assert frosted > last("frosted glass\na bit clearer\n")["params"]["roughness"] > 0.0


def test_clear_plastic_is_smooth_glass():
    params = last("transparent white plastic\n")["params"]
    assert params["roughness"] == 0.0 and params["base_color"] == [1.0, 1.0, 1.0]


def test_coffee_with_milk_is_opaque_and_black_coffee_clear():
    for phrase in ("milky coffee", "coffee with milk", "a caffe latte"):
        material = last(phrase + "\n")
        assert material["model"]["base"] == "dielectric" and material["model"].get("subsurface") == "volume", phrase
    assert last("black coffee\n")["model"]["base"] == "glass"
    assert last("dead flat white\n")["model"].get("subsurface") is None  # matte white paint, not the coffee
