"""Taking words off the material above ('lose the brushed look', 'no rust'), refinement lines of
several parts ('deeper, more of a burgundy'), 'closer' to a named colour, and a change to a
material said as a comparison ('more like a dark walnut'). Issue #14.

The phrases are not the ones of the held-out sets: each category is tested on words of its own.
"""

import pytest

from cnlmc import ast
from cnlmc.api import Session
from cnlmc.colour import linear_to_oklab


def material(result):
    assert result.ok, [d.message for d in result.diagnostics]
    return result.ir["materials"][-1]


def codes(result):
    return [d.code for d in result.diagnostics]


@pytest.mark.parametrize(
    "above,line,same_as",
    [
        ("brushed stainless steel", "lose the brushed look", "stainless steel"),
        ("brushed stainless steel", "could we drop the brushing?", "stainless steel"),
        ("heavily brushed titanium", "not brushed", "titanium"),
        ("rusty cast iron", "get rid of the rust", "cast iron"),
        ("scratched chrome", "no scratches", "chrome"),
        ("copper with a green patina", "take the patina off", "copper"),
        ("walnut with a satin varnish", "strip the varnish", "walnut"),
        ("oak with a clear coat", "without the clear coat, please", "oak"),
        ("blue anodized aluminum with fine scratches", "ok, can you remove the scratches", "blue anodized aluminum"),
        ("shiny black plastic", "lose the shine", "black plastic"),
    ],
)
def test_a_removal_takes_the_words_off_and_keeps_the_rest(compile_text, above, line, same_as):
    removed = compile_text(f"{above}\n{line}\n")
    expected = material(compile_text(same_as))
    got = material(removed)
    assert (got["params"], got["maps"], got["model"]) == (expected["params"], expected["maps"], expected["model"])
    assert any("off the material above" in d.message for d in removed.diagnostics)


def test_a_removal_keeps_the_refinements_below_and_above_in_order(compile_text):
    lines = "lightly brushed blue anodized aluminum\ndarker\nlose the brushing\nrougher\n"
    expected = material(compile_text("blue anodized aluminum\ndarker\nrougher\n"))
    assert material(compile_text(lines))["params"] == expected["params"]


def test_a_removal_of_what_the_material_lacks_warns(compile_text):
    result = compile_text("polished brass\nno rust\n")
    assert "W122" in codes(result)
    assert material(result)["params"] == material(compile_text("polished brass"))["params"]


def test_a_removal_of_a_property_the_material_lacks_reads_as_less_of_it(compile_text):
    """'lose the shine' under a material without 'shiny': less gloss, with a note (not W122)."""
    result = compile_text("glossy red plastic\nlose the shine\n")
    assert "W122" not in codes(result)
    assert material(result)["params"] == material(compile_text("glossy red plastic\nless shine\n"))["params"]


def test_a_removal_with_no_material_above_is_w104(compile_text):
    assert "W104" in codes(compile_text("lose the rust\n"))


@pytest.mark.parametrize("line", ["not weathered copper", "no gloss", "not polished marble"])
def test_a_negated_description_stays_a_description(compile_text, line):
    """A line that names a material, or a negated word with a reading of its own ('no gloss' =
    matte), is not a removal."""
    result = compile_text(line)
    assert not any("off the material above" in d.message for d in result.diagnostics)
    assert result.ok


def test_a_removal_node_carries_the_words(stdlib):
    from cnlmc.document import parse_document

    doc = parse_document("rusty steel\nplease get rid of the rust and the scratches\n", stdlib)
    change = doc.items[1]
    assert isinstance(change, ast.Refinement) and change.changes_material
    assert {w.text for w in change.removed} == {"rust", "scratches"}


def test_a_session_takes_words_off(stdlib):
    session = Session("lightly brushed red anodized aluminum", stdlib)
    session.refine("can we lose the brushed look")
    assert session.material["params"] == Session("red anodized aluminum", stdlib).material["params"]


# ---- parts of a refinement line, each said its own way


