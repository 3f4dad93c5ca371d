"""Which sense or kind is meant, said after a comma, and clauses that name a look (issue #14, held-out
sets 53 and 56: second-language speakers, bar fit-outs, restorers): cnlmc.sense_said and cnlmc.joins."""

from __future__ import annotations

import pytest

from tests.language.meaning import compiled, graphs, material, reads_as


@pytest.mark.parametrize(
    "said, plain",
    [
        ("teak, the colour not the wood", "teak colour"),
        ("teak, the colour", "teak colour"),
        ("oak, the color", "oak colour"),
    ],
)
def test_the_colour_sense_is_the_nouns_colour_on_paint(said, plain):
    reads_as(said, plain, "as its colour, as the line says")
    assert material(said)["model"] == material(plain)["model"] and not graphs(said)


@pytest.mark.parametrize(
    "said, plain",
    [
        ("emerald, the gem not just the colour", "emerald gem"),
        ("walnut, the wood not the colour", "walnut"),
    ],
)
def test_the_thing_sense_is_the_material_itself(said, plain):
    reads_as(said, plain, "itself, as the line says")
    assert material(said)["model"] == material(plain)["model"]


@pytest.mark.parametrize("said", ["glorp, the colour", "teak, the colour not the wood glorp"])
def test_a_sense_said_of_an_unknown_word_or_with_more_after_keeps_its_error(said):
    assert not compiled(said).ok


@pytest.mark.parametrize(
    "said, plain",
    [
        ("white marble tabletop, carrara type", "white carrara marble"),
        ("white marble, carrara", "white carrara marble"),
        ("marble, carrara kind", "carrara marble"),
    ],
)
def test_a_kind_of_the_material_after_the_comma_takes_its_place(said, plain):
    reads_as(said, plain, "(the kind named after the comma)")


def test_a_material_of_another_kind_after_the_comma_is_no_kind_of_it():
    assert not any("the kind named after the comma" in d.message for d in compiled("oak, walnut").diagnostics)


@pytest.mark.parametrize(
    "said, plain",
    [
        ("terrazzo with coloured chips", "terrazzo with colourful chips"),
        ("terrazzo with colored speckles", "terrazzo with colourful speckles"),
    ],
)
def test_coloured_before_a_feature_is_colourful(said, plain):
    reads_as(said, plain, "as colourful")


def test_coloured_after_a_colour_stays_its_head():
    result = compiled("red coloured plastic")
    assert result.ok and not [d for d in result.diagnostics if d.code.startswith("W")]


@pytest.mark.parametrize(
    "said, plain",
    [
        ("laminate with a wood grain effect", "laminate with wood grain"),
        ("laminate table top with a woodgrain effect", "laminate with wood grain"),
        ("white plastic with a speckle look", "white plastic with speckles"),
    ],
)
def test_a_feature_named_as_an_effect_is_the_feature(said, plain):
    reads_as(said, plain)
    assert graphs(said) == graphs(plain)


def test_what_the_material_is_ready_for_is_read_past():
    reads_as("sandblasted steel, ready for primer", "sandblasted steel", "read past")


# ---------------------------------------------------------------- a finish, then one it already is not


@pytest.mark.parametrize(
    "said, plain",
    [
        ("glossy paint but not mirror", "glossy paint"),
        ("satin paint but not glossy", "satin paint"),
        ("white paint, satin but not glossy", "white satin paint"),
        ("glossy paint but not matte", "glossy paint"),
    ],
)
def test_a_negated_finish_the_finish_said_already_excludes_is_read_past(said, plain):
    reads_as(said, plain, "already")
    assert not [d for d in compiled(said).diagnostics if d.code == "W101"]


def test_a_negated_finish_between_the_finish_and_the_middle_still_contradicts():
    assert "W101" in [d.code for d in compiled("glossy paint but not shiny").diagnostics]


def test_a_negated_finish_alone_is_still_its_opposite():
    assert material("not glossy paint")["params"]["roughness"] == material("matte paint")["params"]["roughness"]
