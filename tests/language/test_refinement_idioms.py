"""Refinement lines said the way people talk (issue #14): verb-and-'it' idioms ('tone it down',
'warm it up'), an idiom that only echoes the other part of its line ('too glossy, can we knock it
back'), a complaint made by a degree word ("it's a bit dark"), requests ('can we go …', 'can you do
it in …'), 'same again but …', what a verb brings it to ('sand it to a matte finish'), a likeness of
a state ("like it's just been rained on"), 'all the' in a removal and place words read past.

The phrases are not the ones of the held-out sets: each category is tested on words of its own.
"""

import pytest

from cnlmc.api import Session, compile_source, refined
from cnlmc.colour import linear_to_oklab


def oklch(material):
    lab = linear_to_oklab(material["params"]["base_color"])
    return lab[0], (lab[1] ** 2 + lab[2] ** 2) ** 0.5


def refine(first, *lines):
    session = Session(first)
    before = session.result.ir["materials"][-1]
    for line in lines:
        session.refine(line)
    result = session.result
    assert result.ok, [d.message for d in result.diagnostics]
    assert not [d for d in result.diagnostics if d.code.startswith("E")]
    return before, result.ir["materials"][-1], result


@pytest.mark.parametrize("line", ["tone it down", "tone it down a little", "can we tame it", "dial it down a touch"])
def test_an_idiom_alone_is_its_comparative(line):
    before, after, _ = refine("bright orange plastic", line)
    assert oklch(after)[1] < oklch(before)[1]
    assert after["params"]["roughness"] == before["params"]["roughness"]


@pytest.mark.parametrize(
    "line,key,sign",
    [("warm it up", "hue", None), ("dull it down", "roughness", 1), ("lighten it up a bit", "lightness", 1)],
)
def test_idioms_name_their_direction(line, key, sign):
    before, after, _ = refine("slate blue paint", line)
    if key == "roughness":
        assert (after["params"]["roughness"] - before["params"]["roughness"]) * sign > 0
    elif key == "lightness":
        assert (oklch(after)[0] - oklch(before)[0]) * sign > 0
    else:
        assert after["params"]["base_color"] != before["params"]["base_color"]


def test_an_idiom_beside_a_complaint_only_echoes_it():
    """'way too glossy, could we knock it back': the complaint says what; the idiom adds no greying."""
    before, after, result = refine("dark teal gloss paint", "way too glossy, could we knock it back a bit")
    assert after["params"]["roughness"] > before["params"]["roughness"]
    assert after["params"]["base_color"] == before["params"]["base_color"]
    assert any("read past" in d.message and "knock it back" in d.message for d in result.diagnostics)


@pytest.mark.parametrize("line", ["it's a bit dark", "that's rather dark", "it looks kind of dark"])
def test_a_degree_after_an_opener_is_a_complaint(line):
    before, after, _ = refine("forest green velvet", line)
    assert oklch(after)[0] > oklch(before)[0]


def test_a_loud_colour_is_a_vivid_one_and_a_complaint_about_it_mutes_it():
    before, after, _ = refine("lime green plastic", "that's a bit garish, tone it down")
    assert oklch(after)[1] < oklch(before)[1]


def test_a_report_of_a_comparative_is_no_complaint(stdlib):
    """ "it's a bit darker now" reports a comparative: it is not rewritten as 'a bit less darker'."""
    text, _ = refined("red plastic", "it's a bit darker now", stdlib, "t")
    assert text.splitlines()[-1] == "it's a bit darker now"


@pytest.mark.parametrize(
    "line",
    [
        "can we go a touch lighter",
        "could we go lighter",
        "shall we go lighter",
        "lighter though",
        "lighter then, please",
    ],
)
def test_requests_and_fillers_around_a_comparative(line):
    before, after, _ = refine("walnut", line)
    assert oklch(after)[0] > oklch(before)[0]


@pytest.mark.parametrize(
    "line",
    [
        "same again but in pale blue",
        "same again, but pale blue",
        "can you do it in pale blue",
        "go back to the pale blue",
    ],
)
def test_change_requests_take_the_new_colour(line):
    _, after, _ = refine("matte white ceramic", line)
    expected = Session("matte pale blue ceramic").result.ir["materials"][-1]
    assert after["params"]["base_color"] == expected["params"]["base_color"]
    assert after["params"]["roughness"] == expected["params"]["roughness"]


@pytest.mark.parametrize(
    "line,expected",
    [
        ("sand it to a matte finish", "matte sanded oak"),
        ("polish it up to a mirror", "mirror polished oak"),
        ("polish it to a high shine", "highly polished oak"),
    ],
)
def test_what_a_verb_brings_it_to_is_its_result(line, expected):
    _, after, _ = refine("oak", line)
    want = Session(expected).result.ir["materials"][-1]
    assert abs(after["params"]["roughness"] - want["params"]["roughness"]) < 0.05


