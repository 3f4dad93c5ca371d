"""German word formation (issue #14): compounds, negation, degree prefixes and derived colours with
`--lexicon de`, by the rules in stdlib/overlays/de/word_formation.toml (the format of
stdlib/lexicon/word_formation.toml). A German phrase means what its English translation means,
and every inferred reading says so in a note. None of these phrases is in everyday.toml.
"""

from pathlib import Path

import pytest

from cnlmc.api import compile_source, lexicon_for
from cnlmc.colour import linear_to_oklab
from cnlmc.diagnostics import Severity
from tests.helpers import load_module

from .conftest import first

ROOT = Path(__file__).resolve().parents[2]
COMPOUNDS = ROOT / "stdlib" / "overlays" / "de" / "colours_compounds_de.toml"


gen_compounds = load_module("gen_de_colour_compounds", ROOT / "scripts" / "gen_de_colour_compounds.py")


@pytest.fixture(scope="module")
def de():
    return lexicon_for(("de",))


def compiled(text, lexicon):
    return compile_source(text, "de.cnl", lexicon)


def material(text, lexicon):
    return first(compiled(text, lexicon))


def same_look(a, b):
    return a["model"] == b["model"] and a["params"] == b["params"] and a["maps"] == b["maps"]


def notes(result):
    return [d.message for d in result.diagnostics if d.severity == Severity.NOTE]


def warnings(result):
    return [d.message for d in result.diagnostics if d.severity == Severity.WARNING]


def lightness(m):
    return linear_to_oklab(m["params"]["base_color"])[0]


# ---------------------------------------------------------------- compounds: material + object


@pytest.mark.parametrize(
    "german,english",
    [
        ("Buchenbretter", "beech planks"),
        ("Eichenparkett", "oak parquet"),
        ("Kiefernholzdielen", "pine floorboards"),
        ("Lärchenbalken", "larch beams"),
        ("Stahlträger", "steel beams"),
        ("Messinggriffe", "brass handles"),
        ("Aluminiumblech", "aluminium sheet"),
        ("Granitplatte", "granite slab"),
        ("Betonwand", "concrete wall"),
        ("Glasflasche", "glass bottle"),
        ("Terrakottafliesen", "terracotta tiles"),
        ("Lederjacke", "leather jacket"),
        ("Gummimatte", "rubber rug"),
        ("eiserne Geländer", "iron railings"),
        ("hölzerne Dielen", "wooden floorboards"),
        ("bronzene Statue", "bronze statue"),
        ("seidener Schal", "silk scarf"),
        ("marmorner Boden", "marble floor"),
    ],
)
def test_a_glued_material_and_object_is_the_material(de, german, english):
    result = compiled(german, de)
    assert same_look(first(result), material(english, de))
    assert notes(result) and not warnings(result), result.diagnostics


@pytest.mark.parametrize("german,english", [("Bretter", "boards"), ("Rohre", "pipes"), ("Geländer", "railings")])
def test_an_object_alone_is_its_usual_material(de, german, english):
    assert same_look(material(german, de), material(english, de))


def test_adjectives_before_a_compound_apply_to_its_material(de):
    assert same_look(material("geölte Buchenbretter", de), material("oiled beech planks", de))
    assert same_look(material("gebürstete Edelstahlrohre", de), material("brushed stainless steel pipes", de))


# ---------------------------------------------------------------- colours: glued shades, suffixes


@pytest.mark.parametrize("colour", ["rot", "blau", "grün", "grau", "braun", "gelb", "violett", "türkis", "beige"])
@pytest.mark.parametrize("noun", ["Kunststoff", "Samt"])
def test_dunkel_x_is_darker_and_hell_x_lighter_than_x(de, colour, noun):
    plain = lightness(material(f"{colour}er {noun}", de))
    dark = compiled(f"dunkel{colour}er {noun}", de)
    light = compiled(f"hell{colour}er {noun}", de)
    assert lightness(first(dark)) < plain < lightness(first(light))
    assert not warnings(dark) and not warnings(light)


