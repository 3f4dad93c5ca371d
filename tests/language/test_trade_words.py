"""Trade and everyday words for materials (issue #14, session 14): each word is checked by what it
looks like (its apparent colour's OKLCh family, lightness and gloss), not only that it compiles.

The phrases are not the ones of the held-out sets: each word is tested in a phrase of its own."""

import math

import pytest

from cnlmc.colour import linear_to_oklab


def material(result):
    assert result.ok, [d.message for d in result.diagnostics]
    assert not [d for d in result.diagnostics if d.severity.name == "WARNING"]
    return result.ir["materials"][-1]


def lch(colour):
    L, a, b = linear_to_oklab(colour)
    return L, math.hypot(a, b), math.degrees(math.atan2(b, a)) % 360


@pytest.mark.parametrize(
    "phrase,hue_range,lightness_range",
    [
        ("oiled pearwood", (20, 75), (0.5, 0.8)),  # a pinkish light brown, not the fruit's green
        ("hinoki wood", (50, 95), (0.7, 0.95)),  # pale lemony cream
        ("weathered bath stone", (50, 95), (0.6, 0.9)),  # honey limestone
        ("a London stock brick", (45, 95), (0.45, 0.8)),  # yellow-buff, not red
        ("egg yolk paint", (45, 85), (0.65, 0.95)),  # deep orange-yellow
    ],
)
def test_named_materials_and_colours_have_their_colour(compile_text, phrase, hue_range, lightness_range):
    L, C, h = lch(material(compile_text(phrase))["params"]["base_color"])
    assert C > 0.03 and hue_range[0] <= h <= hue_range[1], (phrase, h)
    assert lightness_range[0] <= L <= lightness_range[1], (phrase, L)


@pytest.mark.parametrize("phrase", ["oyster silk", "glacier white acrylic", "arctic white paint"])
def test_pale_trade_whites_are_near_white(compile_text, phrase):
    L, C, _ = lch(material(compile_text(phrase))["params"]["base_color"])
    assert L > 0.85 and C < 0.03


@pytest.mark.parametrize("phrase", ["a bone china cup", "blue delftware", "majolica"])
def test_glazed_ceramics_are_glossy(compile_text, phrase):
    assert material(compile_text(phrase))["params"]["roughness"] <= 0.1


@pytest.mark.parametrize(
    "phrase,same_as",
    [
        ("ivory dupion", "ivory dupioni"),
        ("grey EPDM membrane", "grey rubber"),
        ("chunky yarn", "wool"),
        ("silver tri-coat", "silver car paint"),
        ("french-polished mahogany", "varnished mahogany"),
        ("a gin and tonic", "vodka"),
        ("oak with a whitewash finish", "whitewashed oak"),
    ],
)
def test_trade_names_mean_their_material(compile_text, phrase, same_as):
    got, want = material(compile_text(phrase)), material(compile_text(same_as))
    assert (got["model"], got["params"]) == (want["model"], want["params"])


def test_a_fiddleback_figure_is_bolder_grain(compile_text):
    plain = material(compile_text("sycamore"))["maps"]["base_color"]["params"]
    figured = material(compile_text("fiddleback sycamore"))["maps"]["base_color"]["params"]
    assert figured["contrast"] > plain.get("contrast", 1.0) and figured["ring_scale"] > plain.get("ring_scale", 1.0)


def test_calacatta_viola_has_violet_veins(compile_text):
    veins = material(compile_text("calacatta viola marble"))["maps"]["base_color"]["params"]
    L, C, h = lch([veins["color_r"], veins["color_g"], veins["color_b"]])
    assert veins["color_amount"] > 0.5 and (h > 330 or h < 20) and C > 0.05


@pytest.mark.parametrize(
    "phrase,same_as",
    [
        ("stone-built", "stone"),
        ("stone-faced", "stone"),
        ("a rust-stained steel plate", "rusty steel"),
        ("anti-slip rubber", "textured rubber"),
        ("Nordic-style limed ash", "limed ash"),
        ("no sheen whatsoever", "matte"),
        ("verde alpi", "serpentine"),
    ],
)
def test_listing_words_mean_their_material(compile_text, phrase, same_as):
    got, want = material(compile_text(phrase)), material(compile_text(same_as))
    assert (got["model"], got["params"], got["maps"]) == (want["model"], want["params"], want["maps"])


def test_an_undertone_is_a_tint(compile_text):
    got = material(compile_text("grey with a cool undertone"))
    assert got["params"] == material(compile_text("grey with a cool tint"))["params"]


def test_delft_blue_is_a_deep_blue_and_rose_a_pale_pink_wine(compile_text):
    L, C, h = lch(material(compile_text("delft blue tiles"))["params"]["base_color"])
    assert 240 <= h <= 290 and L < 0.45
    wine = material(compile_text("a glass of rosé"))
    assert wine["model"]["base"] == "glass"
    L, C, h = lch(wine["params"]["base_color"])
    assert (h < 60 or h > 340) and L > 0.6


