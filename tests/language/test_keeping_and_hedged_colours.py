"""Meaning of everyday lines (issue #14), categories from held-out phrasing: a change line that
keeps the material as it is ('keep the varnish', 'perfect, thanks'), a hedged colour before another
('blackish red': a red leaning toward black, not two colours), 'more of an X', a colour turned down
beside the one asked for ('lighter, not jet black'), a survey colour where a describing word of one
material class does not apply ('rust felt'), 'too new', and the qualifiers that draw nothing (tile
shapes, a clean white, poured concrete)."""

from __future__ import annotations

import pytest

from tests.language.meaning import compiled, lch, material, refined
from tests.language.meaning import same_look as look_alike


def problems(text: str) -> list[str]:
    return [d.code for d in compiled(text).diagnostics if d.severity.value in ("error", "warning")]


def notes(text: str) -> list[str]:
    return [d.message for d in compiled(text).diagnostics if d.severity.value == "note"]


def hue_gap(a: float, b: float) -> float:
    return abs((a - b + 180) % 360 - 180)


def same_look(a: dict, b: dict) -> bool:
    return look_alike(a, b, ("base_color", "roughness", "anisotropy", "coat"))


# ---------------------------------------------------------------- lines that keep the material


@pytest.mark.parametrize(
    ("phrase", "line"),
    [
        ("white varnished oak", "keep the varnish"),
        ("white varnished oak", "leave the grain as it is, thanks"),
        ("brushed steel", "keep the same brushing"),
        ("navy velvet", "keep it the same colour"),
        ("red plastic", "that's perfect!"),
        ("red plastic", "great, thanks"),
        ("red plastic", "don't change the colour"),
        ("white oak", "ok, keep the grain"),
        ("white oak", "no, keep the grain as it is"),
    ],
)
def test_a_line_that_keeps_the_material_changes_nothing(phrase: str, line: str) -> None:
    session = refined(phrase, line)
    assert session.result.ok, [d.message for d in session.result.diagnostics]
    assert same_look(session.material, material(phrase))
    said = [d for d in session.result.diagnostics if d.span.line == 2]
    assert [d.code for d in said] == ["N101"] and "keeping the material as it is" in said[0].message


def test_keep_it_with_a_describing_word_asks_for_it() -> None:
    """'keep it glossy' is a change (make it glossy), not a line that keeps."""
    assert (
        material("matte red plastic\nkeep it glossy")["params"]["roughness"]
        < material("matte red plastic")["params"]["roughness"]
    )


@pytest.mark.parametrize(
    ("phrase", "line"),
    [
        ("matte red plastic", "keep the varnish glossy"),
        ("white oak", "keep the grain, dark brown"),
        ("glossy red plastic", "keep the red and matte"),
        ("white oak", "stick with the walnut"),
        ("oak", "keep the"),
    ],
)
def test_a_line_that_asks_for_something_is_no_keeping_line(phrase: str, line: str) -> None:
    said = compiled(f"{phrase}\n{line}")
    assert not any("keeping the material" in d.message for d in said.diagnostics)


def test_keep_then_a_change_still_changes() -> None:
    darker = refined("white oak", "keep the grain but make it darker").material["params"]["base_color"]
    assert lch(darker)[0] < lch(material("white oak")["params"]["base_color"])[0] - 0.05


@pytest.mark.parametrize("line", ["keep the grain", "thanks", "perfect!"])
def test_a_keeping_line_with_no_material_above_is_an_error(line: str) -> None:
    assert problems(line) == ["E003"]
    assert not compiled(line).ok
    assert not notes(line)  # no 'nothing changes' note beside the error


def test_keep_alone_is_still_an_unknown_word() -> None:
    assert "E001" in problems("oak\nkeep")


# ---------------------------------------------------------------- hedged colours before a colour