@pytest.mark.parametrize(
    "german,english",
    [
        ("mattschwarzer Stahl", "matte black steel"),
        ("goldfarbenes Glas", "gold glass"),
        ("ockerfarbener Putz", "ochre plaster"),
        ("silberfarbige Keramik", "silver ceramic"),
    ],
)
def test_glued_and_derived_colour_words(de, german, english):
    result = compiled(german, de)
    assert same_look(first(result), material(english, de))
    assert notes(result) and not warnings(result)


@pytest.mark.parametrize(
    "german,english",
    [
        ("rotbraunes Leder", "red brown leather"),
        ("blaugraue Keramik", "blue grey ceramic"),
        ("blau-graue Keramik", "blue-grey ceramic"),
        ("graugrüner Filz", "grey green felt"),
        ("rötlichbraunes Holz", "reddish brown wood"),
        ("dunkelblaues Leinen", "dark blue linen"),
        ("tiefschwarzer Samt", "deep black velvet"),
        ("blassrosa Seide", "pale pink silk"),
        ("knallroter Kunststoff", "bright red plastic"),
    ],
)
def test_a_glued_colour_compound_is_the_english_compound(de, german, english):
    """Two colours glued are one colour (the survey's compound or its OKLab mix), never a W105."""
    result = compiled(german, de)
    assert same_look(first(result), material(english, de))
    assert not warnings(result), result.diagnostics


def test_the_generated_colour_compounds_are_up_to_date():
    assert COMPOUNDS.read_text("utf-8") == gen_compounds.generate(), "rerun scripts/gen_de_colour_compounds.py"


# ---------------------------------------------------------------- negation and degree prefixes


@pytest.mark.parametrize(
    "german,english",
    [
        ("nicht polierter Stahl", "not polished steel"),
        ("unpolierter Stahl", "unpolished steel"),
        ("nicht lackierte Buche", "not lacquered beech"),
        ("unlackierte Buche", "unlacquered beech"),
        ("unbeschichtetes Aluminium", "uncoated aluminum"),
        ("nicht zu glänzendes Kupfer", "not too glossy copper"),
        ("nicht sehr rauer Sandstein", "not very rough sandstone"),
        ("nicht ganz glatter Beton", "slightly smooth concrete"),
        ("gar nicht glänzendes Acryl", "not glossy at all acrylic"),
        ("überhaupt nicht polierter Stahl", "not at all polished steel"),
        ("halbmatte Keramik", "semi-matte ceramic"),
        ("halb matte Keramik", "semi matte ceramic"),
    ],
)
def test_negation_and_degree_prefixes_mean_what_the_english_ones_mean(de, german, english):
    result = compiled(german, de)
    assert same_look(first(result), material(english, de))
    assert notes(result), result.diagnostics


def test_nicht_glaenzend_is_matter_than_glaenzend(de):
    shiny = material("glänzendes Acryl", de)["params"]["roughness"]
    assert material("nicht glänzendes Acryl", de)["params"]["roughness"] > shiny
    assert material("nicht glänzendes Acryl", de)["params"]["roughness"] > material("Acryl", de)["params"]["roughness"]


def test_a_word_no_rule_reads_is_still_an_error_with_its_position(de):
    result = compiled("Quxdielen", de)
    assert not result.ok
    error = next(d for d in result.diagnostics if d.severity == Severity.ERROR)
    assert error.code == "E001" and "Quxdielen" in error.message and error.span.col == 1


@pytest.mark.parametrize(
    "german,english",
    [("Lehmputz", "plaster"), ("Zementputz", "plaster"), ("Acrylfarbe", "paint"), ("Glaskeramik", "ceramic")],
)
def test_two_glued_materials_are_the_last_one(de, german, english):
    """German compounds are right-headed: Lehmputz is a plaster (made of clay), noted."""
    result = compiled(german, de)
    assert same_look(first(result), material(english, de))
    assert any("made of" in n for n in notes(result)) and not warnings(result)


def test_the_german_compound_classes_keep_the_english_ones(de):
    """settings_de.toml replaces the stdlib's list: it must still hold every English pair."""
    english = lexicon_for().settings["compound_classes"]
    assert set(english) <= set(de.settings["compound_classes"])