@pytest.mark.parametrize("line", ["like it's just been rained on", "as if it had been rained on", "rained on"])
def test_a_likeness_of_a_state_is_that_state(line):
    before, after, _ = refine("concrete", line)
    assert oklch(after)[0] < oklch(before)[0]
    assert after["params"]["roughness"] < before["params"].get("roughness", 1.0)  # diffuse: fully rough


@pytest.mark.parametrize(
    "line", ["clean off all the scratches", "get rid of all the scratches", "remove any scratches"]
)
def test_all_the_in_a_removal(line):
    _, after, _ = refine("scratched chrome", line)
    assert after["maps"] == Session("chrome").result.ir["materials"][-1]["maps"]


@pytest.mark.parametrize(
    "line", ["add some scratches all over", "add a few scratches to the surface", "add scratches overall"]
)
def test_place_words_after_a_clause_are_read_past(line):
    _, after, result = refine("polished brass", line)
    assert after["maps"], "the scratches are drawn"
    assert any("read past" in d.message for d in result.diagnostics)


@pytest.mark.parametrize(
    "phrase,plain,name,key,sign",
    [
        ("the darkest navy you can do", "dark navy", "darkest_navy_paint", "lightness", -1),
        ("palest pink linen", "pale pink linen", "palest_pink_linen", "lightness", 1),
        ("the shiniest chrome possible", "shiny chrome", "shiniest_chrome", "roughness", -1),
    ],
)
def test_a_superlative_is_its_word_at_full_strength(compile_text, phrase, plain, name, key, sign):
    """'-est' reads as 'intensely' on the word (further than the word alone); the default name
    keeps the word as written."""
    got, want = compile_text(phrase), compile_text(plain)
    assert got.ok, [d.message for d in got.diagnostics]
    g, w = got.ir["materials"][0], want.ir["materials"][0]
    if key == "lightness":
        assert (oklch(g)[0] - oklch(w)[0]) * sign > 0
    else:
        assert (g["params"]["roughness"] - w["params"]["roughness"]) * sign > 0
    assert g["name"] == name


@pytest.mark.parametrize(
    "line,key",
    [("the colour's a bit garish", "chroma"), ("the finish looks too glossy, can we dull it down", "roughness")],
)
def test_a_complaint_about_the_colour_or_the_finish(line, key):
    before, after, _ = refine("lime green gloss paint", line)
    if key == "chroma":
        assert oklch(after)[1] < oklch(before)[1]
    else:
        assert after["params"]["roughness"] > before["params"]["roughness"]
        assert after["params"]["base_color"] == before["params"]["base_color"]


@pytest.mark.parametrize(
    "line,key,sign",
    [
        ("ugh, that's way too glossy", "roughness", 1),
        ("more muted, it's a bit garish", "chroma", -1),
        ("it's coming across a bit too dark, can we go lighter", "lightness", 1),
        ("give it a bit more shine", "roughness", -1),
    ],
)
def test_openers_in_a_row_and_complaints_in_each_part(line, key, sign):
    before, after, _ = refine(
        "lime green gloss paint" if key != "roughness" or sign > 0 else "satin lime green paint", line
    )
    if key == "roughness":
        assert (after["params"]["roughness"] - before["params"]["roughness"]) * sign > 0
    else:
        index = 0 if key == "lightness" else 1
        assert (oklch(after)[index] - oklch(before)[index]) * sign > 0


@pytest.mark.parametrize("line", ["what about it in forest green", "keep the grain but make it forest green"])
def test_more_change_requests(line):
    _, after, _ = refine("pale oak", line)
    assert oklch(after)[0] < 0.5


@pytest.mark.parametrize("line,same_as", [("let it weather", "weather it"), ("let it age a bit", "age it a bit")])
def test_let_it_is_the_verb_on_the_material(line, same_as):
    _, got, _ = refine("teak", line)
    _, want, _ = refine("teak", same_as)
    assert got["params"] == want["params"] and got["params"] != Session("teak").result.ir["materials"][-1]["params"]


def test_an_idiom_beside_another_request_is_applied_too():
    """'warmer, tone it down a bit': no complaint to echo, so both parts apply."""
    _, warmer, _ = refine("bright orange plastic", "warmer")
    _, both, _ = refine("bright orange plastic", "warmer, tone it down a bit")
    assert oklch(both)[1] < oklch(warmer)[1]


