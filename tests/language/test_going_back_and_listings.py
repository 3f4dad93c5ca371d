"""Meaning of everyday lines (issue #14), categories from held-out phrasing (sets 27-28): going back
a bit on the change above ('go back a bit', 'too dark, go back a bit'), a degree said after the
change ('rougher, a little'), listings with their marks ('Walnut (dark), matte', 'glass... frosted',
'marble: white, honed', 'European walnut, book-matched', 'walnut, satin'), a limit said of a colour
('not too yellow'), wear asked for on a material that shows none ('more worn'), and chat words
('tbh', 'kinda want it')."""

from __future__ import annotations

import pytest

from tests.language.meaning import compiled, lch, material, refined, same_look


def codes(text: str) -> list[str]:
    return [d.code for d in compiled(text).diagnostics if d.severity.value in ("error", "warning")]


def notes(text: str) -> list[str]:
    return [d.message for d in compiled(text).diagnostics if d.severity.value == "note"]


def lightness(session_or_material) -> float:
    m = session_or_material if isinstance(session_or_material, dict) else session_or_material.material
    return lch(m["params"]["base_color"])[0]


def look(session) -> dict:
    """What a session's material looks like: its model, parameters and maps (not where words stood)."""
    m = session.material
    return {key: m[key] for key in ("model", "params", "maps")}


def map_params(m: dict) -> dict:
    return {role: dict(ref.get("params", {})) for role, ref in (m.get("maps") or {}).items()}


# ---------------------------------------------------------------- going back a bit


@pytest.mark.parametrize(
    "line", ["go back a bit", "hmm, back a little", "ok, take it back a touch", "go back a bit please"]
)
def test_going_back_reverses_the_change_above_partly(line):
    before = lightness(refined("oak"))
    darker = lightness(refined("oak", "darker"))
    back = lightness(refined("oak", "darker", line))
    assert darker < back < before


def test_going_back_is_the_opposite_at_the_lines_degree():
    assert look(refined("red plastic", "less orange", "go back a bit")) == look(
        refined("red plastic", "less orange", "a bit more orange")
    )
    assert look(refined("oak", "rougher", "go back")) == look(refined("oak", "rougher", "smoother"))


def test_going_back_twice_goes_back_twice_from_the_same_change():
    once = lightness(refined("oak", "darker", "go back a bit"))
    twice = lightness(refined("oak", "darker", "go back a bit", "go back a bit"))
    assert once < twice < lightness(refined("oak"))


def test_going_back_says_how_it_was_read():
    said = notes("oak\ndarker\ngo back a bit")
    assert any("'go back a bit' as 'a bit lighter'" in n for n in said)


@pytest.mark.parametrize(
    ("lines", "why"), [(("go back a bit",), "no change above"), (("make it blue", "go back"), "only comparatives")]
)
def test_nothing_to_go_back_from_changes_nothing_and_says_why(lines, why):
    text = "\n".join(("oak", *lines))
    assert not codes(text)
    assert any("nothing to go back from" in n and why in n for n in notes(text))
    assert same_look(material(text), material("\n".join(("oak", *lines[:-1]))))


def test_going_back_after_a_change_on_the_same_line_is_read_past():
    session = refined("light oak", "a touch darker", "hmm too dark, go back a bit")  # a complaint: said in a session
    assert look(session) == look(refined("light oak", "a touch darker", "too dark"))
    assert any("read past 'go back a bit'" in d.message for d in session.result.diagnostics)
    assert look(refined("oak", "darker, go back a bit")) == look(refined("oak", "darker"))


def test_going_back_alone_needs_a_material_above():
    assert codes("go back a bit") == ["W104"]


# ---------------------------------------------------------------- a degree after the change


@pytest.mark.parametrize(
    ("said", "meant"),
    [
        ("rougher, a little", "a little rougher"),
        ("rougher again, a little", "a little rougher"),
        ("darker, but only slightly", "slightly darker"),
        ("darker, much", "much darker"),
    ],
)
def test_a_degree_after_the_change_is_its_degree(said, meant):
    assert look(refined("oak", said)) == look(refined("oak", meant))


