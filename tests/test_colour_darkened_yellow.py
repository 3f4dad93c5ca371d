"""A yellow made darker stays what people call yellow (a mustard, an ochre), not an olive
(compiler/colour.py darkened_yellow; the line is read from the xkcd survey's names)."""

from __future__ import annotations

import math
import statistics
import tomllib
from importlib import resources

import pytest
from hypothesis import given
from hypothesis import strategies as st

from cnlmc import api
from cnlmc.colour import YELLOW_OFFSETS, darkened_yellow, linear_to_oklab, yellow_hue_at

NOT_YELLOW = ("green", "orange", "olive", "tan", "pink", "khaki")


def _survey() -> dict[str, list[float]]:
    text = resources.files("cnlmc.stdlib").joinpath("data", "colour_names.toml").read_text(encoding="utf-8")
    return {name: row["oklab"] for name, row in tomllib.loads(text).items() if row["source"] == "xkcd"}


def _hue(lab) -> float:
    return math.degrees(math.atan2(lab[2], lab[1])) % 360.0


def test_the_line_follows_the_survey_names_that_stay_yellow():
    """Every survey name with 'yellow' in it below L 0.85 ('dark yellow', 'mustard yellow', 'yellow
    ochre', 'yellowish brown'...) lies near the line; the olives lie past the point where it turns."""
    survey = _survey()
    yellows = {
        n: lab for n, lab in survey.items() if "yellow" in n and lab[0] < 0.85 and not any(w in n for w in NOT_YELLOW)
    }
    offsets = [_hue(lab) - yellow_hue_at(lab[0]) for lab in yellows.values()]
    assert len(offsets) >= 10
    assert abs(statistics.median(offsets)) <= 4.0
    assert all(abs(o) <= 10.0 for o in offsets)
    for olive in ("olive", "olive drab", "olive green"):
        lab = survey[olive]
        assert _hue(lab) - yellow_hue_at(lab[0]) >= YELLOW_OFFSETS[1]  # untouched: olive stays olive


def _hue_of(phrase: str, *steps: str) -> tuple[float, float]:
    session = api.Session(phrase, api.lexicon_for([]))
    for step in steps:
        session.refine(step)
    lab = linear_to_oklab(session.material["params"]["base_color"])
    return lab[0], _hue(lab)


def test_darker_yellow_is_a_mustard_then_an_ochre():
    start, _ = _hue_of("yellow plastic")
    once = _hue_of("yellow plastic", "darker")
    twice = _hue_of("yellow plastic", "darker", "darker")
    assert start > once[0] > twice[0]
    assert 92 < once[1] < 102 and 85 < twice[1] < 95  # the survey's dark yellow 96.6, yellow ochre 87.3


@pytest.mark.parametrize("phrase", ["olive paint", "lime green plastic", "orange plastic", "blue plastic"])
def test_darker_keeps_the_hue_of_anything_but_a_yellow(phrase):
    (_, before), (_, after) = _hue_of(phrase), _hue_of(phrase, "darker")
    assert after == pytest.approx(before, abs=0.5)


def test_a_dark_shade_of_yellow_is_not_olive():
    _, hue = _hue_of("deep yellow paint")
    assert hue < 100


@given(
    was=st.floats(0.0, 1.0),
    to=st.floats(0.0, 1.0),
    hue=st.floats(0.0, 360.0, exclude_max=True),
    chroma=st.floats(0.0, 0.3),
)
def test_only_a_darkened_yellow_turns_and_never_its_chroma(was, to, hue, chroma):
    a, b = chroma * math.cos(math.radians(hue)), chroma * math.sin(math.radians(hue))
    new_a, new_b = darkened_yellow(was, to, a, b)
    assert math.isfinite(new_a) and math.isfinite(new_b)
    assert math.hypot(new_a, new_b) == pytest.approx(chroma, abs=1e-12)
    if (new_a, new_b) != (a, b):
        turned = math.degrees(math.atan2(new_b, new_a)) % 360.0
        assert (
            to < was and yellow_hue_at(to) <= turned <= hue
        )  # toward orange (a turn may be below float precision), never past the line
