"""Briefs and client replies (issue #14, categories of held-out set 40): a material implied for
words that only fit some materials, editor verbs for colour, 'try it X', age as a feature, filled
stone, German undyed colour, and 'too white' on a coloured material."""

from __future__ import annotations

import pytest

from tests.language.meaning import compiled, lch, material, refined, same_look


@pytest.mark.parametrize("said", ["burnt orange glaze shiny", "white glaze shiny"])
def test_an_implied_material_is_one_every_word_applies_to(said):
    result = compiled(said)
    assert result.ir["materials"][0]["model"]["base"] != "conductor"
    assert "W102" not in [d.code for d in result.diagnostics]


def test_desaturate_and_saturate_move_the_chroma():
    session = refined("blue fabric")
    start = lch(session.material["params"]["base_color"])[1]
    duller = lch(session.refine("desaturate a bit")["params"]["base_color"])[1]
    richer = lch(session.refine("saturate it")["params"]["base_color"])[1]
    assert duller < start and richer > duller


def test_can_we_try_it_brushed():
    assert refined("polished brass").refine("can we try it brushed")["model"]["anisotropic"]


def test_age_is_a_feature_at_the_clause_weight():
    some = material("brass with a bit of age")["maps"]["base_color"]
    full = material("aged brass")["maps"]["base_color"]
    assert some["graph"] == full["graph"] == "tarnish"
    assert some["params"]["coverage"] < full["params"]["coverage"]
    assert same_look(material("brass, bit of age on it"), material("brass with a bit of age"))


def test_filled_travertine_is_closed_and_smoother():
    filled, plain = material("filled travertine"), material("travertine")
    assert filled["params"]["roughness"] < plain["params"]["roughness"]
    assert filled["params"]["base_color"] == plain["params"]["base_color"]
    assert same_look(material("travertine, filled and honed"), material("filled and honed travertine"))


def test_german_undyed_linen():
    from cnlmc.api import compile_source, lexicon_for

    result = compile_source("Leinen, naturfarben\n", "t.cnl", lexicon_for(["de"]))
    L, C, _ = lch(result.ir["materials"][0]["params"]["base_color"])
    assert result.ok and L > 0.9 and C < 0.05


@pytest.mark.parametrize(
    "first, line", [("limed oak", "too white"), ("cream paint", "less white"), ("white paint", "too white")]
)
def test_less_white_darkens_and_keeps_the_hue(first, line):
    session = refined(first)
    L0, C0, h0 = lch(session.material["params"]["base_color"])
    L1, C1, h1 = lch(session.refine(line)["params"]["base_color"])
    assert L1 < L0 - 0.03
    assert C0 < 0.02 or abs(h1 - h0) < 1.0


def test_less_black_lightens_a_near_black_colour():
    session = refined("navy paint")
    L0 = lch(session.material["params"]["base_color"])[0]
    assert lch(session.refine("less black")["params"]["base_color"])[0] > L0


def test_filled_travertine_keeps_few_open_pores_and_filling_is_for_travertine():
    open_face = material("travertine")["maps"]["base_color"]["params"]["coverage"]
    filled = material("filled travertine")["maps"]
    assert filled["base_color"]["params"]["coverage"] < open_face / 2
    assert filled["normal"]["params"]["coverage"] == filled["base_color"]["params"]["coverage"]
    assert "W102" in [d.code for d in compiled("filled marble").diagnostics]
