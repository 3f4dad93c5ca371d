"""Meaning of everyday lines (issue #14), categories from held-out phrasing: a change line with a
remark beside it ('more matte, it looks plasticky'), colour steps that keep the colour a person
named ('lighter' on navy is a blue, 'greyer' on white is a grey), plating that is bright, the
finish a noun's own name states, describing words alone that contradict, likenesses and vessels
after a material, and hedges ('not quite white')."""

from __future__ import annotations

import pytest

from cnlmc.api import Session, compile_source, lexicon_for
from tests.language.meaning import LEX, compiled, lch, material, refined, same_look


def codes(text: str) -> list[str]:
    return [d.code for d in compiled(text).diagnostics if d.severity.value in ("error", "warning")]


def colour_after(phrase: str, *lines: str) -> list[float]:
    return refined(phrase, *lines).material["params"]["base_color"]


# ---------------------------------------------------------------- colour steps


@pytest.mark.parametrize("phrase", ["navy paint", "dark green plastic", "burgundy velvet", "forest green paint"])
def test_lighter_keeps_the_hue_and_most_of_the_chroma(phrase: str) -> None:
    L0, C0, h0 = lch(material(phrase)["params"]["base_color"])
    L1, C1, h1 = lch(colour_after(phrase, "lighter"))
    assert L1 > L0 + 0.1
    assert abs((h1 - h0 + 180) % 360 - 180) < 8  # the same hue: a lighter navy is a blue
    assert C1 > 0.6 * C0  # not the grey a linear blend towards white gives (navy: chroma 0.01)


def test_the_papers_bracket_numbers_hold_with_the_oklab_lighter() -> None:
    """Blue (0,0,1) -darker-> (0,0,0.5) -lighter-> (0,0,0.75): a bracket's midpoint (paper §4.2)."""
    session = Session("blue plastic", LEX)
    blue = session.material["params"]["base_color"]
    darker = session.refine("darker")["params"]["base_color"]
    lighter = session.refine("lighter")["params"]["base_color"]
    assert darker == pytest.approx([c * 0.5 for c in blue], abs=1e-6)
    assert lighter == pytest.approx([c * 0.75 for c in blue], abs=1e-6)


def test_paler_fades_the_colour_as_it_lightens() -> None:
    L0, C0, _h = lch(material("navy paint")["params"]["base_color"])
    L1, C1, _h = lch(colour_after("navy paint", "paler"))
    L2, C2, _h = lch(colour_after("navy paint", "lighter"))
    assert L1 > L0 and C1 < C2  # paler: lighter and less coloured than 'lighter'


@pytest.mark.parametrize(("phrase", "way"), [("white ceramic tile", -1), ("black paint", 1)])
def test_greyer_moves_a_white_or_a_black_towards_grey(phrase: str, way: int) -> None:
    L0 = lch(material(phrase)["params"]["base_color"])[0]
    L1 = lch(colour_after(phrase, "a bit greyer"))[0]
    assert (L1 - L0) * way > 0.01


def test_greyer_still_takes_chroma_from_a_colour() -> None:
    C0 = lch(material("red paint")["params"]["base_color"])[1]
    assert lch(colour_after("red paint", "greyer"))[1] < 0.85 * C0


@pytest.mark.parametrize("line", ["more vibrant", "more vivid", "richer"])
def test_more_vivid_on_a_pale_colour_at_the_gamuts_edge_adds_chroma(line: str) -> None:
    C0 = lch(material("pale pink linen")["params"]["base_color"])[1]
    assert lch(colour_after("pale pink linen", line))[1] > C0 * 1.1


# ---------------------------------------------------------------- a change line with a remark beside it


@pytest.mark.parametrize(
    ("phrase", "line", "plain"),
    [
        ("light oak flooring", "more matte, it looks plasticky", "more matte"),
        ("light oak flooring", "it looks plasticky, more matte", "more matte"),
        ("navy wool", "it reads almost black, lift it a bit", "a bit lighter"),
        ("pale pink linen", "keep that pink, just a little darker", "a little darker"),
        ("white ceramic tile", "add some crazing, like an old crackle glaze", "add some crazing"),
        ("dull brass", "add some brushing, it looks cheap", "add some brushing"),
    ],
)
def test_a_remark_beside_a_change_is_read_past(phrase: str, line: str, plain: str) -> None:
    said, bare = Session(phrase, LEX), Session(phrase, LEX)
    assert same_look(said.refine(line), bare.refine(plain))
    assert said.material != Session(phrase, LEX).material  # it changed
    remark = next(part.strip() for part in line.split(",") if plain not in part)
    last = [d for d in said.result.diagnostics if d.span is not None and d.span.line == 2]
    assert any(f"read past '{remark}'" in d.message for d in last), [d.message for d in last]


