"""Categories of everyday phrasing brought by held-out sets 36-37 (issue #14): the thing first in a
listing ('sofa, green velvet'), possessives and courtesy inside a line, 'X looking', a colour then
a feature ('white, a touch of sheen'), noun-first words before a clause, a complaint run on after
a change."""

from __future__ import annotations

import pytest

from tests.language.meaning import compiled, material, refined, same_look


def problems(text: str) -> list[str]:
    return [d.code for d in compiled(text).diagnostics if d.severity.value in ("error", "warning")]


def notes(text: str) -> list[str]:
    return [d.message for d in compiled(text).diagnostics if d.severity.value == "note"]


@pytest.mark.parametrize(
    ("said", "same_as", "thing"),
    [
        ("sofa, green velvet", "green velvet", "sofa"),
        ("tabletop, oiled oak", "oiled oak", "tabletop"),
        ("kitchen worktop, black granite", "black granite", "worktop"),
        ("the chair, oak", "oak", "chair"),
        ("our worktop, white marble", "white marble", "worktop"),
    ],
)
def test_a_thing_first_in_a_listing_names_what_the_material_is_for(said, same_as, thing):
    assert problems(said) == []
    assert same_look(material(said), material(same_as))
    assert f"read '{thing}' as saying how or what for, not what: the material is named later" in notes(said)


def test_a_thing_after_other_words_keeps_its_comma_reading():
    """The comma goes with the thing only where the thing opens the line: 'oak chair, oiled' is the
    oiled oak of the chair."""
    assert same_look(material("oak chair, oiled"), material("oiled oak"))


@pytest.mark.parametrize(
    ("said", "same_as"),
    [
        ("my oak", "oak"),
        ("my front door, dark blue", "front door, dark blue"),
        ("our brushed steel", "brushed steel"),
    ],
)
def test_a_possessive_is_a_determiner(said, same_as):
    assert problems(said) == []
    assert same_look(material(said), material(same_as))


def test_courtesy_inside_a_line_is_read_past():
    said = "no gloss please, matt dark green"
    assert problems(said) == []
    assert same_look(material(said), material("no gloss, matt dark green"))
    assert "read past 'please': a phrase names the material only, so politeness is left out" in notes(said)


def test_courtesy_alone_is_still_not_a_material():
    assert "E001" in problems("please please")


@pytest.mark.parametrize(
    ("said", "same_as"),
    [
        ("rusty looking iron", "rusty iron"),
        ("old looking oak", "old oak"),
        ("kinda rusty looking iron", "kinda rusty iron"),
    ],
)
def test_x_looking_with_a_space_is_x(said, same_as):
    assert problems(said) == []
    assert same_look(material(said), material(same_as))


@pytest.mark.parametrize(
    ("said", "same_as"),
    [
        ("white, a touch of sheen", "white paint with a touch of sheen"),
        ("off white, some sheen", "off white paint with some sheen"),
        ("matte black, some scratches", "matte black paint with some scratches"),
        ("dark grey, fine speckles", "dark grey paint with fine speckles"),
        ("leather, bit of a sheen", "leather with a bit of a sheen"),
    ],
)
def test_a_colour_then_a_feature_is_the_implied_material_with_its_clause(said, same_as):
    assert problems(said) == []
    assert same_look(material(said), material(same_as))


def test_the_implied_material_and_its_clause_are_one_note():
    assert (
        "no material named: read 'white' as 'white paint'; read ', slightly sheen' as 'with slightly sheen'"
        in notes("white, a touch of sheen")
    )


@pytest.mark.parametrize(
    ("said", "same_as", "read"),
    [
        (
            "paint mostly matte, a little sheen",
            "paint, mostly matte, a little sheen",
            "read 'paint mostly matte, a little sheen' as 'mostly matte paint, a little sheen' (describing words go before the noun)",
        ),
        (
            "steel brushed, light scratches",
            "brushed steel with light scratches",
            "read 'steel brushed, light scratches' as 'brushed steel, light scratches' (describing words go before the noun)",
        ),
    ],
)
def test_noun_first_words_before_a_clause_after_a_comma(said, same_as, read):
    assert "E002" not in problems(said)
    assert same_look(material(said), material(same_as))
    assert read in notes(said)


def test_a_comma_before_the_noun_keeps_the_lines_own_reading():
    assert problems("oak, satin") == []
    assert not any("describing words go before the noun" in n for n in notes("oak, satin"))