# ---------------------------------------------------------------- listings and their marks


@pytest.mark.parametrize(
    ("said", "meant"),
    [
        ("Walnut (dark), matte", "dark matte walnut"),
        ("walnut, dark,, matte", "dark matte walnut"),
        ("glass... frosted", "frosted glass"),
        ("gold!!! polished", "polished gold"),
        ("oak. matte.", "matte oak"),
        ("marble: white, honed", "white honed marble"),
        ("Concrete: raw grey", "raw grey concrete"),
        ("European walnut, book-matched", "walnut"),
        ("walnut; dark; satin", "dark satin walnut"),
        ("walnut, satin", "satin walnut"),
        ("black checkered tiles", "black tiles"),
    ],
)
def test_a_listing_means_what_its_words_say(said, meant):
    assert not codes(said)
    assert same_look(material(said), material(meant))


def test_a_name_that_is_no_material_still_needs_one():
    assert codes("m1: white, honed") == ["E003"]


def test_a_material_named_first_says_how_the_ambiguous_word_was_read():
    assert any("'satin' as describing the walnut" in n for n in notes("walnut, satin"))
    assert not any("describing the oak" in n for n in notes("oak, satin"))  # no colour 'oak': nothing to say


# ---------------------------------------------------------------- a limit said of a colour


@pytest.mark.parametrize(
    ("said", "meant"),
    [("cream paint, not too yellow", "cream paint"), ("oak, not too dark", "oak"), ("not too dark oak", "oak")],
)
def test_not_too_a_colour_is_a_limit_that_keeps_the_colour(said, meant):
    assert not codes(said)
    assert same_look(material(said), material(meant))
    assert any("a limit, not a change" in n for n in notes(said))


@pytest.mark.parametrize("said", ["not too yellow", "not at all rusty"])
def test_a_line_whose_words_are_all_read_past_is_no_material(said):
    assert codes(said) == ["E003"]


# ---------------------------------------------------------------- wear asked for where none shows


def test_more_wear_on_a_material_without_any_is_a_little_of_it():
    before = material("tan leather")
    after = look(refined("tan leather", "more worn"))
    assert map_params(after) != map_params(before)
    assert same_look(after, material("slightly worn tan leather"))


def test_less_wear_on_weathered_bronze_is_less_of_its_patina():
    coverage = map_params(material("weathered bronze"))["mask"]["coverage"]
    less = map_params(look(refined("weathered bronze", "a bit less worn")))["mask"]["coverage"]
    more = map_params(look(refined("weathered bronze", "more weathered")))["mask"]["coverage"]
    assert less < coverage < more


def test_a_made_treatment_must_still_be_part_of_the_material():
    assert codes("steel\nstronger brushing") == ["W104"]
    assert codes("red plastic\nless worn") == ["W104"]


# ---------------------------------------------------------------- chat words


@pytest.mark.parametrize(
    ("phrase", "said", "meant"),
    [
        ("terracotta", "less orange tbh", "less orange"),
        ("brass", "kinda want it brushed", "make it brushed"),
        ("frosted glass", "anyway rougher", "rougher"),
    ],
)
def test_chat_words_are_read_past(phrase, said, meant):
    assert look(refined(phrase, said)) == look(refined(phrase, meant))


# ---------------------------------------------------------------- where it is, what it is for, what it is like


@pytest.mark.parametrize(
    ("said", "meant"),
    [
        ("sage green for the kitchen cabinets", "sage green paint"),
        ("rusty corrugated iron on the shed roof", "rusty corrugated iron"),
        ("frosted glass for the shower screen", "frosted glass"),
        ("gold like a wedding ring", "gold"),
        ("super shiny red like a new car", "super shiny red paint"),
        ("raw concrete like a multistorey car park", "raw concrete"),
        ("white marble, the kind you see in posh hotel bathrooms", "white marble"),
        ("red cedar cladding on the shed", "red cedar cladding"),
    ],
)
def test_context_after_the_look_is_read_past(said, meant):
    assert not codes(said)
    assert same_look(material(said), material(meant))
    said_notes = notes(said)
    assert any(n.startswith("read past ") for n in said_notes)
    assert not any("usual material" in n for n in said_notes)  # the words read past have no notes of their own