@pytest.mark.parametrize(
    "line,same_as",
    [
        ("a little lighter, more of a sage", "a little lighter\nmore of a sage"),
        ("slightly rougher, less shine please", "slightly rougher\nless shine"),
        ("a touch glossier, same colour", "a touch glossier"),
        ("warmer, keep the finish", "warmer"),
    ],
)
def test_a_line_of_parts_is_each_part_in_turn(compile_text, line, same_as):
    above = "pale green ceramic tile"
    joined = compile_text(f"{above}\n{line}\n")
    assert not [d for d in joined.diagnostics if d.is_error]
    assert material(joined)["params"] == material(compile_text(f"{above}\n{same_as}\n"))["params"]


def test_a_line_of_parts_with_an_unknown_word_is_still_an_error(compile_text):
    result = compile_text("oak\ndarker, more zorbly\n")
    assert any(d.code == "E001" for d in result.diagnostics)


# ---- closer to a named colour; a comparison that names a material


def test_closer_to_a_colour_moves_lightness_too(compile_text):
    """'more of a navy' on sky blue: darker and nearer navy's hue, where 'more blue' keeps the
    lightness."""
    base = linear_to_oklab(material(compile_text("sky blue paint"))["params"]["base_color"])
    navy = linear_to_oklab(material(compile_text("navy paint"))["params"]["base_color"])
    closer = linear_to_oklab(material(compile_text("sky blue paint\nmore of a navy\n"))["params"]["base_color"])
    assert closer[0] < base[0]
    before = sum((b - n) ** 2 for b, n in zip(base, navy))
    after = sum((c - n) ** 2 for c, n in zip(closer, navy))
    assert after < before * 0.6


def test_closer_twice_goes_further(compile_text):
    once = material(compile_text("white paint\ncloser to navy\n"))["params"]["base_color"]
    twice = material(compile_text("white paint\ncloser to navy\ncloser to navy\n"))["params"]["base_color"]
    assert linear_to_oklab(twice)[0] < linear_to_oklab(once)[0] < 1.0


@pytest.mark.parametrize(
    "above,line,same_as",
    [
        ("white varnished ash", "more like maple", "white varnished maple"),
        ("pale oak", "hmm, more like a dark cherry", "dark cherry"),
        ("red plastic", "closer to brass", "brass"),
        ("red plastic", "closer to bronze", "red plastic\nmake it bronze"),  # another kind, a colour too: the colour
    ],
)
def test_a_comparison_that_names_a_material_changes_to_it(compile_text, above, line, same_as):
    got = material(compile_text(f"{above}\n{line}\n"))
    expected = material(compile_text(same_as))
    assert got["params"] == expected["params"]


@pytest.mark.parametrize("listed", ["a cooler, darker slate", "richer, deeper red velvet"])
def test_comparatives_listed_before_a_material(compile_text, listed):
    *comparatives, _ = listed.replace("a ", "", 1).split(", ")
    result = compile_text(listed)
    assert result.ok and not result.diagnostics


def test_deeper_alone_is_a_richer_darker_colour(compile_text):
    before = linear_to_oklab(material(compile_text("terracotta tile"))["params"]["base_color"])
    after = linear_to_oklab(material(compile_text("terracotta tile\ndeeper\n"))["params"]["base_color"])
    chroma = lambda lab: (lab[1] ** 2 + lab[2] ** 2) ** 0.5
    assert after[0] < before[0] and chroma(after) > chroma(before)


def test_a_noun_that_is_also_a_finish_is_the_finish_on_another_kind(compile_text):
    """'make it satin' under glazed tile is the satin finish; under cotton it is satin the fabric."""
    tile = material(compile_text("white ceramic tile\nmake it satin\n"))
    assert tile["params"] == material(compile_text("white satin ceramic tile"))["params"]
    fabric = compile_text("cotton\nmake it satin\n")
    assert material(fabric)["name"] != "cotton" and material(fabric)["model"]["diffuse"] == "oren_nayar"


def test_a_removal_of_what_the_noun_brings_is_much_less_of_it(compile_text):
    """'no veins' under marble: the veins are the noun's, not a word's: much less of them, a note."""
    result = compile_text("white marble\nno veins\n")
    assert "W122" not in codes(result)
    assert material(result)["maps"] == material(compile_text("white marble\nmuch less veins\n"))["maps"]
    assert material(result)["maps"] != material(compile_text("white marble"))["maps"]