@pytest.mark.parametrize("line", ["lighter please its too dark", "lighter it's too dark"])
def test_a_complaint_run_on_after_a_change_is_read_as_its_own_part(line):
    before = refined("walnut").material["params"]["base_color"]
    after = refined("walnut", line).material["params"]["base_color"]
    assert sum(after) > sum(before)


def test_a_likeness_is_not_cut_before_its_pronoun():
    """'like it's been waxed' has no complaint in it: no comma is put before 'it's'."""
    from cnlmc.api import _comma_before_complaint

    assert _comma_before_complaint("like it's been waxed", ["it's"]) == "like it's been waxed"
    assert _comma_before_complaint("lighter its too dark", ["its"]) == "lighter, its too dark"


@pytest.mark.parametrize(
    ("said", "same_as", "note"),
    [
        ("brushed stainless steal", "brushed stainless steel", "read 'steal' as 'steel' (a word that sounds the same)"),
        ("guilt frame", "gilt frame", "read 'guilt' as 'gilt' (a word that sounds the same)"),
        ("laquered oak", "lacquered oak", "read 'laquered' as 'lacquered' (a word that sounds the same)"),
    ],
)
def test_a_word_a_spell_checker_leaves_reads_as_the_word_it_sounds_like(said, same_as, note):
    assert problems(said) == []
    assert same_look(material(said), material(same_as))
    assert note in notes(said)


@pytest.mark.parametrize("said", ["green copper", "copper roof gone green with age", "blue green bronze"])
def test_the_colour_a_copper_alloy_turns_by_itself_is_its_patina(said):
    """Copper weathers to verdigris: 'green copper' is a patinated copper, not a green film over it."""
    m = material(said)
    assert m["maps"]["base_color"]["graph"] == "patina" and m["params"]["coat"] is None
    assert any(
        "the colour copper turns by itself" in n or "the colour bronze turns by itself" in n for n in notes(said)
    )


@pytest.mark.parametrize(
    "said",
    [
        "red copper",
        "green steel",
        "copper with a green lacquer",
        "green painted copper",
        "green tinted copper",
        "olive brass",
        "lime green copper",
    ],
)
def test_any_other_colour_on_a_metal_keeps_its_film_or_coat(said):
    m = material(said)
    assert "patina" not in str(m.get("maps", {}))


@pytest.mark.parametrize(
    ("first", "line", "read"),
    [
        ("red brick", "more worn and weathered", "read 'more worn and weathered' as 'more worn, more weathered'"),
        ("oak", "less shiny and yellow", "read 'less shiny and yellow' as 'less shiny, less yellow'"),
        ("oak", "more grain and contrast", "read 'more grain and contrast' as 'more grain, more contrast'"),
    ],
)
def test_a_comparison_word_compares_each_describing_word_joined_by_and(first, line, read):
    session = refined(first, line)
    said = [d.message for d in session.result.diagnostics]
    assert read in said and not [d for d in session.result.diagnostics if d.is_error]
    parts = refined(first, ", ".join(read.split(" as '")[1].rstrip("'").split(", ")))
    assert same_look(session.material, parts.material)


def test_polish_it_more_is_more_polished():
    more = refined("marble", "polish it more").material["params"]["roughness"]
    assert more < refined("marble").material["params"]["roughness"]
    assert same_look(refined("marble", "polish it more").material, refined("marble", "more polished").material)


def test_bling_is_shine():
    less = refined("yellow gold", "less bling").material["params"]["roughness"]
    assert less > refined("yellow gold").material["params"]["roughness"]


@pytest.mark.parametrize("said", ["wood floor but not orange", "oak, not orange"])
def test_not_a_colour_the_material_has_moves_its_hue_away(said):
    from tests.language.meaning import lch

    plain = lch(material(said.split(",")[0].split(" but")[0])["params"]["base_color"])
    moved = lch(material(said)["params"]["base_color"])
    assert problems(said) == []
    assert moved[1] < plain[1] and moved[2] > plain[2]  # less chroma, the hue turned away from orange (toward yellow)


def test_not_a_colour_under_a_material_with_none_of_it_warns():
    session = refined("navy paint", "not orange")
    assert "W122" in [d.code for d in session.result.diagnostics]
    session = refined("oak", "not orange")
    assert "W122" not in [d.code for d in session.result.diagnostics]


def test_sorta_like_is_a_likeness():
    assert problems("sorta like slate but lighter") == []
    assert same_look(material("sorta like slate but lighter"), material("slate, lighter"))