def test_something_keeps_its_degree():
    _, some, _ = refine("red plastic", "something a bit darker")
    _, full, _ = refine("red plastic", "darker")
    assert oklch(some)[0] > oklch(full)[0]


def test_a_colour_ending_in_er_after_an_opener_is_a_complaint(stdlib):
    text, _ = refined("red plastic", "it's a bit amber", stdlib, "t")
    assert text.splitlines()[-1].endswith("a bit less amber")


def test_a_comparative_the_lexicon_lacks_is_more_of_its_adjective():
    """'waxier' = more waxy (word_formation.toml: X-er on an adjective without a comparative)."""
    _, got, result = refine("oak", "waxier")
    _, want, _ = refine("oak", "more waxy")
    assert got["params"] == want["params"]
    assert any("'more waxy'" in d.message for d in result.diagnostics)


@pytest.mark.parametrize(
    ("line", "rougher"),
    [("less mirror", True), ("it's too mirror-like", True), ("less satin", False), ("less satin, please", False)],
)
def test_a_describing_word_after_less_is_its_target_not_a_new_material(line, rougher):
    """'mirror' and 'satin' are also materials; after 'less'/'more' (which need a target) they are
    what to move, not a change to that material ('less' of what?)."""
    first, changed, result = refine("chrome light fittings", line)
    assert not any(d.code == "W104" for d in result.diagnostics), [d.message for d in result.diagnostics]
    assert changed["model"]["base"] == "conductor"  # still chrome, not a mirror or satin cloth
    moved = changed["params"]["roughness"] - first["params"]["roughness"]
    assert moved > 0 if rougher else moved < 0  # less satin than chrome's near mirror: glossier still


def test_a_comparative_with_its_own_target_keeps_the_material_after_it():
    assert compile_source("shinier satin\n", "r.cnl").ir["materials"][0]["model"]["base"] != "conductor"


def test_less_of_the_is_less_not_none():
    """'less of the orange' under oak is 'less orange' (it named no colour to take off); 'less of
    the rust' keeps rust, less of it (a removal would take it all: 'lose the rust')."""
    before, after, result = refine("oak worktop", "less of the orange")
    assert oklch(after)[1] < oklch(before)[1]
    assert any("less of it, not none" in d.message for d in result.diagnostics)
    _, lessened, _ = refine("rusty steel", "less of the rust")
    _, removed, _ = refine("rusty steel", "lose the rust")
    assert "mask" in lessened["maps"] and lessened != removed


def test_an_er_comparative_of_a_shade():
    before, after, _ = refine("red paint", "punchier")
    assert oklch(after)[1] > oklch(before)[1]


def test_a_finish_is_a_description_at_the_end_of_a_line_too():
    """'a satin finish' under oak is satin oak (the finish), not satin cloth; alone, satin paint."""
    before, after, _ = refine("oak", "a satin finish")
    assert after["maps"] == before["maps"] and after["params"]["roughness"] < before["params"]["roughness"]
    alone = compile_source("a satin finish\n", "f.cnl").ir["materials"][0]
    assert "diffuse_roughness" not in alone["params"] and alone["params"]["roughness"] == 0.35


@pytest.mark.parametrize(
    ("line", "key", "direction"),
    [
        ("it needs to be shinier", "roughness", -1),
        ("could be more reflective", "roughness", -1),
        ("it should be darker", "lightness", -1),
        ("I'd like it warmer", "hue", 0),
        ("perfect, but a little darker", "lightness", -1),
        ("nearly, just a bit lighter", "lightness", 1),
        ("one shade darker", "lightness", -1),
        ("a couple of shades lighter", "lightness", 1),
        ("bring the gloss down", "roughness", 1),
        ("knock back the shine", "roughness", 1),
        ("take the edge off the shine", "roughness", 1),
        ("a warmer tone", "hue", 0),
        ("make it pop", "chroma", 1),
    ],
)
def test_everyday_change_phrasing(line, key, direction):
    """A need, a wish or a verdict before the change, counts of shades, a verb with its object and
    particle, a colour's tone: each moves the material as the plain change would."""
    before, after, _ = refine("red plastic", line)
    if key == "roughness":
        moved = after["params"]["roughness"] - before["params"]["roughness"]
    elif key == "hue":
        assert after["params"]["base_color"] != before["params"]["base_color"]
        return
    else:
        moved = oklch(after)[0 if key == "lightness" else 1] - oklch(before)[0 if key == "lightness" else 1]
    assert moved * direction > 0, (line, moved)


def test_two_shades_is_a_larger_step_than_one():
    _, one, _ = refine("red plastic", "one shade darker")
    _, two, _ = refine("red plastic", "two shades darker")
    assert oklch(two)[0] < oklch(one)[0]
