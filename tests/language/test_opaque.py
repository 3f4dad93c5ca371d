"""'opaque' and 'non-transparent' (adjectives_translucent.toml) say no light passes: a plastic
stays the opaque plastic it is, glass is read as frosted, and after 'clear' it contradicts (W101)
and wins. The phrases here are not in tests/language/everyday.toml."""

from __future__ import annotations

import tomllib
from pathlib import Path

from cnlmc.api import compile_source, lexicon_for

LEX = lexicon_for()
PHRASES = ["non-transparent acrylic", "opaque polycarbonate", "clear opaque acrylic", "opaque window glass"]


def material(text: str):
    return compile_source(text, "t.cnl", LEX)


def test_the_phrases_here_are_not_in_the_everyday_set():
    data = tomllib.loads(Path(__file__).with_name("everyday.toml").read_text("utf-8"))
    assert not {row["text"].lower() for row in data["phrase"]} & {p.lower() for p in PHRASES}


def test_an_opaque_plastic_lets_no_light_through():
    for text in ("non-transparent acrylic", "opaque polycarbonate"):
        assert material(text).materials[0]["model"]["base"] == "dielectric", text


def test_opaque_after_clear_contradicts_and_wins():
    result = material("clear opaque acrylic")
    assert [d.message for d in result.diagnostics if d.code == "W101"] == [
        "'opaque' contradicts 'clear': 'opaque' wins"
    ]
    assert result.materials[0]["model"]["base"] == "dielectric"


def test_opaque_glass_is_opal_glass():
    """Opaque glass is opal (milk) glass: a glossy surface over a body that lets no light through."""
    said = material("opaque window glass").materials[0]
    assert said["model"]["base"] == "dielectric"
    assert said["params"]["roughness"] <= 0.05
    assert min(said["params"]["base_color"]) > 0.7  # white unless a colour is named
    green = material("opaque green glass").materials[0]
    assert (
        green["model"]["base"] == "dielectric"
        and green["params"]["base_color"][1] > 2 * green["params"]["base_color"][0]
    )


def test_not_transparent_is_opaque_not_frosted():
    said = material("not transparent glass").materials[0]
    assert said["model"]["base"] == "dielectric"
    assert said["params"] == material("opaque glass").materials[0]["params"]
