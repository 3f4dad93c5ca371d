"""An ageing word draws what weather grows on the metal (adjectives `features_on`): 'weathered
copper' a verdigris patina, 'weathered steel' rust spots, more of it with a stronger degree, and
nothing on a metal that keeps a passive film (stainless steel, aluminium). The phrases here are not
in tests/language/everyday.toml."""

from __future__ import annotations

import tomllib
from pathlib import Path

import pytest

from cnlmc.api import compile_source, lexicon_for
from tests.helpers import load_module

LEX = lexicon_for()
EVERYDAY = load_module("everyday_bench", Path(__file__).resolve().parents[2] / "bench" / "everyday.py")
PHRASES = ["weathered bronze", "very weathered brass", "old wrought iron", "weathered aluminum", "weathered pine"]


def material(text: str) -> dict:
    result = compile_source(text, "t.cnl", LEX)
    assert result.ok and not [d for d in result.diagnostics if d.severity.name == "WARNING"], text
    return result.materials[0]


def graphs(m: dict) -> set[str]:
    return {ref["graph"] for ref in m["maps"].values()}


def test_the_phrases_here_are_not_in_the_everyday_set():
    data = tomllib.loads(Path(__file__).with_name("everyday.toml").read_text("utf-8"))
    assert not {row["text"].lower() for row in data["phrase"]} & {p.lower() for p in PHRASES}


@pytest.mark.parametrize(("text", "graph"), [("weathered bronze", "patina"), ("old wrought iron", "rust")])
def test_weather_grows_its_feature_on_the_metal(text, graph):
    m = material(text)
    assert graph in graphs(m) and graph not in graphs(material(text.split(" ", 1)[1]))
    drawn = [s for s in m["provenance"]["maps.mask"] if s["words"] == [text.split()[0]]]
    assert drawn and drawn[-1]["value"] == graph, m["provenance"]["maps.mask"]


def test_a_stronger_degree_covers_more():
    plain, strong = material("weathered brass"), material("very weathered brass")
    assert strong["maps"]["mask"]["params"]["coverage"] > plain["maps"]["mask"]["params"]["coverage"]


@pytest.mark.parametrize("text", ["weathered aluminum", "weathered stainless steel", "weathered pine"])
def test_no_patina_or_rust_where_weather_does_not_grow_one(text):
    assert not graphs(material(text)) & {"patina", "rust"}


# ---------------------------------------------------------------- fading keeps the hue (op 'mix')


@pytest.mark.parametrize(
    "colour", ["navy", "maroon", "forest green", "purple", "teal", "chocolate brown", "denim blue"]
)
def test_a_faded_dye_keeps_its_hue_and_pales(colour):
    dyed = material(f"{colour} cotton")["params"]["base_color"]
    faded = material(f"faded {colour} cotton")["params"]["base_color"]
    assert EVERYDAY.hue_family(faded) == EVERYDAY.hue_family(dyed), (dyed, faded)
    assert EVERYDAY.oklab(faded)[0] > EVERYDAY.oklab(dyed)[0]


def test_less_faded_moves_back_toward_the_dye():
    faded = material("faded navy cotton")["params"]["base_color"]
    result = compile_source("faded navy cotton\nless faded", "t.cnl", LEX)
    assert result.ok
    assert sum(result.materials[0]["params"]["base_color"]) < sum(faded)


# ---------------------------------------------------------------- the noun's own relief stays


@pytest.mark.parametrize("text", ["distressed aniline leather", "scratched leather", "battered cowhide leather"])
def test_a_wear_word_keeps_the_leather_grain_and_shows_in_the_roughness(text):
    m = material(text)
    assert m["maps"]["normal"]["graph"] == "leather"
    assert m["maps"]["roughness"]["graph"] == "scratched"


def test_a_wear_word_on_a_material_without_its_own_relief_draws_its_own():
    m = material("scratched walnut")
    assert m["maps"]["normal"]["graph"] == "scratched"