@pytest.mark.parametrize(
    "line", ["leave the grain but make it darker, glossier", "keep the grain but make it darker, glossier"]
)
def test_a_remark_opener_before_a_change_it_says_is_not_read_past(line: str) -> None:
    """A part that says a change after a remark ('... but make it darker') is never dropped silently:
    read or not, the colour it asks for is not lost with a note."""
    session = Session("light oak flooring", LEX)
    try:
        after = session.refine(line)
    except ValueError:
        return  # not read: the line's error says so
    assert after["params"]["base_color"] != Session("light oak flooring", LEX).material["params"]["base_color"]


def test_a_noun_beside_a_describing_word_is_no_describing_part() -> None:
    """'walnut, matte' has no comparative: the describing part is not rewritten as a change."""
    after = Session("light oak flooring", LEX).refine("walnut, matte")
    assert after["params"]["roughness"] == pytest.approx(0.8)


def test_a_remark_alone_is_no_change() -> None:
    """Only beside a change is a remark read past: alone it is not a change line."""
    session = Session("light oak flooring", LEX)
    before = session.material
    with pytest.raises(ValueError):
        session.refine("it looks plasticky, it reads cheap")
    assert session.material == before


def test_lift_it_is_lighter() -> None:
    assert colour_after("navy wool", "lift it") == colour_after("navy wool", "lighter")


def test_the_same_in_a_colour_is_that_colour() -> None:
    assert colour_after("dark green tiles", "the same in navy") == colour_after("dark green tiles", "make it navy")
    assert colour_after("dark green tiles", "what about the same in mustard") == colour_after(
        "dark green tiles", "make it mustard"
    )


def test_brushing_is_a_feature() -> None:
    brushed = material("brass with some brushing")
    assert brushed["model"]["anisotropic"] and "normal" in brushed["maps"]


# ---------------------------------------------------------------- plating, names, contradictions


def test_a_describing_word_keeps_its_roughness_under_a_plating() -> None:
    assert material("gold plated matte steel")["params"]["roughness"] == material("matte steel")["params"]["roughness"]


def test_plating_is_as_bright_as_the_plating_metal() -> None:
    chrome = material("chrome")["params"]["roughness"]
    assert material("chrome plated steel")["params"]["roughness"] == chrome
    assert material("chrome-plated steel tube")["params"]["roughness"] == chrome
    assert material("gold plated steel")["params"]["roughness"] == material("gold")["params"]["roughness"]
    # a plating never roughens: the base is kept when it is the smoother
    assert material("gold plated polished steel")["params"]["roughness"] <= material("gold")["params"]["roughness"]


@pytest.mark.parametrize("text", ["shiny chalky paint", "super glossy chalky paint"])
def test_a_describing_word_against_the_nouns_own_name_warns(text: str) -> None:
    (w101,) = [d for d in compiled(text).diagnostics if d.code == "W101"]
    assert "'chalky'" in w101.message and "chalky paint" in w101.message
    assert codes("matte chalky paint") == []


@pytest.mark.parametrize("text", ["glossy matte", "high-gloss matte", "mirror-polished but totally matte"])
def test_describing_words_alone_that_contradict_compile_and_warn(text: str) -> None:
    result = compiled(text)
    assert result.ir["materials"] and [d.code for d in result.diagnostics if d.severity.value == "warning"] == ["W101"]


# ---------------------------------------------------------------- likeness, vessels, hedges


@pytest.mark.parametrize(
    ("text", "plain"),
    [
        ("warm greige, like a mushroom", "warm greige paint"),
        ("almost black, with a hint of green", "almost black paint with a hint of green"),
        ("a lighter shade of navy", "a lighter navy paint"),
        ("a paler shade of brown", "a paler brown paint"),
        ("coffee in a mug", "coffee"),
        ("clear water in a glass", "clear water"),
        ("a drizzle of olive oil", "olive oil"),
        ("not quite white", "almost white paint"),
        ("absolutely matte paint", "completely matte paint"),
    ],
)
def test_everyday_wrappings_read_as_the_plain_phrase(text: str, plain: str) -> None:
    assert same_look(material(text), material(plain)), text
    assert not [d for d in compiled(text).diagnostics if d.severity.value in ("error", "warning")]


