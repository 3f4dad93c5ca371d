"""'warm' and 'cool' before a colour (issue #14: 'warm white paint', 'cool grey'): a tint toward
orange or blue in OKLab, checked through the compiler on colours of every family."""

from __future__ import annotations

import pytest

from cnlmc import api, colour

# colours the survey has no "warm X" / "cool X" for (those are the survey's own compounds)
COLOURS = ["white", "beige", "green", "ivory", "lilac", "olive", "teal"]  # black has no hue to tint
ORANGE_AB, BLUE_AB = (0.1245, 0.1415), (-0.0279, -0.2394)  # the survey's orange and blue in OKLab


def _distance(lab: list[float], ab: tuple[float, float]) -> float:
    return float(((lab[1] - ab[0]) ** 2 + (lab[2] - ab[1]) ** 2) ** 0.5)


def _lab(phrase: str) -> list[float]:
    result = api.compile_source(phrase, "<phrase>")
    assert not [d for d in result.diagnostics if d.severity.value in ("error", "warning")], result.diagnostics
    return colour.linear_to_oklab(result.materials[0]["params"]["base_color"])


@pytest.mark.parametrize("name", COLOURS)
def test_warm_moves_toward_orange_and_cool_toward_blue(name: str) -> None:
    plain, warm, cool = (_lab(f"{shade}{name} paint") for shade in ("", "warm ", "cool "))
    assert _distance(warm, ORANGE_AB) < _distance(plain, ORANGE_AB) - 0.005
    assert _distance(cool, BLUE_AB) < _distance(plain, BLUE_AB) - 0.005
    assert abs(warm[0] - plain[0]) <= 0.05 and abs(cool[0] - plain[0]) <= 0.05  # lightness nearly kept


def test_a_warm_white_is_tinted_but_still_white() -> None:
    warm, cool = _lab("warm white paint"), _lab("cool white ceramic")
    assert warm[2] > 0.005 and cool[2] < -0.005  # visibly tinted, not clipped back to pure white
    assert warm[0] > 0.9 and cool[0] > 0.9
