"""Hedged and clipped speech (issue #14, cnlmc.hedges): a quantity before a feature is its degree,
a clause said without 'with' is a clause, a tint keeps the material's own colour."""

from __future__ import annotations

import pytest

from cnlmc.api import compile_source, lexicon_for
from cnlmc.colour import linear_to_oklab

LEX = lexicon_for()


def compiled(text: str):
    result = compile_source(text + "\n", "t.cnl", LEX)
    return result, [d for d in result.diagnostics if d.is_error]


def material(text: str) -> dict:
    result, errors = compiled(text)
    assert not errors, [e.message for e in errors]
    assert not [d for d in result.diagnostics if d.code.startswith("W")], [d.message for d in result.diagnostics]
    return result.ir["materials"][-1]


def notes(text: str) -> list[str]:
    return [d.message for d in compiled(text)[0].diagnostics if d.code == "N101"]


def rough(text: str) -> float:
    return material(text)["params"]["roughness"]


@pytest.mark.parametrize(
    ("hedged", "plain"),
    [
        ("pine with a touch of sheen", "pine with a slight sheen"),
        ("iron with a bit of rust", "iron with slightly rust"),
        ("bronze with just a hint of patina", "bronze with barely patina"),
        ("bronze with heaps of patina", "bronze with many patina"),
        ("slate with a trace of sheen", "slate with barely sheen"),
    ],
)
def test_a_quantity_before_a_feature_is_its_degree(hedged, plain):
    assert material(hedged)["params"] == material(plain)["params"]
    said = hedged.split(" with ", 1)[1].rsplit(" ", 1)[0]
    assert any(n.startswith(f"read '{said}' as '") for n in notes(hedged)), notes(hedged)


def test_the_quantity_orders_the_degree():
    """barely < slightly < (the feature) < many: more rust, more roughness on iron."""
    rs = [rough(f"iron with {q} rust") for q in ("just a hint of", "a bit of", "some", "loads of")]
    assert rs == sorted(rs) and len(set(rs)) == 4, rs


def test_a_quantity_word_the_lexicon_does_not_know_is_read_with_its_phrase():
    result, errors = compiled("bronze with tons of patina")
    assert not errors and not [d for d in result.diagnostics if d.code == "E001"]


def test_a_clause_without_with_under_a_material_adds_the_clause():
    with_it = material("matte grey plastic\nwith a faint sheen")
    without = material("matte grey plastic\na faint sheen")
    assert without["params"] == with_it["params"]
    assert "read 'a faint sheen' as 'with a faint sheen'" in notes("matte grey plastic\na faint sheen")


@pytest.mark.parametrize(
    ("line", "noun"),
    [
        ("a faint sheen", "paint"),
        ("some patina", "copper"),
        ("with dark veins", "marble"),
        ("a few rust spots", "steel"),
    ],
)
def test_a_clause_as_the_first_line_takes_its_example_material(line, noun):
    """A feature of any surface goes on paint; a feature with its own material on that material."""
    said = material(line)
    assert said["name"].startswith(noun + "_with"), said["name"]
    assert any(n.startswith(f"no material named: read '{line}' as '{noun} ") for n in notes(line)), notes(line)


def test_a_finish_compared_is_a_change_line():
    changed = material("red plastic\na smoother, shinier finish")
    assert changed["params"] == material("red plastic\nsmoother, shinier")["params"]
    assert changed["params"]["roughness"] < material("red plastic")["params"]["roughness"]


def _oklab(text: str) -> list[float]:
    return linear_to_oklab(material(text)["params"]["base_color"])


def test_a_tint_keeps_the_own_colour():
    """'grey with a green tint' is a greenish grey: lighter and less saturated than green, its hue green's."""
    grey, green, tinted = _oklab("grey paint"), _oklab("green paint"), _oklab("grey paint with a green tint")
    assert abs(tinted[0] - grey[0]) < abs(green[0] - grey[0])
    chroma = [(c[1] ** 2 + c[2] ** 2) ** 0.5 for c in (grey, green, tinted)]
    assert chroma[0] < chroma[2] < chroma[1] / 2
    assert tinted[1] * green[1] > 0 and tinted[2] * green[2] > 0  # the same quadrant of hue


def test_a_hint_is_less_than_a_tint_and_says_no_second_colour():
    white = _oklab("white paint")
    hint, tint = _oklab("white paint with a hint of red"), _oklab("white paint with a red tint")
    assert 0 < hint[1] - white[1] < tint[1] - white[1]
    assert white[0] - hint[0] < 0.05  # a blush, not a pink
    result, _ = compiled("white paint with a hint of red")
    assert "W105" not in {d.code for d in result.diagnostics}


def test_glass_takes_a_tint_as_its_colour():
    """A glass's colour is its transmittance: 'a blue tint' is blue glass, as 'blue tinted glass'."""
    assert material("glass with a blue tint")["params"]["base_color"] == material("blue glass")["params"]["base_color"]


