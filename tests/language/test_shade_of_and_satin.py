"""'a shade of blue', 'a darker shade of green velvet' (issue #14: colour phrasing people use) and
satin, the lustrous weave (a satin cloth reads as satin, not as a matte cloth)."""

from __future__ import annotations

import pytest

from cnlmc.api import compile_source, lexicon_for


def material(text: str) -> dict:
    result = compile_source(text + "\n", "t.cnl", lexicon_for())
    assert result.ok and result.materials, [d.message for d in result.diagnostics]
    return result.materials[-1]


def same_look(a: dict, b: dict) -> bool:
    return a["model"] == b["model"] and a["params"] == b["params"] and a.get("maps") == b.get("maps")


@pytest.mark.parametrize(
    ("said", "typed"),
    [
        ("a shade of blue", "blue"),
        ("a darker shade of green velvet", "darker green velvet"),
        ("a lighter shade of grey plastic", "lighter grey plastic"),
        ("oak\na paler shade of brown", "oak\npaler brown"),
    ],
)
def test_a_shade_of_a_colour_is_that_colour(said: str, typed: str) -> None:
    assert same_look(material(said), material(typed))


def test_satin_cloth_is_lustrous() -> None:
    satin, silk = material("red satin ribbon"), material("red silk")
    assert 0.25 <= satin["params"]["roughness"] <= 0.5  # the satin band of the everyday set
    assert satin["params"]["roughness"] < silk["params"]["roughness"]  # the weave that shines
    assert material("satin")["params"]["sheen_color"] is not None


@pytest.mark.parametrize(
    ("said", "typed"),
    [
        ("the colour of sand", "sand colour"),
        ("the colour of sand paint", "sand colour paint"),
        ("the color of honey", "honey color"),
        ("the colour of butter", "butter"),
        ("linen in the colour of sand", "sand colour linen"),
    ],
)
def test_the_colour_of_a_thing_is_its_colour(said: str, typed: str) -> None:
    """'the colour of X' is 'X colour' (the named colour nearest X's own, or X when it is a colour),
    with a note; a material named after it is what has the colour."""
    result = compile_source(said + "\n", "t.cnl", lexicon_for())
    assert result.ok and any("read 'the colo" in d.message for d in result.diagnostics)
    assert same_look(material(said), material(typed))