def test_not_quite_so_is_a_softener_not_a_booster() -> None:
    shiny = material("shiny steel")["params"]["roughness"]
    assert material("not quite so shiny steel")["params"]["roughness"] > shiny


# ---------------------------------------------------------------- a first highlight, trade words


@pytest.mark.parametrize(
    ("phrase", "line"), [("pale pink linen", "a little shinier"), ("matte grey concrete", "smoother")]
)
def test_a_gloss_step_on_a_diffuse_material_shows_a_highlight(phrase: str, line: str) -> None:
    """Below settings.toml diffuse_threshold a highlight is drawn: the first step goes there."""
    session = Session(phrase, LEX)
    assert session.material["model"]["base"] == "diffuse"
    after = session.refine(line)
    threshold = LEX.settings.get("diffuse_threshold")
    assert after["model"]["base"] == "dielectric" and after["params"]["roughness"] < threshold
    again = session.refine("shinier")["params"]["roughness"]
    assert again < after["params"]["roughness"]  # and it keeps moving


def test_a_metal_has_a_highlight_at_any_roughness_so_it_steps_as_usual() -> None:
    session = Session("extremely rough copper", LEX)
    before = session.material["params"]["roughness"]
    after = session.refine("a tiny bit smoother")["params"]["roughness"]
    assert before - 0.05 < after < before  # a small step, no jump to the diffuse threshold


@pytest.mark.parametrize(
    ("text", "plain"),
    [
        ("white plaster with a glossy feel", "white plaster with a glossy finish"),
        ("the deep teal from the brochure", "deep teal paint"),
        ("European oak, rustic grade", "European oak"),
    ],
)
def test_trade_and_sales_words_read_as_the_plain_phrase(text: str, plain: str) -> None:
    assert same_look(material(text), material(plain)), text
    if "feel" in text:  # the feel is the finish: not the plaster as it is
        assert not same_look(material(text), material("white plaster"))


def test_bubbles_in_glass_compile_and_say_they_are_not_drawn() -> None:
    result = compiled("green glass with little bubbles")
    assert result.ir["materials"][0]["model"]["base"] == "glass"
    assert [d.code for d in result.diagnostics if d.severity.value == "warning"] == ["W120"]


# ---------------------------------------------------------------- flecks of metal, weathering steel


@pytest.mark.parametrize("text", ["black lacquer with gold flecks", "navy lacquer with gold flecks"])
def test_flecks_of_a_metal_are_sparse_flakes_of_it(text: str) -> None:
    result = compiled(text)
    params = result.ir["materials"][0]["params"]
    gold = LEX.require("nouns", "gold")
    assert params["flake_color"] == pytest.approx([b * f for b, f in zip(gold.get("base_color"), gold.get("f0"))])
    paint = material("car paint with metallic flakes")["params"]["flake_density"]
    assert 0 < params["flake_density"] < 0.5 * paint  # scattered flecks, not a metallic paint's cover
    assert "N126" in [d.code for d in result.diagnostics]
    assert "flake_color" not in material("granite with black flecks")["params"]  # mineral flecks stay speckles


def test_gold_flakes_keep_their_gold_over_any_pigment() -> None:
    assert (
        material("navy lacquer with gold flakes")["params"]["flake_color"]
        == material("car paint with gold flakes")["params"]["flake_color"]
    )


@pytest.mark.parametrize("text", ["Corten weathering steel", "rusty corten steel"])
def test_a_word_of_rust_never_takes_rust_off(text: str) -> None:
    coverage = material(text)["maps"]["mask"]["params"]["coverage"]
    assert coverage >= material("corten steel")["maps"]["mask"]["params"]["coverage"]


# ---------------------------------------------------------------- -ness, a comparative finish, an echo


@pytest.mark.parametrize(
    ("line", "plain"),
    [("less flatness", "less flat"), ("lose the flatness", "less flat"), ("more smoothness", "more smooth")],
)
def test_a_quality_named_with_ness_is_its_adjective(line: str, plain: str) -> None:
    said, bare = Session("navy blue paint", LEX), Session("navy blue paint", LEX)
    assert said.refine(line)["params"]["roughness"] == bare.refine(plain)["params"]["roughness"]


