"""'colour' said as a label before the colour it names (issue #14, held-out sets 48 and 52: forms
and listings, English as a second language): cnlmc.joins Joiner._colour_label."""

from __future__ import annotations

import pytest

from tests.language.meaning import compiled, material, reads_as, same_look


@pytest.mark.parametrize(
    "said, plain",
    [
        ("plastic, colour red", "red plastic"),
        ("plastic colour red", "red plastic"),
        ("colour: red", "red"),
        ("colour red", "red"),
        ("leather, colour dark brown", "dark brown leather"),
        ("shell cordovan, colour burgundy", "burgundy shell cordovan"),
        ("sofa, color grey", "grey sofa"),
    ],
)
def test_a_colour_label_names_the_colour_after_it(said, plain):
    reads_as(said, plain, "naming the colour after it")


@pytest.mark.parametrize(
    "said, plain", [("cream colour paint", "cream paint"), ("the colour of sand paint", "sand colour paint")]
)
def test_a_colour_word_after_its_colour_is_no_label(said, plain):
    result = compiled(said)
    assert not any("naming the colour after it" in d.message for d in result.diagnostics)
    assert same_look(result.ir["materials"][0], material(plain))


@pytest.mark.parametrize("said", ["oak, clear colour", "wood of oak, clear colour", "clear colour oak"])
def test_clear_colour_is_a_light_colour_as_second_language_speakers_say_it(said):
    assert same_look(material(said), material("light oak"))
    assert material("clear glass")["model"]["base"] == "glass"  # 'clear' alone stays clear


@pytest.mark.parametrize(
    "said, meant",
    [
        ("white marble with grey", "white marble with grey veins"),
        ("marble, white with grey", "white marble with grey veins"),
        ("black granite with white", "black granite with white speckles"),
    ],
)
def test_a_colour_alone_in_a_with_clause_names_the_material_s_own_pattern(said, meant):
    result = compiled(said)
    assert result.ok and "W105" not in [d.code for d in result.diagnostics]
    assert any("own" in d.message and "with" in d.message for d in result.diagnostics)
    assert material(said)["maps"] == material(meant)["maps"]
    assert same_look(material(said), material(meant))


def test_a_colour_alone_in_a_with_clause_on_a_plain_material_is_still_a_second_colour():
    assert "W105" in [d.code for d in compiled("white plastic with black").diagnostics]


@pytest.mark.parametrize(
    "said, meant",
    [
        ("granite, speckled grey", "speckled grey granite"),
        ("stoneware, speckled oatmeal", "speckled oatmeal stoneware"),
    ],
)
def test_a_feature_then_a_colour_after_the_comma_reads_as_before_the_noun(said, meant):
    assert material(said)["maps"] == material(meant)["maps"]
    assert same_look(material(said), material(meant))