@pytest.mark.parametrize(
    "phrase,same_as", [("white gloss", "white glossy paint"), ("midnight blue gloss", "glossy midnight blue paint")]
)
def test_a_colour_then_gloss_is_glossy_paint_of_that_colour(compile_text, phrase, same_as):
    got, want = material(compile_text(phrase)), material(compile_text(same_as))
    assert got["params"] == want["params"]


def test_crystal_clear_is_clear_and_contradicts_frosted(compile_text):
    assert (
        material(compile_text("crystal-clear acrylic"))["params"] == material(compile_text("clear acrylic"))["params"]
    )
    result = compile_text("frosted crystal clear glass")
    assert [d.code for d in result.diagnostics if d.severity.name == "WARNING"] == ["W101"]


@pytest.mark.parametrize(
    "phrase,same_as",
    [
        ("linen with a loose weave", "linen with a strong weave"),
        ("wool with a chunky weave", "wool with a strong weave"),
    ],
)
def test_weave_words_are_degrees(compile_text, phrase, same_as):
    got, want = material(compile_text(phrase)), material(compile_text(same_as))
    assert (got["params"], got["maps"]) == (want["params"], want["maps"])


@pytest.mark.parametrize(
    "phrase,same_as",
    [
        ("mid-grey wool", "medium grey wool"),
        ("an oak floor for the kitchen", "oak"),
        ("limestone tiles in the hallway", "limestone tiles"),
        ("kind of like brass", "brass"),
        ("that sage green", "sage green paint"),
        ("brass with a verdigris bloom", "brass with a verdigris patina"),
        ("a barely-there sheen", "a barely sheen"),
        ("worn-in leather", "worn leather"),
        ("a mug of hot cocoa", "chocolate"),
    ],
)
def test_more_everyday_words(compile_text, phrase, same_as):
    got, want = material(compile_text(phrase)), material(compile_text(same_as))
    assert (got["model"], got["params"], got["maps"]) == (want["model"], want["params"], want["maps"])


def test_beeswax_is_honey_yellow_and_chalky_is_matte(compile_text):
    L, C, h = lch(material(compile_text("natural beeswax"))["params"]["base_color"])
    assert 55 <= h <= 95 and C > 0.08
    assert material(compile_text("chalky white paint"))["params"]["roughness"] >= 0.8


@pytest.mark.parametrize(
    "phrase,same_as",
    [("Kiefer massiv, geölt", "geölte Kiefer"), ("Räucherkiefer", "geräucherte Kiefer"), ("Ahorn furniert", "Ahorn")],
)
def test_german_listing_words(phrase, same_as):
    from cnlmc.api import compile_source, lexicon_for

    de = lexicon_for(("de",))
    got, want = compile_source(phrase, "t", de), compile_source(same_as, "t", de)
    assert got.ok and want.ok, [d.message for d in got.diagnostics]
    assert got.ir["materials"][0]["params"] == want.ir["materials"][0]["params"]


def test_arolla_pine_is_a_pale_yellow_softwood(compile_text):
    L, C, h = lch(material(compile_text("swiss stone pine"))["params"]["base_color"])
    assert L > 0.7 and 50 <= h <= 90


@pytest.mark.parametrize(
    "phrase,same_as",
    [("quarter-sawn sycamore", "sycamore"), ("rift-sawn ash", "ash"), ("wide-plank oak floorboards", "oak")],
)
def test_how_boards_are_cut_is_read_past(compile_text, phrase, same_as):
    got, want = material(compile_text(phrase)), material(compile_text(same_as))
    assert got["params"] == want["params"]


def test_wide_grained_stays_coarse_grained(compile_text):
    got = material(compile_text("wide grained oak"))
    assert got["params"] == material(compile_text("coarse-grained oak"))["params"]
    assert got["maps"] == material(compile_text("coarse-grained oak"))["maps"]


@pytest.mark.parametrize(
    ("said", "meant"), [("satinwood paint", "satin paint"), ("white satinwood", "white satin paint")]
)
def test_satinwood_is_the_paint_trades_satin(compile_text, said, meant):
    assert material(compile_text(said))["params"] == material(compile_text(meant))["params"]


@pytest.mark.parametrize("phrase", ["white semi-gloss", "navy semi-gloss", "grey satinwood"])
def test_a_colour_and_a_sheen_alone_are_paint(compile_text, phrase):
    """A finish word any material takes, with a colour and no material: an everyday noun (paint),
    not the finish word's own example ('satin nickel')."""
    got = material(compile_text(phrase))
    assert got["model"]["base"] == "dielectric" and got["name"].endswith("_paint"), got["name"]