def test_a_clause_on_its_material_and_a_suffix_like_still_read_as_before():
    assert same_look(material("rust on steel"), material("steel with rust"))
    assert same_look(material("leather like vinyl"), material("leathery vinyl"))


def test_context_after_a_change_is_read_past():
    assert look(refined("oak", "darker, like a walnut stain")) == look(refined("oak", "darker"))


# ---------------------------------------------------------------- between two colours, and words


def test_between_two_colours_with_no_compound_is_half_way():
    between = lch(material("somewhere between navy and charcoal")["params"]["base_color"])
    navy, charcoal = (lch(material(f"{c} paint")["params"]["base_color"]) for c in ("navy", "charcoal"))
    assert min(navy[0], charcoal[0]) < between[0] < max(navy[0], charcoal[0])
    assert charcoal[1] < between[1] < navy[1]
    assert not codes("halfway between navy and charcoal paint")


@pytest.mark.parametrize(
    ("said", "meant"),
    [
        ("concrete without the shine", "concrete without shine"),
        ("red toy brick", "red abs"),
    ],
)
def test_everyday_words(said, meant):
    assert not codes(said)
    assert same_look(material(said), material(meant))


def test_rosier_is_pinker():
    assert look(refined("polished gold", "rosier")) == look(refined("polished gold", "pinker"))


# ---------------------------------------------------------------- limits of a finish, and chat around going back


@pytest.mark.parametrize(
    ("said", "meant"),
    [
        ("not too shiny black plastic", "satin black plastic"),
        ("paint, not too shiny", "satin paint"),
        ("not too shiny aluminum", "satin aluminum"),
    ],
)
def test_not_too_shiny_is_the_finish_between(said, meant):
    assert same_look(material(said), material(meant))


@pytest.mark.parametrize("line", ["and not so shiny", "not too shiny"])
def test_not_so_shiny_said_as_a_change_is_less_shiny(line):
    before = refined("light oak").material["params"]["roughness"]
    assert refined("light oak", line).material["params"]["roughness"] > before


def test_going_back_with_its_chat():
    assert look(refined("oak", "darker", "ooh too far, go back a little")) == look(
        refined("oak", "darker", "a little lighter")
    )
    assert look(refined("oak", "lighter", "no, go back a bit darker")) == look(
        refined("oak", "lighter", "a bit darker")
    )


@pytest.mark.parametrize(
    ("said", "meant"),
    [
        ("darkish wood", "slightly dark wood"),
        ("glossy white kitchen units", "glossy white cabinets"),
        ("faded red cotton tea towel", "faded red cotton towel"),
        ("a slightly darker oak than usual", "slightly darker oak"),
        ("white glossy metro tiles behind the hob", "white glossy tiles"),
    ],
)
def test_more_everyday_words(said, meant):
    assert not codes(said)
    assert same_look(material(said), material(meant))
    assert map_params(material(said)) == map_params(material(meant))


@pytest.mark.parametrize(
    ("said", "meant"),
    [
        ("crumbly old sandstone", "weathered old sandstone"),
        ("weathered grey fence panels", "weathered grey wood"),
        ("oak with the grain showing through", "oak with grain"),
        ("concrete with cracks all over it", "concrete with cracks"),
    ],
)
def test_words_from_set_29(said, meant):
    assert not codes(said)
    assert same_look(material(said), material(meant))


def test_too_clinical_is_too_cold():
    assert look(refined("white paint", "too clinical")) == look(refined("white paint", "too cold"))


def test_rusty_iron_is_mostly_rust():
    coverage = map_params(material("rusty iron"))["mask"]["coverage"]
    assert coverage > 0.6 > map_params(material("slightly rusty iron"))["mask"]["coverage"]