@pytest.mark.parametrize(
    ("phrase", "plain", "toward"),
    [
        ("blackish red paint", "red paint", "darker"),
        ("whitish blue paint", "blue paint", "lighter"),
        ("almost black green velvet", "green velvet", "darker"),
        ("nearly white pink plastic", "pink plastic", "lighter"),
    ],
)
def test_a_hedged_colour_leans_the_next_colour_toward_it(phrase: str, plain: str, toward: str) -> None:
    L, C, h = lch(material(phrase)["params"]["base_color"])
    L0, C0, h0 = lch(material(plain)["params"]["base_color"])
    assert (L < L0 - 0.05) if toward == "darker" else (L > L0 + 0.03)
    assert hue_gap(h, h0) < 15 and C > 0.03  # still that colour, not black, white or grey
    assert "W105" not in problems(phrase)
    assert any("moved toward" in n for n in notes(phrase))


@pytest.mark.parametrize("phrase", ["red blue paint", "very red blue paint"])
def test_two_plain_colours_still_warn(phrase: str) -> None:
    assert "W105" in problems(phrase)


def test_a_likeness_to_an_unknown_thing_keeps_the_colour() -> None:
    """'pale green, like a ginkgo leaf': the thing is not the material; the colour stays."""
    said = material("dark green, like a ginkgo leaf")
    assert problems("dark green, like a ginkgo leaf") == []
    assert hue_gap(lch(said["params"]["base_color"])[2], lch(material("green paint")["params"]["base_color"])[2]) < 20


# ---------------------------------------------------------------- change lines


def test_more_of_an_orange_is_more_like_orange() -> None:
    session = refined("red plastic", "more of an orange")
    assert session.result.ok
    assert (
        session.material["params"]["base_color"]
        == refined("red plastic", "more like orange").material["params"]["base_color"]
    )
    assert lch(session.material["params"]["base_color"])[2] > lch(material("red plastic")["params"]["base_color"])[2]


def test_more_of_a_material_beside_a_comparative_changes_to_it() -> None:
    """'deeper, more of a walnut' under pale oak: walnut, then deeper (as the two lines say)."""
    said = refined("pale oak", "deeper, more of a walnut").material
    assert same_look(said, refined("pale oak", "make it walnut", "deeper").material)


@pytest.mark.parametrize("line", ["lighter, not jet black", "a bit lighter, not pitch black", "lighter, but not white"])
def test_a_colour_turned_down_beside_a_change_is_read_past(line: str) -> None:
    session = refined("matte black paint", line)
    assert session.result.ok, [d.message for d in session.result.diagnostics]
    assert lch(session.material["params"]["base_color"])[0] > 0.2
    assert any(d.message == f"read past '{line.split(', ')[1]}'" for d in session.result.diagnostics)


def test_too_new_ages_the_material() -> None:
    session = refined("polished brass", "it looks too new")
    assert session.result.ok
    assert session.material["params"]["roughness"] > material("polished brass")["params"]["roughness"]


def test_new_contradicts_rusty() -> None:
    assert "W101" in problems("brand-new rusty steel")


def test_a_complaint_said_with_now() -> None:
    session = refined("glossy white paint", "it's too glossy now")
    assert session.result.ok
    assert session.material["params"]["roughness"] > material("glossy white paint")["params"]["roughness"]


# ---------------------------------------------------------------- colours and qualifiers


@pytest.mark.parametrize("noun", ["felt", "linen", "leather"])
def test_rust_before_a_material_that_cannot_rust_is_the_colour(noun: str) -> None:
    L, C, h = lch(material(f"rust {noun}")["params"]["base_color"])
    assert problems(f"rust {noun}") == []
    assert 25 < h < 70 and C > 0.08  # an orange-red brown (the survey's rust, #a83c09)


def test_the_survey_colour_is_applied_as_a_colour_word() -> None:
    """A softening degree is a share of the way; another colour before it warns, as colours do."""
    full, slight = (lch(material(p)["params"]["base_color"]) for p in ("rust linen", "slightly rust linen"))
    assert slight[1] < full[1] - 0.03  # half way from the linen's own colour
    assert "W105" in problems("red rust linen")


def test_rust_on_iron_stays_rust() -> None:
    assert "mask" in material("rust iron")["maps"]
    assert "W102" in problems("rusty linen")  # 'rusty' is no colour name