@pytest.mark.parametrize("line", ["with a glossier finish", "give it a glossier finish"])
def test_a_comparative_said_of_the_finish_after_with_is_the_comparative(line: str) -> None:
    said, bare = Session("oak worktop", LEX), Session("oak worktop", LEX)
    assert said.refine(line)["params"]["roughness"] == bare.refine("glossier")["params"]["roughness"]


def test_an_echoing_idiom_read_past_leaves_no_error_of_its_words() -> None:
    session = Session("grey concrete floor", LEX)
    session.refine("too shiny, can we knock it back")
    assert not [d for d in session.result.diagnostics if d.severity.value in ("error", "warning")]


# ---------------------------------------------------------------- 'almost X', tiles of a patterned stone


@pytest.mark.parametrize(("text", "most"), [("almost black paint", 0.2), ("not quite black", 0.2)])
def test_almost_a_colour_is_nearly_that_colour_to_the_eye(text: str, most: float) -> None:
    """A share of the way in OKLab: a linear blend left 'almost black' paint a mid grey (L 0.5)."""
    assert lch(material(text)["params"]["base_color"])[0] < most


def test_almost_navy_is_a_dark_blue() -> None:
    L, C, h = lch(material("almost navy")["params"]["base_color"])
    assert L < 0.45 and C > 0.04 and 220 < h < 300


@pytest.mark.parametrize("text", ["slate tiles", "Dark Grey Slate Tiles", "limestone tiles in the hallway"])
def test_tiles_of_a_patterned_stone_show_their_joints(text: str) -> None:
    maps = material(text)["maps"]
    assert maps["normal"]["graph"] == "tiles" and maps["base_color"]["graph"] != "tiles"


@pytest.mark.parametrize("text", ["marble tiles with dark grout", "slate tiles with white grout"])
def test_grout_said_takes_the_place_of_the_implied_joints(text: str) -> None:
    result = compiled(text)
    name = result.ir["materials"][0]["name"]
    assert "grout" in name and "joints" not in name, name
    assert not any("with joints" in d.message for d in result.diagnostics)


# ---------------------------------------------------------------- liking, reasons, idioms with their object


@pytest.mark.parametrize(("text", "plain"), [("a nice warm terracotta", "a warm terracotta"), ("lovely oak", "oak")])
def test_a_word_of_liking_has_no_effect_on_the_look(text: str, plain: str) -> None:
    assert same_look(material(text), material(plain))
    assert any("you like it" in d.message for d in compiled(text).diagnostics)


@pytest.mark.parametrize(
    ("phrase", "line", "plain"),
    [
        ("white marble floor", "less shiny, people will slip", "less shiny"),
        ("white marble floor", "darker, because the room is bright", "darker"),
        ("terracotta tiles", "too orange, tone the colour down", "less orange"),
        ("shiny brass", "too shiny, tone the shine down", "less shiny"),
        ("sky blue linen", "can we see it in mustard", "make it mustard"),
        ("dark grey paint", "can it have a hint of blue in it", "with a hint of blue"),
    ],
)
def test_a_reason_or_an_echo_beside_the_change_is_read_past(phrase: str, line: str, plain: str) -> None:
    said, bare = Session(phrase, LEX), Session(phrase, LEX)
    assert same_look(said.refine(line), bare.refine(plain))


# ---------------------------------------------------------------- 'nothing shiny', describing parts, verdicts


def test_nothing_negates_as_not() -> None:
    assert same_look(material("nothing shiny"), material("not shiny paint"))
    # 'nothing too shiny' is 'not too shiny' (the finish between: satin), never 'slightly shiny'
    assert same_look(material("nothing too shiny plastic"), material("satin plastic"))
    session = Session("glossy oak flooring", LEX)
    before = session.material["params"]["roughness"]
    assert session.refine("nothing too shiny")["params"]["roughness"] > before


@pytest.mark.parametrize(
    ("phrase", "line", "plain"),
    [
        ("smooth concrete wall", "lighter, almost white", "lighter, make it almost white"),
        ("red plastic", "darker, glossy", "darker, make it glossy"),
        ("matte white cabinets", "actually, try them in a sage green", "make it sage green"),
    ],
)
def test_a_describing_part_beside_a_comparative_is_a_change(phrase: str, line: str, plain: str) -> None:
    said, bare = Session(phrase, LEX), Session(phrase, LEX)
    assert same_look(said.refine(line), bare.refine(plain))