@pytest.mark.parametrize(
    ("said", "meant"),
    [
        ("keep the colour, make it glossier", "glossier"),
        ("same colour but rougher", "rougher"),
        ("keep everything else, just make it matte", "make it matte"),
        ("more towards green", "more green"),
    ],
)
def test_a_change_line_says_what_stays_and_what_changes(said, meant):
    """What is kept is read past with a note; the change is made."""
    first = "satin blue ceramic\n"
    changed, plain = material(first + said), material(first + meant)
    assert changed["params"] == plain["params"]
    assert changed["params"] != material(first.strip())["params"]


def test_a_verb_with_a_particle_and_a_degree_after_the_pronoun():
    """'polish it up a bit' = 'polish it a bit' = a bit polished; the particle is read past."""
    first = "brushed aluminium\n"
    up, plain = material(first + "polish it up a bit"), material(first + "polish it a bit")
    assert up["params"] == plain["params"] and up["maps"] == plain["maps"]
    rough = [material(first + line)["params"]["roughness"] for line in ("polish it", "polish it a bit")]
    assert rough[0] < rough[1] < material(first.strip())["params"]["roughness"]


def test_whole_milk_is_whiter_and_less_deep_than_skim_milk():
    """Jensen et al. 2001: whole milk scatters about three times as much as skim milk."""
    whole, skim = material("full-fat milk")["params"], material("skim milk")["params"]
    assert linear_to_oklab(whole["base_color"])[0] > linear_to_oklab(skim["base_color"])[0]
    whole_ir, skim_ir = material("full-fat milk"), material("skim milk")
    radii = [m["params"]["subsurface"]["radius"] for m in (whole_ir, skim_ir)]
    assert all(w < s for w, s in zip(*radii)), radii


@pytest.mark.parametrize(
    ("said", "compound"),
    [
        ("somewhere between khaki and grey", "khaki-grey"),
        ("halfway between teal and navy velvet", "teal-navy velvet"),
        ("a colour between lilac and grey, matte", "lilac-grey, matte"),
    ],
)
def test_between_two_colours_is_their_compound(said, compound):
    result, errors = compiled(said)
    assert not errors, [e.message for e in errors]
    assert result.ir["materials"][0]["params"] == material(compound)["params"]
    assert any(n.startswith("read '") and n.endswith(f" as '{compound.split()[0].rstrip(',')}'") for n in notes(said))


def test_a_hyphenated_pair_of_everyday_colours_is_their_oklab_midpoint():
    """'taupe-green' is one colour between taupe and green (no second-colour warning); spaced apart,
    two colours still warn."""
    pair = _oklab("taupe-green paint")
    ends = [_oklab(f"{c} paint") for c in ("taupe", "green")]
    assert all(min(a, b) - 1e-6 <= m <= max(a, b) + 1e-6 for m, a, b in zip(pair, *ends))
    result, _ = compiled("cream navy paint")
    assert "W105" in {d.code for d in result.diagnostics}


def test_a_finish_compared_as_the_first_line_is_paint_one_step_along():
    said = material("a shinier finish")
    assert said["params"] == material("shinier paint")["params"]
    assert said["params"]["roughness"] < material("paint")["params"]["roughness"]


@pytest.mark.parametrize(("serving", "liquid"), [("a glass of cola", "cola"), ("a pint of lager", "lager")])
def test_a_serving_of_a_liquid_is_the_liquid(serving, liquid):
    assert material(serving)["params"] == material(liquid)["params"]


@pytest.mark.parametrize(
    ("food", "looks_as"),
    [
        ("a pint of porter", "cola"),
        ("oat milk", "milk"),
        ("raspberry jam", "cranberry juice"),
        ("royal icing", "toothpaste"),
    ],
)
def test_food_and_drink_look_as_the_measured_material_they_resemble(food, looks_as):
    """nouns_food.toml: each takes the dataset values of what it looks like, saying so in its source."""
    said, like = material(food), material(looks_as)
    assert said["params"] == like["params"] and said["model"] == like["model"]


def test_comparatives_listed_as_the_first_line_move_their_colour_on_paint():
    """'a darker, moodier green': green paint, then darker, then moodier (the colour first)."""
    listed = _oklab("a darker, moodier green")
    green, darker = _oklab("green paint"), _oklab("darker green paint")
    assert listed[0] < darker[0] < green[0]
    assert any("comparisons as the first line" in n for n in notes("a darker, moodier green"))


@pytest.mark.parametrize(
    ("listing", "plain"), [("walnut, oiled finish", "oiled walnut"), ("Oak - Natural Finish", "natural oak")]
)
def test_a_product_listing_finish_after_the_noun_is_its_describing_word(listing, plain):
    assert material(listing)["params"] == material(plain)["params"]
