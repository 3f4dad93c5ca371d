"""'but' and 'yet' between describing words join them as 'and' does ('chrome, but slightly satin');
laid tiles are drawn with grout however the tile is named; an object after an unknown word adds no
second error."""

from __future__ import annotations

import pytest

from cnlmc.api import compile_source

from .conftest import look


@pytest.mark.parametrize(
    ("said", "meant"),
    [
        ("chrome, but slightly satin", "chrome, slightly satin"),
        ("walnut, yet matte", "matte walnut"),
        ("smooth yet matte black paint", "smooth, matte black paint"),
        ("dark, but warm oak", "dark, warm oak"),
        ("shiny, but not rusty, iron", "shiny iron"),
    ],
)
def test_a_contrast_word_joins_describing_words(stdlib, said, meant):
    assert look(stdlib, said)[1] == look(stdlib, meant)[1]


def test_but_alone_is_not_a_material(stdlib):
    assert not compile_source("but\n", "c.cnl", stdlib).ok


@pytest.mark.parametrize("phrase", ["glossy white ceramic tiles", "ceramic tiles", "white tiles", "porcelain tiles"])
def test_laid_tiles_have_grout(stdlib, phrase):
    material = compile_source(phrase + "\n", "t.cnl", stdlib).ir["materials"][0]
    assert material["maps"]["base_color"]["graph"] == "tiles"


def test_one_tile_named_as_a_material_is_its_glaze(stdlib):
    assert compile_source("white ceramic tile\n", "t.cnl", stdlib).ir["materials"][0]["maps"] == {}


@pytest.mark.parametrize("phrase", ["blorf tiles", "blorf planks", "blorf floor"])
def test_an_object_after_an_unknown_word_adds_no_second_error(stdlib, phrase):
    assert [d.code for d in compile_source(phrase + "\n", "u.cnl", stdlib).diagnostics] == ["E001"]


@pytest.mark.parametrize(
    ("said", "meant"),
    [
        ("Walnut / Satin Lacquer", "walnut with a satin lacquer"),
        ("Walnut, satin lacquer", "walnut with a satin lacquer"),
        ("Beech - clear varnish", "beech with a clear varnish"),
        ("Oak / Natural Oil", "oiled oak"),
        ("Steel / brushed", "brushed steel"),
    ],
)
def test_a_listings_finish_after_its_material(stdlib, said, meant):
    """A product listing names the material, a comma, slash or dash, then its finish: the material
    with that finish (before, 'Walnut, satin lacquer' was a walnut-coloured lacquer, no grain)."""
    result, meaning = look(stdlib, said)
    assert meaning == look(stdlib, meant)[1]
    assert any("the finish after the material" in d.message for d in result.diagnostics)


@pytest.mark.parametrize("phrase", ["red/blue paint", "oak/walnut", "brushed/polished steel"])
def test_a_slash_between_alternatives_stays_or(stdlib, phrase):
    assert len(compile_source(phrase + "\n", "o.cnl", stdlib).ir["materials"]) == 2


@pytest.mark.parametrize("sep", [", and", ", but", "; and", " and", " but", ","])
@pytest.mark.parametrize("first", ["oak", "red plastic"])
def test_a_two_word_separator_between_comparatives_or_clauses_reads(stdlib, sep, first):
    """'darker, and warmer' raised a KeyError (a separator of two words read as a comparative); a
    clause list may take ', and' too ('with a clear coat, and fine scratches')."""
    changed = compile_source(f"{first}\ndarker{sep} warmer\n", "s.cnl", stdlib)
    assert changed.ok and changed.ir["materials"][-1]["params"] != look(stdlib, first)[1]["params"]
    clauses = compile_source(f"{first} with a clear coat{sep} fine scratches\n", "s.cnl", stdlib)
    assert clauses.ok, [d.message for d in clauses.diagnostics]