@pytest.mark.parametrize(
    ("phrase", "plain"),
    [
        ("hexagon floor tiles", "floor tiles"),
        ("a crisp white paint", "white paint"),
        ("poured concrete", "concrete"),
        ("exposed brickwork", "exposed brick"),
        ("a single malt whisky", "whisky"),
    ],
)
def test_qualifiers_that_draw_nothing_are_read_past(phrase: str, plain: str) -> None:
    assert problems(phrase) == []
    assert same_look(material(phrase), material(plain))


def test_a_tile_shape_says_it_is_not_drawn() -> None:
    assert any("not drawn" in n for n in notes("hexagonal tiles"))


# ---------------------------------------------------------------- survey shade names that drift in hue


@pytest.mark.parametrize(
    ("phrase", "plain", "toward"),
    [
        ("pale blue paint", "blue paint", "lighter"),  # the survey's #d0fefe is a cyan
        ("very pale blue paint", "pale blue paint", "lighter"),
        ("very dark brown paint", "dark brown paint", "darker"),  # the survey's #1d0200 is a red-black
        ("pale peach paint", "peach paint", "lighter"),
    ],
)
def test_a_shade_keeps_the_hue_of_its_colour(phrase: str, plain: str, toward: str) -> None:
    L, C, h = lch(material(phrase)["params"]["base_color"])
    L0, _C0, h0 = lch(material(plain)["params"]["base_color"])
    assert hue_gap(h, h0) < 10 and C > 0.03
    assert (L < L0) if toward == "darker" else (L > L0)


def test_a_shade_name_within_the_hue_keeps_the_survey_colour() -> None:
    """'light blue' is the survey's #95d0fc (22 degrees from its blue: a shade, kept)."""
    from cnlmc.colour import hex_to_linear

    assert material("light blue paint")["params"]["base_color"] == pytest.approx(hex_to_linear("#95d0fc"), abs=1e-5)


# ---------------------------------------------------------------- comparisons with the material as it is, removals


@pytest.mark.parametrize(
    ("line", "plain"),
    [
        ("a lighter grey than that", "lighter grey"),
        ("a shade darker than before", "a shade darker"),
        ("lighter than that, please", "lighter"),
    ],
)
def test_a_comparison_with_the_material_as_it_is_is_the_comparative(line: str, plain: str) -> None:
    said, bare = refined("dark grey paint", line), refined("dark grey paint", plain)
    assert said.result.ok and said.material["params"]["base_color"] == bare.material["params"]["base_color"]
    assert any(d.message.startswith("read past 'than") for d in said.result.diagnostics)


def test_a_comparison_with_a_material_still_names_it() -> None:
    assert "E003" in problems("lighter than")  # nothing named after 'than'
    assert material("lighter than oak")["params"]["base_color"] != material("oak")["params"]["base_color"]


@pytest.mark.parametrize("line", ["no visible grain", "no grain at all", "without any obvious grain"])
def test_a_removal_said_with_what_is_seen(line: str) -> None:
    assert same_look(refined("oak", line).material, refined("oak", "no grain").material)


@pytest.mark.parametrize(("phrase", "plain"), [("no sheen", "matte paint"), ("no sheen at all", "matte paint")])
def test_a_removal_with_no_material_above_reads_as_its_words(phrase: str, plain: str) -> None:
    assert problems(phrase) == []
    assert material(phrase)["params"]["roughness"] == material(plain)["params"]["roughness"]
    assert not any("taking" in n for n in notes(phrase))


# ---------------------------------------------------------------- foods


@pytest.mark.parametrize(
    ("phrase", "noun"),
    [
        ("runny caramel", "caramel"),
        ("salted caramel sauce", "caramel"),
        ("vanilla custard", "custard"),
        ("liquid mercury", "mercury"),
    ],
)
def test_a_food_named_in_its_state_is_the_food(phrase: str, noun: str) -> None:
    assert problems(phrase) == []
    assert same_look(material(phrase), material(noun))


def test_a_food_colour_before_another_material_is_the_colour() -> None:
    leather = material("caramel leather")
    assert leather["model"]["base"] != "glass" and lch(leather["params"]["base_color"])[2] == pytest.approx(
        lch(material("caramel")["params"]["base_color"])[2], abs=2
    )


# ---------------------------------------------------------------- between two finishes; dark stones and mill scale


