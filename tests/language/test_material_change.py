"""A change line that names a material (issue #14): 'make it walnut' under 'white varnished oak' is
white varnished walnut; another kind of material replaces the one above; a noun that is also a
colour is the colour where the kinds differ ('make it cream' under red plastic)."""

from __future__ import annotations

import pytest

from cnlmc import api

LEX = api.lexicon_for()


def session(first: str, *lines: str) -> api.Session:
    s = api.Session(first, LEX)
    for line in lines:
        s.refine(line)
    return s


def compiled(text: str) -> dict:
    result = api.compile_source(text + "\n", "t.cnl", LEX)
    assert result.ok and len(result.materials) == 1, [d.message for d in result.diagnostics]
    return result.materials[0]


@pytest.mark.parametrize(
    ("first", "line", "same_as"),
    [
        ("white varnished oak", "make it walnut", "white varnished walnut"),
        ("brushed aluminum", "can you make it copper instead", "brushed copper"),
        ("matte red plastic", "switch to nylon", "matte red nylon"),
        ("glossy red plastic", "change it to steel", "steel"),
    ],
)
def test_a_change_line_naming_a_material_changes_the_material(first, line, same_as):
    s = session(first, line)
    assert len(s.result.materials) == 1
    assert s.material["params"] == compiled(same_as)["params"]
    assert s.material["maps"] == compiled(same_as)["maps"]


def test_refinements_before_the_change_still_apply():
    s = session("oak", "darker", "make it walnut")
    assert s.material["params"] == compiled("walnut\ndarker")["params"]


def test_a_material_that_is_also_a_colour_is_the_colour_on_another_kind():
    s = session("red plastic", "make it cream")
    plain = compiled("red plastic\nmake it cream")
    assert s.material["model"] == compiled("red plastic")["model"]
    assert (
        s.material["params"]["base_color"]
        == plain["params"]["base_color"]
        != compiled("red plastic")["params"]["base_color"]
    )


def test_the_note_says_what_was_read():
    result = api.compile_source("oak\nmake it walnut\n", "t.cnl", LEX)
    assert any("as a change of the material above" in d.message for d in result.diagnostics if d.code == "N101")


def test_a_change_to_a_material_as_the_first_line_is_that_material():
    result = api.compile_source("switch to brass\n", "t.cnl", LEX)
    assert result.ok and result.materials[0]["params"] == compiled("brass")["params"]


@pytest.mark.parametrize("line", ["frob it down", "make it zorbly", "switch to flimflam"])
def test_a_change_line_with_an_unknown_word_is_an_unknown_word_not_a_crash(line):
    result = api.compile_source(f"glossy red plastic\n{line}\n", "t.cnl", LEX)
    assert [d.code for d in result.diagnostics if d.is_error] == ["E001"]


@pytest.mark.parametrize(
    ("line", "same_as"),
    [
        ("satin", "make it satin"),
        ("too glossy", "less glossy"),
        ("it's way too red", "much less red"),
        ("that is a bit too dark", "a bit less dark"),
    ],
)
def test_a_session_line_always_refines_the_material(line, same_as):
    """In a session every line refines: describing words alone are a change ('satin' = make it
    satin, not a second material), a complaint asks for less ('too glossy' = less glossy)."""
    said, meant = session("glossy red plastic", line), session("glossy red plastic", same_as)
    assert len(said.result.materials) == 1
    assert said.material["params"] == meant.material["params"]
    assert said.material["params"] != session("glossy red plastic").material["params"]


def test_too_in_a_description_is_still_a_booster():
    assert compiled("too glossy plastic")["params"]["roughness"] < compiled("glossy plastic")["params"]["roughness"]


@pytest.mark.parametrize(
    ("line", "same_as"),
    [
        ("more of a teal", "closer to teal"),
        ("ok, more of a teal", "closer to teal"),
        ("please, tone down the shine", "less shine"),
    ],
)
def test_politeness_and_rewrites_are_read_on_a_line_of_known_words_too(line, same_as):
    said, meant = session("navy blue velvet", line), session("navy blue velvet", same_as)
    assert said.material["params"] == meant.material["params"] != session("navy blue velvet").material["params"]


def test_an_unknown_word_before_a_head_word_is_not_a_colour():
    result = api.compile_source("glossy red plastic\nplease tone down the shine\n", "t.cnl", LEX)
    assert not any("as the colour ''" in d.message for d in result.diagnostics)


def test_a_german_complaint_asks_for_less():
    de = api.lexicon_for(("de",))
    said, meant = api.Session("glänzender roter Kunststoff", de), api.Session("glänzender roter Kunststoff", de)
    said.refine("viel zu glänzend")
    meant.refine("viel weniger glänzend")
    assert said.material["params"] == meant.material["params"]
    assert (
        said.material["params"]["roughness"]
        > api.Session("glänzender roter Kunststoff", de).material["params"]["roughness"]
    )


@pytest.mark.parametrize(
    "text",
    [
        "red plastic\nmake it between beige and grey",
        "between beige and grey instead",
        "red plastic\n" + "too " * 20 + "glossy",
        "very " * 50 + "glossy paint",
    ],
)
def test_odd_change_lines_compile_without_a_traceback(text):
    result = api.compile_source(text + "\n", "t.cnl", LEX)
    assert all(d.code != "E999" for d in result.diagnostics)
    for m in result.materials:
        assert all(isinstance(v, float) and v == v for v in m["params"].get("base_color", []))


def test_too_much_shine_asks_for_less_and_a_lot_of_shine_for_more():
    less, more = session("glossy paint", "too much shine"), session("glossy paint", "a lot of shine")
    plain = session("glossy paint").material["params"]["roughness"]
    assert less.material["params"]["roughness"] > plain > more.material["params"]["roughness"]


def test_a_german_session_changes_in_german():
    s = api.Session("rotes Plastik", api.lexicon_for(("de",)))
    s.refine("matt")
    assert s.lines[-1] == "mach es matt" and len(s.result.materials) == 1


def test_a_change_phrase_is_noted_as_a_change_not_as_courtesy():
    result = api.compile_source("red plastic\nmatte instead\nmake it blue\n", "t.cnl", LEX)
    said = [d.message for d in result.diagnostics]
    assert "read past 'instead': a change phrase (the line's words change the material above, if any)" in said
    assert "read past 'make it': a change phrase (the line's words change the material above, if any)" in said
    assert not any("politeness" in m for m in said)