@pytest.mark.parametrize(("first", "line"), [("black lacquer", "more charcoal"), ("oak", "a bit more charcoal")])
def test_more_of_a_noun_that_is_a_colour_is_that_colour(first, line):
    """'more charcoal' under black lacquer is a step toward the colour charcoal, not a new charcoal
    material with a comparative of nothing (W104)."""
    from tests.language.meaning import lch

    session = refined(first, line)
    assert not [d for d in session.result.diagnostics if d.code == "W104" or d.is_error]
    assert session.material["model"] == refined(first).material["model"]
    before, after = (lch(s.material["params"]["base_color"]) for s in (refined(first), session))
    charcoal = lch(material("charcoal paint")["params"]["base_color"])
    assert abs(after[0] - charcoal[0]) < abs(before[0] - charcoal[0])  # its lightness toward charcoal's
    assert after[1] <= max(before[1], charcoal[1]) + 1e-6  # toward a near-grey: no colour of its own added


def test_a_comparative_list_ending_in_a_colour_noun_moves_in_turn():
    assert same_look(
        refined("oak", "lighter, more charcoal").material, refined("oak", "lighter", "more charcoal").material
    )


@pytest.mark.parametrize(
    ("said", "same_as"),
    [
        ("off white, nothing fancy", "off white"),
        ("oak, nothing else", "oak"),
        ("bare pine, no stain, nothing else", "bare pine, no stain"),
    ],
)
def test_nothing_fancy_at_the_end_is_read_past(said, same_as):
    assert problems(said) == []
    assert same_look(material(said), material(same_as))


@pytest.mark.parametrize(
    ("said", "same_as"),
    [
        ("a touch of sheen, off white", "off white, a touch of sheen"),
        ("fine scratches, brushed steel", "brushed steel with fine scratches"),
        ("some sheen, oak", "oak with some sheen"),
    ],
)
def test_a_clause_said_first_is_the_clause_of_the_material_after_it(said, same_as):
    assert problems(said) == []
    assert same_look(material(said), material(same_as))
    assert any("(the clause after its material)" in n for n in notes(said))


def test_a_colour_named_liquid_before_a_thing_stays_its_colour():
    """Only a drink before a vessel is what it holds: 'cream mug', 'honey vase' keep their colour."""
    assert not any("holds" in n for n in notes("cream mug") + notes("honey vase") + notes("cream tiles"))


@pytest.mark.parametrize(
    ("said", "same_as", "held"),
    [
        (
            "white ceramic coffee mug",
            "white ceramic mug",
            "read 'coffee' as what the mug holds, not what it is made of",
        ),
        (
            "green glass wine bottle",
            "green glass bottle",
            "read 'wine' as what the bottle holds, not what it is made of",
        ),
        ("coffee mug", "mug", "read 'coffee' as what the mug holds, not what it is made of"),
    ],
)
def test_a_liquid_before_a_container_is_what_it_holds(said, same_as, held):
    assert problems(said) == []
    assert same_look(material(said), material(same_as))
    assert held in notes(said)


def test_a_glass_of_a_liquid_is_still_the_liquid():
    assert material("a glass of merlot")["model"]["base"] == material("merlot")["model"]["base"]
    assert same_look(material("a glass of merlot"), material("merlot"))


@pytest.mark.parametrize(("said", "same_as"), [("walnut dark", "dark walnut"), ("oak light", "light oak")])
def test_a_shade_after_the_noun_is_not_a_colour_name(said, same_as):
    assert problems(said) == []
    assert same_look(material(said), material(same_as))


@pytest.mark.parametrize(
    ("said", "same_as"),
    [
        ("grey paint but not too shiny", "grey paint, not too shiny"),
        ("glass but not frosted", "glass, not frosted"),
        ("chrome but slightly satin", "chrome, but slightly satin"),
        ("steel but brushed", "brushed steel"),
    ],
)
def test_but_after_the_material_sets_its_describing_words_off(said, same_as):
    assert problems(said) == []
    assert same_look(material(said), material(same_as))


@pytest.mark.parametrize(
    ("said", "thing"),
    [
        ("celadon glaze on a bowl", "bowl"),
        ("varnish on a table", "table"),
        ("pale green celadon glaze on a tea bowl", "bowl"),
    ],
)
def test_a_finish_on_a_thing_is_the_things_material_with_that_finish(said, thing):
    """'varnish on a table': the table's wood with varnish, not varnish paint with a place read past."""
    assert problems(said) == []
    assert material(said)["name"].startswith(thing)
    assert not any(n.startswith("read past 'on ") for n in notes(said))