@pytest.mark.parametrize(
    ("phrase", "low", "high"),
    [
        ("somewhere between satin and gloss", "glossy paint", "satin paint"),
        ("somewhere between satin and matte", "satin paint", "matte paint"),
    ],
)
def test_between_two_finishes_lies_between_them(phrase: str, low: str, high: str) -> None:
    assert problems(phrase) == []
    r = material(phrase)["params"]["roughness"]
    assert material(low)["params"]["roughness"] < r < material(high)["params"]["roughness"]


def test_between_two_finishes_on_a_material() -> None:
    oak = material("oak, somewhere between satin and matte")
    assert (
        material("satin oak")["params"]["roughness"]
        < oak["params"]["roughness"]
        < material("matte oak")["params"]["roughness"]
    )


@pytest.mark.parametrize("phrase", ["slate", "riven slate", "hot-rolled steel"])
def test_slate_and_mill_scale_read_dark(phrase: str) -> None:
    from cnlmc.colour import linear_to_oklab

    said = material(phrase)
    rgb = said["params"]["base_color"]
    if said["model"]["base"] == "conductor":  # what is seen: the tint times the metal's reflectance at normal incidence
        rgb = [c * f for c, f in zip(rgb, said["params"]["f0"])]
    assert linear_to_oklab(rgb)[0] < 0.45


def test_black_american_walnut_is_walnut() -> None:
    assert same_look(material("black american walnut worktop"), material("walnut worktop"))


# ---------------------------------------------------------------- colours named after a thing; more change lines


@pytest.mark.parametrize(
    ("phrase", "colour"), [("soft plaster pink", "pink paint"), ("sea glass green", "green paint")]
)
def test_a_colour_named_after_a_thing_leans_toward_its_colour(phrase: str, colour: str) -> None:
    """'plaster pink' is pink as seen on plaster: a paler pink than the survey's, same hue family."""
    assert problems(phrase) == []
    L, C, h = lch(material(phrase)["params"]["base_color"])
    L0, C0, h0 = lch(material(colour)["params"]["base_color"])
    assert L > L0 and C < C0 and hue_gap(h, h0) < 25


def test_an_object_read_as_its_material_names_no_colour() -> None:
    assert "E002" in problems("smooth peanut butter")  # 'nut' is steel by rule: no 'nut butter' colour


@pytest.mark.parametrize(
    ("phrase", "line", "plain"),
    [
        ("terracotta floor tiles", "keep the tiles but make them shinier", "shinier"),
        ("glossy red plastic", "the red is a bit much", "a bit less red"),
        ("white oak", "the grain is too much", "less grain"),
        ("terracotta floor tiles", "too orange, can we push it towards pink?", "less orange, more pink"),
        ("oak veneer", "less of the orange, please", "less orange"),
        ("grey concrete", "a slightly darker grey than the sample", "slightly darker grey"),
    ],
)
def test_more_ways_of_saying_a_change(phrase: str, line: str, plain: str) -> None:
    said, bare = refined(phrase, line), refined(phrase, plain)
    assert said.result.ok, [d.message for d in said.result.diagnostics]
    assert same_look(said.material, bare.material)
    assert said.material != material(phrase)


@pytest.mark.parametrize(
    ("phrase", "plain"),
    [
        ("an old rusty wheelbarrow", "old rusty steel"),
        ("steel with flecks of rust", "steel with spots of rust"),
    ],
)
def test_everyday_words_for_things(phrase: str, plain: str) -> None:
    assert problems(phrase) == []
    assert same_look(material(phrase), material(plain))


@pytest.mark.parametrize(("phrase", "hue"), [("conker brown leather", (20, 60)), ("blonde ash veneer", (55, 95))])
def test_everyday_colour_names(phrase: str, hue: tuple[int, int]) -> None:
    assert problems(phrase) == []
    assert hue[0] < lch(material(phrase)["params"]["base_color"])[2] < hue[1]


