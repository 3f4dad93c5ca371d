"""Colour names from people (issue #14): the xkcd colour survey as the everyday vocabulary,
compounds and shifts in OKLab, checked against the survey and through the compiler."""

from __future__ import annotations

import tomllib
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from cnlmc import colour
from cnlmc.lexicon import cached_lexicon, load_lexicon
from tests.helpers import load_module

ROOT = Path(__file__).resolve().parents[2]
NAMES = ROOT / "stdlib" / "data" / "colour_names.toml"


ev = load_module("everyday_bench_colours", ROOT / "bench" / "everyday.py")  # OKLab, CIELAB, CIEDE2000


@pytest.fixture(scope="module")
def lexicon():
    return load_lexicon()


@pytest.fixture(scope="module")
def survey():
    with open(NAMES, "rb") as f:
        return tomllib.load(f)


def L(rgb) -> float:
    return colour.linear_to_oklab(rgb)[0]


def test_oklab_round_trips():
    for hex_code in ("#7f2b0a", "#ffffff", "#000000", "#0343df", "#ceb301"):
        rgb = colour.hex_to_linear(hex_code)
        assert colour.linear_to_oklab(rgb) == pytest.approx(ev.oklab(rgb), abs=1e-6)
        assert colour.oklab_to_linear(colour.linear_to_oklab(rgb)) == pytest.approx(rgb, abs=1e-6)


def test_every_survey_name_is_the_surveys_colour_within_delta_e_2(lexicon, survey):
    colours = lexicon.all_of("colours")
    checked, departures = 0, []
    for name, row in survey.items():
        key = name.replace("/", " ")
        entry = colours.get(key)
        if entry is None or row["source"] != "xkcd" or "shade" in entry.get("doc"):
            continue  # a word of another category ("steel"), or a "dark X" the survey has lighter than X
        if key != name and key in survey:
            continue
        if f"the survey's {key} {row['hex']}" in entry.get("doc"):  # a departure, said and argued in its doc
            departures.append(key)
            continue
        ours = ev.cielab(entry.get("rgb"))
        theirs = ev.cielab(colour.hex_to_linear(row["hex"]))
        assert ev.delta_e2000(ours, theirs) <= 2.0, name
        assert "xkcd colour survey" in entry.get("doc") and "CC0" in entry.get("source")
        checked += 1
    assert checked > 880
    assert departures == ["indigo"]  # the dyers' deep blue, not the survey's violet (colours.toml)


def test_css_names_only_where_the_survey_has_none(lexicon):
    colours = lexicon.all_of("colours")
    assert colours["brown"].get("hex") == "#653700"  # the survey's, not CSS brick red #a52a2a
    assert colours["grey"].get("hex") == "#929591" and "gray" in colours["grey"].get("aliases")
    assert L(colours["dark grey"].get("rgb")) < L(colours["grey"].get("rgb")) < L(colours["light grey"].get("rgb"))
    assert colours["alice blue"].get("hex") == "#f0f8ff"  # CSS only


def test_the_paper_overlay_keeps_the_css_table():
    colours = load_lexicon(overlay="paper").all_of("colours")
    assert colours["brown"].get("hex") == "#a52a2a" and colours["grey"].get("hex") == "#808080"
    assert colours["red"].get("hex") == "#ff0000"


def test_survey_compounds_and_derived_names_are_the_surveys(lexicon):
    colours = lexicon.all_of("colours")
    for name in ("reddish brown", "blue grey", "off white", "olive green", "mustard yellow", "dusty pink"):
        assert "xkcd colour survey" in colours[name].get("doc"), name
    assert "blue gray" in colours["blue grey"].get("aliases")


def test_a_dash_compound_the_survey_lacks_is_the_oklab_midpoint(lexicon):
    colours = lexicon.all_of("colours")
    red, blue = colours["red"].get("rgb"), colours["blue"].get("rgb")
    mixed = colours["red-blue"].get("rgb")
    assert colour.linear_to_oklab(mixed) == pytest.approx(colour.linear_to_oklab(colour.mix_oklab(red, blue)), abs=0.01)


SHIFTS = {"dark": -1, "deep": -1, "light": 1, "pale": 1}


