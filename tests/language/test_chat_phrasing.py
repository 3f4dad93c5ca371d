"""Chat and forum phrasing (issue #14, categories of held-out set 41): a degree said after its word
('shiny af'), texting degree forms ('v dark'), chemical symbols never read as metals, slashes that
list words of different kinds, unsure openers and endings, and 'more FEATURE' on a material without
that feature."""

from __future__ import annotations

import pytest

from tests.language.meaning import compiled, material, refined, same_look


def codes(text: str) -> list[str]:
    return [d.code for d in compiled(text).diagnostics]


@pytest.mark.parametrize(
    "said, meant",
    [
        ("shiny af chrome", "very shiny chrome"),
        ("rough as hell concrete", "very rough concrete"),
        ("matte to the max black paint", "very matte black paint"),
        ("shiny af black lacquer", "very shiny black lacquer"),
    ],
)
def test_a_degree_said_after_its_word_is_that_words_degree(said, meant):
    assert same_look(material(said), material(meant))
    notes = [d.message for d in compiled(said).diagnostics]
    assert any("as 'very " in n for n in notes), notes


def test_the_after_degree_belongs_to_the_word_before_not_the_next():
    # 'shiny af matte leather': very shiny (contradicted by matte, which wins), not very matte
    assert same_look(material("shiny af matte leather"), material("very shiny matte leather"))
    assert not same_look(material("shiny af matte leather"), material("shiny very matte leather"))


@pytest.mark.parametrize(
    "said, meant", [("v dark grey plastic", "very dark grey plastic"), ("rly glossy paint", "very glossy paint")]
)
def test_texting_degree_words(said, meant):
    assert same_look(material(said), material(meant))


@pytest.mark.parametrize("symbol", ["v", "u", "in", "co", "ni"])
def test_a_chemical_symbol_is_never_a_material(symbol):
    result = compiled(f"{symbol} paint")
    assert result.ir["materials"] == [] or all("WordNet" not in d.message for d in result.diagnostics), [
        d.message for d in result.diagnostics
    ]


def test_a_slash_between_kinds_lists_and_between_one_kind_offers_alternatives():
    assert same_look(material("matte/black/rubber"), material("matte black rubber"))
    assert any("as a list" in d.message for d in compiled("matte/black/rubber").diagnostics)
    assert len(compiled("copper/brass").ir["materials"]) == 2


@pytest.mark.parametrize(
    "said, meant",
    [
        ("idk like a dull brass maybe", "dull brass"),
        ("greenish grey plaster, not sure", "greenish grey plaster"),
        ("red oak or something", "red oak"),
    ],
)
def test_unsure_words_are_read_past(said, meant):
    assert same_look(material(said), material(meant))


@pytest.mark.parametrize(
    "first, line, graph",
    [("copper", "more patina", "patina"), ("steel", "more rust", "rust"), ("steel", "more scratches", "scratched")],
)
def test_more_of_an_absent_feature_draws_it(first, line, graph):
    session = refined(first)
    assert not session.material.get("maps")
    changed = session.refine(line)
    assert graph in {ref["graph"] for ref in changed["maps"].values()}
    assert any("had none" in d.message for d in session.result.diagnostics)


def test_more_of_a_feature_that_cannot_form_warns_and_less_of_an_absent_one_still_warns():
    oak = refined("oak")
    before = oak.material["maps"]
    assert oak.refine("more rust")["maps"] == before
    assert "W102" in [d.code for d in oak.result.diagnostics]
    copper = refined("copper")
    copper.refine("less patina")
    assert not copper.material.get("maps") and "W106" in [d.code for d in copper.result.diagnostics]


@pytest.mark.parametrize(
    "said, meant",
    [
        ("black stone with small white points", "black stone with small white speckles"),
        ("red paint with rust showing thru", "red paint with rust"),
    ],
)
def test_chat_words_for_features(said, meant):
    assert same_look(material(said), material(meant))
    assert material(said)["maps"] == material(meant)["maps"]


@pytest.mark.parametrize(
    "said, meant",
    [("copper thats gone green", "copper that's gone green"), ("brass thats gone dull", "brass that's gone dull")],
)
def test_a_contraction_without_its_apostrophe_reads_as_with_it(said, meant):
    assert same_look(material(said), material(meant))


def test_a_contraction_that_is_another_word_without_its_apostrophe_is_not_added():
    from cnlmc.suggest import with_unmarked_contractions

    data = with_unmarked_contractions({"x": ["it's", "that's gone", "we'll"], "y": {"k": ["don't"]}})
    assert data == {"x": ["it's", "that's gone", "we'll", "thats gone"], "y": {"k": ["don't", "dont"]}}


@pytest.mark.parametrize(
    "said, meant",
    [
        ("concrete smooth as glass", "very smooth concrete"),
        ("steel, shiny as a mirror", "very shiny steel"),
        ("old iron, high roughness", "old rough iron"),
        ("deep navy blue plastic, low roughness", "deep navy blue glossy plastic"),
        ("teal plastic albedo, kinda satin", "teal plastic, kinda satin"),
    ],
)
def test_similes_and_a_3d_artists_words(said, meant):
    assert same_look(material(said), material(meant))