def test_a_material_on_a_place_still_reads_the_place_past():
    assert "read past 'on the floor': where the material is used, not how it looks" in notes("oak on the floor")


def test_an_interjection_set_off_by_a_comma_is_read_past_with_its_own_error():
    session = refined("white marble", "no, keep the colour, just less shiny")
    assert not [d for d in session.result.diagnostics if d.is_error]
    assert session.material["params"]["roughness"] > refined("white marble").material["params"]["roughness"]


@pytest.mark.parametrize(
    ("first", "line", "same_as"),
    [
        ("rusty steel", "darker, it's sitting in a damp alley", "darker"),
        ("oak", "a bit less shiny please, it should read as a natural oil not a lacquer", "a bit less shiny"),
        ("birch", "shinier, as if it had a clear lacquer on it", "shinier"),
    ],
)
def test_a_reason_after_the_change_is_read_past(first, line, same_as):
    session = refined(first, line)
    assert not [d for d in session.result.diagnostics if d.is_error]
    assert any(d.message.startswith("read past '") for d in session.result.diagnostics)
    assert same_look(session.material, refined(first, same_as).material)


@pytest.mark.parametrize(
    ("first", "line", "same_as"),
    [
        ("light oak", "can u make it darker", "darker"),
        ("concrete", "abit lighter", "a bit lighter"),
        ("navy velvet", "slightly more towards purple", "slightly more purple"),
    ],
)
def test_texting_forms_of_a_change(first, line, same_as):
    session = refined(first, line)
    assert not [d for d in session.result.diagnostics if d.is_error]
    assert same_look(session.material, refined(first, same_as).material)


def test_nah_go_back_is_going_back():
    session = refined("blue car paint", "darker", "nah go back a bit")
    darker = refined("blue car paint", "darker").material["params"]["base_color"]
    assert sum(session.material["params"]["base_color"]) > sum(darker)


def test_hint_of_without_its_article_is_a_degree():
    assert problems("white paint, hint of sheen") == []
    assert same_look(material("white paint, hint of sheen"), material("white paint with a hint of sheen"))


@pytest.mark.parametrize(
    ("said", "same_as"),
    [
        ("oak, visible grain, matt", "matt oak with visible grain"),
        ("marble, grey veins, polished", "polished marble with grey veins"),
    ],
)
def test_a_feature_part_in_the_middle_of_a_listing_is_its_clause(said, same_as):
    assert problems(said) == []
    assert same_look(material(said), material(same_as))


@pytest.mark.parametrize(("said", "same_as"), [("mustard yellow accent", "mustard yellow"), ("oak kitchen", "oak")])
def test_a_word_of_use_last_on_the_line_is_read_past(said, same_as):
    assert problems(said) == []
    assert same_look(material(said), material(same_as))
    assert any("saying where or what for" in n for n in notes(said))


@pytest.mark.parametrize(
    ("said", "same_as"), [("old school chalkboard", "chalkboard"), ("old fashioned brass", "brass")]
)
def test_old_school_is_a_style_not_an_age(said, same_as):
    assert "E001" not in problems(said) and "E002" not in problems(said)
    assert same_look(material(said), material(same_as))


@pytest.mark.parametrize(
    ("first", "line", "same_as"),
    [
        ("pine", "stain darker", "darker stain"),
        ("marble", "veins stronger", "stronger veins"),
        ("brushed steel", "make the brushing less obvious", "less brushing"),
        ("walnut", "make the grain more visible", "more grain"),
    ],
)
def test_a_feature_named_before_its_comparative(first, line, same_as):
    session = refined(first, line)
    assert not [d for d in session.result.diagnostics if d.is_error]
    assert session.material == refined(first, same_as).material or same_look(
        session.material, refined(first, same_as).material
    )


@pytest.mark.parametrize(("said", "same_as"), [("teal tiles in bathroom", "teal tiles"), ("oak in kitchen", "oak")])
def test_a_place_without_its_article_is_read_past(said, same_as):
    assert problems(said) == []
    assert same_look(material(said), material(same_as))


def test_a_place_that_is_a_word_of_the_lexicon_needs_its_article():
    assert "E002" in problems("paint in flat")


def test_a_particle_after_a_participle_is_read_past():
    session = refined("stainless steel", "more scratched up")
    assert not [d for d in session.result.diagnostics if d.is_error]
    assert same_look(session.material, refined("stainless steel", "more scratched").material)
    assert "read 'scratched up' as 'scratched'" in [d.message for d in session.result.diagnostics]
