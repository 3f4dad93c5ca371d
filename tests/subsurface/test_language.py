"""Words that need light inside the body compile to the subsurface model; nothing else does
(docs/subsurface.md). Everything through cnlmc.api, checked against the typed IR."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from cnlmc.api import compile_source
from cnlmc.material import Document

DATA = Path(__file__).resolve().parents[3] / "shared" / "data" / "physicallybased_materials.json"

VOLUME = [
    "wax",
    "jade",
    "skin",
    "skin ii",
    "fair skin",
    "skin type v",
    "milk",
    "soap",
    "candle",
    "white candle",
    "marble",
    "porcelain",
    "crystallized honey",
    "cream",
    "translucent white plastic",
    "milky plastic",
    "waxy white plastic",
    "wax-like soap",
    "backlit marble",
]
THIN = ["leaf", "backlit leaf", "thin paper", "thin white paper", "backlit paper"]
NONE = [
    "oak",
    "white plastic",
    "copper",
    "clear glass",
    "honey",
    "gold leaf",
    "cream leather",
    "chrome with scratches",
    "waxed oak",
]


def material(phrase: str) -> dict:
    result = compile_source(phrase)
    assert result.ok, [d.message for d in result.diagnostics]
    Document.from_ir(result.ir)  # the typed IR accepts it
    return result.ir["materials"][0]


def codes(phrase: str) -> list[str]:
    return [d.code for d in compile_source(phrase).diagnostics]


@pytest.mark.parametrize("phrase", VOLUME)
def test_a_thick_translucent_body_is_a_volume(phrase):
    m = material(phrase)
    assert m["model"]["base"] == "dielectric" and m["model"]["subsurface"] == "volume"
    medium = m["params"]["subsurface"]
    assert medium["thickness"] is None and 0 < min(medium["radius"]) and max(medium["color"]) <= 1
    assert "ior" in m["params"]


@pytest.mark.parametrize("phrase", THIN)
def test_a_thin_sheet_is_thin(phrase):
    m = material(phrase)
    assert m["model"]["subsurface"] == "thin"
    assert 0 < m["params"]["subsurface"]["thickness"] < 0.01


@pytest.mark.parametrize("phrase", NONE)
def test_nothing_else_has_a_medium(phrase):
    m = material(phrase)
    assert "subsurface" not in m["model"] and "subsurface" not in m["params"]


def test_fitzpatrick_skin_tones_are_the_datasets():
    """Skin I..VI: physicallybased_materials.json's colour, and its subsurfaceRadius (cm) in metres."""
    if not DATA.exists():
        pytest.skip("../shared/data is not beside this checkout")
    entries = {e["name"]: e for e in json.loads(DATA.read_text())["data"]}
    for numeral in ("I", "II", "III", "IV", "V", "VI"):
        m = material(f"skin {numeral.lower()}")
        entry = entries[f"Skin {numeral}"]
        assert m["params"]["base_color"] == entry["color"][0]["color"]
        assert m["params"]["subsurface"]["radius"] == pytest.approx([r / 100 for r in entry["subsurfaceRadius"]])
    darker = [sum(material(f"skin {n}")["params"]["base_color"]) for n in ("i", "ii", "iii", "iv", "v", "vi")]
    assert darker == sorted(darker, reverse=True)


def test_marble_is_the_datasets_translucent_stone_and_keeps_its_veins():
    m = material("polished white marble")
    assert m["params"]["subsurface"]["radius"] == pytest.approx([0.00851, 0.00557, 0.00395])
    assert m["maps"]["base_color"]["graph"] == "marble"


def test_translucent_scales_the_mean_free_path_of_a_translucent_noun():
    assert material("translucent wax")["params"]["subsurface"]["radius"] == pytest.approx(
        [2 * r for r in material("wax")["params"]["subsurface"]["radius"]]
    )


def test_a_colour_word_tints_the_body_as_it_tints_the_surface():
    plain, white = material("candle"), material("white candle")
    assert white["params"]["base_color"] == [1.0, 1.0, 1.0]
    assert min(white["params"]["subsurface"]["color"]) > max(plain["params"]["subsurface"]["color"][2], 0.9)
    dark = material("dark green jade")["params"]["subsurface"]["color"]
    assert max(dark) < max(material("jade")["params"]["subsurface"]["color"])


def test_thin_makes_a_translucent_body_a_sheet_and_backlit_keeps_it_thick():
    assert material("thin wax")["model"]["subsurface"] == "thin"
    assert material("backlit wax")["model"]["subsurface"] == "volume"


def test_a_metal_lets_no_light_in():
    m = material("translucent copper")
    assert "subsurface" not in m["model"]
    assert "W150" in codes("translucent copper")


def test_translucent_glass_is_frosted_glass():
    m = material("translucent glass")
    assert m["model"]["base"] == "glass" and "subsurface" not in m["model"]
    assert m["params"]["roughness"] == material("frosted glass")["params"]["roughness"]


def test_the_medium_says_where_it_came_from():
    m = material("translucent milky wax")
    rules = [step["rule"] for step in m["provenance"]["subsurface"]]
    assert rules[0] == "nouns.wax" and "adjectives.translucent.subsurface" in rules


def test_more_and_less_translucent_move_the_mean_free_path():
    result = compile_source("a: wax\nmore translucent\nb: wax\nless translucent\nc: white plastic\nmore translucent\n")
    a, b, c = (m["params"].get("subsurface") for m in result.ir["materials"])
    wax = material("wax")["params"]["subsurface"]["radius"]
    assert a["radius"] == pytest.approx([2 * r for r in wax]) and b["radius"] == pytest.approx([r / 2 for r in wax])
    assert c is not None  # more translucent gives a plastic a medium
    assert "W150" in codes("copper\nmore translucent\n")