@pytest.mark.parametrize(
    ("phrase", "line", "plain"),
    [
        (
            "pine planks",
            "make them look older and rougher",
            "more aged and rougher",
        ),  # older: aged (indoors), not weathered
        ("white marble", "the veining is too busy, can we lose it", "less veining"),
        ("red plastic", "make it a lighter blue", "make it blue"),
    ],
)
def test_change_lines_with_derived_comparatives_echoes_and_named_colours(phrase: str, line: str, plain: str) -> None:
    said = refined(phrase, line)
    assert said.result.ok, [d.message for d in said.result.diagnostics]
    if line.startswith("make it a lighter"):  # blue, then lighter: a blue lighter than plain blue
        blue = refined(phrase, plain).material["params"]["base_color"]
        L, _C, h = lch(said.material["params"]["base_color"])
        assert L > lch(blue)[0] and hue_gap(h, lch(blue)[2]) < 15
    else:
        assert same_look(said.material, refined(phrase, plain).material)


def test_more_grey_on_black_moves_toward_grey() -> None:
    black = material("glossy black plastic")["params"]["base_color"]
    greyer = refined("glossy black plastic", "more grey").material["params"]["base_color"]
    assert lch(greyer)[0] > lch(black)[0] + 0.05
    assert refined("glossy black plastic", "more grey").result.ok


def test_a_wine_named_by_its_grape() -> None:
    assert same_look(material("a glass of merlot"), material("red wine"))
    assert material("merlot velvet")["model"]["base"] != "glass"  # before another material, the colour


# ---------------------------------------------------------------- a named target of another family is applied first


@pytest.mark.parametrize(
    ("phrase", "line", "toward"),
    [
        ("dark grey paint", "a slightly darker grey", "darker"),  # the same family: only the step
        ("charcoal paint", "a slightly darker grey", "darker"),
        ("dark grey paint", "a lighter grey than that", "lighter"),
        ("pale pink paint", "a slightly deeper pink", "darker"),
    ],
)
def test_a_comparative_of_the_materials_own_colour_family_only_steps(phrase: str, line: str, toward: str) -> None:
    before = lch(material(phrase)["params"]["base_color"])
    after = lch(refined(phrase, line).material["params"]["base_color"])
    assert (after[0] < before[0]) if toward == "darker" else (after[0] > before[0])
    assert abs(after[0] - before[0]) < 0.35  # a step (lighter: half way to white), not a jump to the survey colour


@pytest.mark.parametrize(
    ("line", "low", "high"),
    [("somewhere between satin and gloss", 0.08, 0.35), ("somewhere between matte and satin", 0.35, 0.8)],
)
def test_between_two_finishes_on_a_change_line(line: str, low: float, high: float) -> None:
    assert low < refined("oak", line).material["params"]["roughness"] < high


@pytest.mark.parametrize("phrase", ["chrome yellow paint", "iron red paint"])
def test_a_colour_named_after_a_metal_is_the_colour_word(phrase: str) -> None:
    """A metal's base colour is a tint of its reflectance, not a colour one sees: no lean to white."""
    colour = phrase.split()[1]
    assert material(phrase)["params"]["base_color"] == material(f"{colour} paint")["params"]["base_color"]


@pytest.mark.parametrize("line", ["keep this blue", "keep that blue"])
def test_keep_this_keeps_what_it_names(line: str) -> None:
    session = refined("blue paint", line)
    assert session.result.ok and same_look(session.material, material("blue paint"))


@pytest.mark.parametrize(
    ("phrase", "plain"),
    [
        ("white oak, rift sawn", "white oak"),
        ("quarter sawn sycamore", "sycamore"),
    ],
)
def test_how_boards_are_cut_draws_nothing(phrase: str, plain: str) -> None:
    assert problems(phrase) == []
    assert same_look(material(phrase), material(plain))
    assert any("does not change how" in n for n in notes(phrase))


def test_a_negation_alone_is_plain_paint() -> None:
    assert problems("not metallic") == []
    assert same_look(material("not metallic"), material("paint"))


def test_a_crackle_glaze_keeps_its_colour() -> None:
    """'turquoise crackle glaze': the glaze's colour on the surface, as for a glaze (it was dropped)."""
    said = material("turquoise crackle glaze")
    assert (
        hue_gap(lch(said["params"]["base_color"])[2], lch(material("turquoise glaze")["params"]["base_color"])[2]) < 5
    )
    assert problems("crackle-glaze ceramic") == []  # a feature before the material still reads as its clause