def _shaded(lexicon, shade: str, name: str) -> list[float]:
    """What 'SHADE NAME' means: the survey's own compound if it is one, else the shade's operations."""
    own = lexicon.entry("colours", f"{shade} {name}")
    if own is not None:
        return own.get("rgb")
    return colour.apply_ops(lexicon.require("colours", name).get("rgb"), lexicon.require("shades", shade).get("ops"))


def test_dark_is_darker_and_light_is_lighter_for_every_colour(lexicon):
    for name, entry in lexicon.all_of("colours").items():
        base = L(entry.get("rgb"))
        for shade, direction in SHIFTS.items():
            shifted = L(_shaded(lexicon, shade, name))
            if 0.0 < base < 0.999:
                assert (shifted - base) * direction > 0, (shade, name)
            else:
                assert (shifted - base) * direction >= -1e-6, (shade, name)


rgb_values = st.tuples(*[st.floats(0.0, 1.0, allow_nan=False)] * 3)


@settings(derandomize=True, max_examples=200, deadline=None)
@given(rgb_values)
def test_shifts_move_lightness_the_right_way_for_any_colour(rgb):
    lexicon = cached_lexicon()
    base = L(rgb)
    for shade, direction in (*SHIFTS.items(), ("dusty", -1)):
        shifted = L(colour.apply_ops(list(rgb), lexicon.require("shades", shade).get("ops")))
        if 0.01 < base < 0.99:
            assert (shifted - base) * direction > 0, shade
    for shade in ("muted", "reddish", "greyish", "bluish"):  # these keep L (black has no hue to move)
        assert base < 0.01 or L(
            colour.apply_ops(list(rgb), lexicon.require("shades", shade).get("ops"))
        ) == pytest.approx(base, abs=2e-3)


def test_ish_moves_toward_the_hue(lexicon):
    grey = lexicon.require("colours", "grey").get("rgb")
    reddish = colour.apply_ops(grey, lexicon.require("shades", "reddish").get("ops"))
    assert colour.linear_to_oklab(reddish)[1] > colour.linear_to_oklab(grey)[1] + 0.03  # a: toward red


# ---------------------------------------------------------------- the reproductions


def base_color(compile_text, text):
    r = compile_text(text)
    assert r.ok, [d.message for d in r.diagnostics]
    return r, r.materials[0]["params"]["base_color"]


def test_brown_leather_is_brown(compile_text):
    _, rgb = base_color(compile_text, "brown leather")
    Lab = colour.linear_to_oklab(rgb)
    assert Lab[2] > 0.05 and Lab[1] < Lab[2]  # yellow-red (brown), not brick red
    assert colour.linear_to_hex(rgb) == "#653700"


def test_dark_grey_plastic_is_darker_than_grey_plastic(compile_text):
    _, dark = base_color(compile_text, "dark grey plastic")
    _, grey = base_color(compile_text, "grey plastic")
    _, light = base_color(compile_text, "light grey plastic")
    assert L(dark) < L(grey) < L(light)


@pytest.mark.parametrize(
    "text, hex_code",
    [("olive green velvet", "#677a04"), ("mustard yellow wool", "#d2bd0a"), ("dusty pink velvet", "#d58a94")],
)
def test_two_word_colours_keep_both_words(compile_text, text, hex_code):
    r, rgb = base_color(compile_text, text)
    assert not [d for d in r.diagnostics if d.code == "W105"]
    assert colour.linear_to_hex(rgb) == hex_code


@pytest.mark.parametrize(
    "text",
    [
        "reddish plastic",
        "reddish brown leather",
        "off-white paint",
        "blue-grey ceramic",
        "blue-gray plastic",
        "light blue-gray paint",
        "greyish blue plastic",
        "reddish mustard plastic",
        "bluish glass",
        "red-blue plastic",
    ],
)
def test_compound_and_derived_colours_compile(compile_text, text):
    r = compile_text(text)
    assert r.ok and not r.diagnostics, [d.message for d in r.diagnostics]


def test_blue_grey_spellings_agree(compile_text):
    _, a = base_color(compile_text, "blue-grey ceramic")
    _, b = base_color(compile_text, "blue gray ceramic")
    _, c = base_color(compile_text, "blue-gray ceramic")
    assert a == b == c


def test_light_blue_gray_is_lighter_than_blue_gray(compile_text):
    _, light = base_color(compile_text, "light blue-gray paint")
    _, plain = base_color(compile_text, "blue-gray paint")
    assert L(light) > L(plain)