def test_almost_before_a_colour_is_its_degree_and_alone_a_verdict() -> None:
    assert colour_after("red plastic", "almost black") != colour_after("red plastic", "black")
    assert colour_after("smooth concrete wall", "almost, but a bit darker") == colour_after(
        "smooth concrete wall", "a bit darker"
    )


def test_a_described_thing_without_a_material_is_painted_with_a_note() -> None:
    """'a red bike': WordNet 3.0 lists 'bike' as an artifact; its colour and finish go on paint."""
    result = compiled("a red bike with a glossy clear coat")
    assert same_look(result.ir["materials"][0], material("red paint with a glossy clear coat"))
    assert any("WordNet 3.0 lists 'bike' as an artifact" in d.message for d in result.diagnostics)
    assert [d.code for d in compiled("a red blorf").diagnostics if d.is_error] == ["E001"]  # no noun: still an error


def test_natural_white_is_the_surveys_off_white_in_english_and_german() -> None:
    assert same_look(material("linen in natural white"), material("off-white linen"))
    de = lexicon_for(["de"])
    said = compile_source("Leinen in Naturweiß\n", "t.cnl", de).ir["materials"][0]
    assert said["params"]["base_color"] == material("off-white linen")["params"]["base_color"]


@pytest.mark.parametrize(
    ("text", "plain"),
    [("a slightly darker shade of oak", "slightly darker oak"), ("a darker shade of oak", "darker oak")],
)
def test_a_comparative_shade_of_a_material_is_the_materials_comparative(text: str, plain: str) -> None:
    assert same_look(material(text), material(plain))
    assert not [d for d in compiled(text).diagnostics if d.is_error]


def test_a_coat_said_alone_under_a_material_is_added_to_it() -> None:
    said, bare = Session("rough sawn pine", LEX), Session("rough sawn pine", LEX)
    coated = said.refine("a glossy varnish")
    assert said.lines[-1] == "with a glossy varnish" and coated == bare.refine("with a glossy varnish")
    assert Session("oak", LEX).refine("walnut")["params"]["base_color"] == material("walnut")["params"]["base_color"]


@pytest.mark.parametrize(
    ("text", "plain"),
    [
        ("walls in a flat pale grey", "flat pale grey walls"),
        ("the front door in a glossy oxblood red", "glossy oxblood red door"),
    ],
)
def test_describing_words_after_in_describe_the_material(text: str, plain: str) -> None:
    assert same_look(material(text), material(plain))


@pytest.mark.parametrize(
    ("text", "plain"),
    [
        ("faux sheepskin", "sheepskin"),
        ("recycled plastic", "plastic"),
        ("not transparent at all", "not transparent paint"),
    ],
)
def test_what_a_thing_is_made_from_and_emphasis_read_as_the_plain_phrase(text: str, plain: str) -> None:
    assert same_look(material(text), material(plain))


@pytest.mark.parametrize(
    ("phrase", "line", "plain"),
    [
        ("pine planks", "stain them darker", "darker"),
        ("pine planks", "too yellow, can we calm that down", "less yellow"),
        ("glossy red plastic", "and tone the red down", "less red"),
        ("raw concrete wall", "that's too dark for the room", "less dark"),
    ],
)
def test_verbs_of_a_change_and_where_it_is_read_as_the_change(phrase: str, line: str, plain: str) -> None:
    said, bare = Session(phrase, LEX), Session(phrase, LEX)
    assert same_look(said.refine(line), bare.refine(plain))


@pytest.mark.parametrize(
    ("phrase", "line", "plain"),
    [
        ("brushed stainless steel", "the brushing is too strong", "less brushing"),
        ("white Carrara marble", "the veining is a bit too busy", "a bit less veining"),
        ("oak", "the grain is too strong", "less grain"),
        ("oak", "the colour is too dark", "less dark"),  # a describing word says what is too much
    ],
)
def test_a_complaint_about_a_named_feature_is_less_of_it(phrase: str, line: str, plain: str) -> None:
    said, bare = Session(phrase, LEX), Session(phrase, LEX)
    assert said.refine(line) == bare.refine(plain)