@pytest.mark.parametrize(
    ("said", "meant"),
    [
        ("cherry wood, the reddish kind, satin varnish", "reddish cherry wood, satin varnish"),
        ("oak, the light one", "light oak"),
        ("white(ish) marble", "whitish marble"),
    ],
)
def test_listing_forms_from_set_30(said, meant):
    assert not codes(said)
    assert same_look(material(said), material(meant))


def test_a_kept_part_then_and_the_change():
    said = refined("oak", "keep the grain and make it darker")
    assert look(said) == look(refined("oak", "darker"))


def test_a_likeness_of_a_state_after_a_change_is_read_past():
    said = refined("terracotta floor tiles", "rougher, like they've never been sealed")
    assert look(said) == look(refined("terracotta floor tiles", "rougher"))


# ---------------------------------------------------------------- a colour named after a thing, and degrees (set 31)


@pytest.mark.parametrize("colour", ["brick red", "walnut brown", "slate grey"])
def test_a_colour_named_after_a_thing_stays_a_colour(colour):
    assert same_look(material(colour), material(f"{colour} paint"))


def test_a_degree_after_the_change_without_a_comma():
    assert look(refined("grey concrete", "lighter a bit")) == look(refined("grey concrete", "a bit lighter"))


@pytest.mark.parametrize(
    ("phrase", "line", "way"), [("black plastic", "less black", 1), ("white paint", "less white", -1)]
)
def test_less_black_and_less_white_step_toward_a_grey(phrase, line, way):
    before = lightness(refined(phrase))
    after = lightness(refined(phrase, line))
    assert (after - before) * way > 0.05
    assert lch(refined(phrase, line).material["params"]["base_color"])[1] < 0.02  # still a grey


@pytest.mark.parametrize(
    ("said", "meant"),
    [
        ("tile, white + glossy", "white glossy tile"),
        ("fridge", "stainless steel"),
        ("cherry wood, the reddish kind", "reddish cherry wood"),
    ],
)
def test_small_words_from_set_31(said, meant):
    assert not codes(said)
    assert same_look(material(said), material(meant))


# ---------------------------------------------------------------- what the new readings must leave alone (review)


@pytest.mark.parametrize("said", ["steel on the oak", "oak, like walnut", "steel on oak"])
def test_a_second_material_after_a_place_word_is_still_an_error(said):
    assert "E002" in codes(said) or "E001" in codes(said)


def test_not_that_shiny_is_a_softener_not_a_pointer():
    assert same_look(material("not that shiny paint"), material("satin paint"))  # as 'not too shiny'
    assert not same_look(material("not that shiny paint"), material("dull paint"))


def test_a_cloth_named_after_a_colour_stays_the_cloth():
    assert same_look(material("ivory, silk"), material("ivory silk"))
    assert not any("describing the ivory" in n for n in notes("ivory, silk"))


def test_less_white_on_a_colour_with_a_hue_takes_nothing_away():
    navy = refined("navy paint")
    assert look(refined("navy paint", "less white")) == look(navy)


def test_and_before_a_describing_change_is_no_complaint():
    assert look(refined("oak", "and very glossy")) == look(refined("oak", "very glossy"))


def test_inches_keep_their_mark():
    assert not codes('12" porcelain tile')
    assert same_look(material('12" porcelain tile'), material("porcelain tile"))


def test_many_openers_and_degree_words_end_in_errors_not_a_crash():
    assert codes("oak\n" + "no " * 40 + "darker")  # a backtracking pattern would take minutes here
    assert "E004" in codes("zzz darker " + "bit " * 300)  # too long: said so, no deep recursion


def test_a_quantity_without_its_article_is_a_degree():
    assert same_look(material("glass with a bit of a greenish tinge"), material("glass with a slightly greenish tinge"))


def test_a_state_likeness_after_a_change_is_read_past():
    said = refined("terracotta pot", "more faded, like it's been out in the sun")
    assert look(said) == look(refined("terracotta pot", "more faded"))


@pytest.mark.parametrize(
    ("said", "meant"), [("navy but a bit brighter", "navy, a bit brighter"), ("oak but darker", "darker oak")]
)
def test_comparatives_after_but(said, meant):
    assert not codes(said)
    assert same_look(material(said), material(meant))
