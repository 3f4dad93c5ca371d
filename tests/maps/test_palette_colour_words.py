"""A colour word tints a pattern's palette and keeps its variation (issue #15 item 3): measured on
the baked colour maps, in OKLab."""

from __future__ import annotations

import numpy as np
import pytest

from cnlmc import api, colour
from cnlmc.backends.maps.bake import bake
from cnlmc.material import params_to_ir

SIZE = 128


def _material(phrase: str):
    result = api.compile_source(phrase, "<phrase>")
    assert not [d for d in result.diagnostics if d.is_error], result.diagnostics
    return result.document.materials[0]


def _baked(phrase: str, outputs: tuple[str, ...] = ("color",)) -> dict[str, np.ndarray]:
    """The material's base_color graph baked with its own parameters, for each output asked."""
    material = _material(phrase)
    ref = material.maps["base_color"].to_ir()
    refs = {out: {**ref, "output": out} for out in outputs}
    return bake(refs, params_to_ir(material.params), SIZE, 0)


def _oklab(rgb: np.ndarray) -> np.ndarray:
    flat = np.clip(rgb.reshape(-1, 3), 0, None)
    return np.array([colour.linear_to_oklab([float(c) for c in p]) for p in flat[:: max(1, len(flat) // 4096)]])


def _lightness_spread(phrase: str) -> tuple[float, float, float]:
    lab = _oklab(_baked(phrase)["color"])
    return tuple(float(x) for x in np.percentile(lab[:, 0], [2, 50, 99]))


@pytest.mark.parametrize("phrase", ["black granite", "polished black granite"])
def test_black_granite_is_black_with_visible_crystals(phrase):
    low, median, high = _lightness_spread(phrase)
    assert median < 0.4  # a black stone
    assert high - median > 0.15  # pale crystals show (a flat black ball has no spread)


def test_black_marble_is_black_with_light_veins():
    low, median, high = _lightness_spread("black marble")
    assert median < 0.4
    assert high - median > 0.3  # white calcite veins: a visible contrast


def test_white_marble_is_white_with_visible_veins():
    low, median, high = _lightness_spread("white marble")
    assert median > 0.85
    assert median - low > 0.06


def test_a_clause_colour_wins_over_the_dark_palette():
    """'black marble with red veins': the clause's colour, not the palette's white."""
    veins = _oklab(_baked("black marble with red veins")["color"])
    reddest = veins[np.argmax(veins[:, 1])]
    assert reddest[1] > 0.05  # a: toward red


def test_red_brick_is_a_brick_red_and_its_mortar_stays_mortar():
    baked = _baked("red brick", ("color", "mask"))
    color, mask = baked["color"].reshape(-1, 3), baked["mask"].reshape(-1)
    mortar, bricks = _oklab(color[mask < 0.05]), _oklab(color[mask > 0.95])
    assert len(mortar) > 50 and len(bricks) > 50
    mortar_chroma = np.hypot(mortar[:, 1], mortar[:, 2])
    assert np.median(mortar_chroma) < 0.03 and 0.5 < np.median(mortar[:, 0]) < 0.85  # grey mortar
    chroma = np.hypot(bricks[:, 1], bricks[:, 2])
    hue = np.degrees(np.arctan2(bricks[:, 2], bricks[:, 1]))
    assert 0.05 < np.median(chroma) <= 0.13  # a brick red, not a paint red (xkcd red: chroma 0.25)
    assert 0 < np.median(hue) < 60  # red
    spread = np.percentile(bricks[:, 0], 95) - np.percentile(bricks[:, 0], 5)
    assert spread > 0.08 * np.median(bricks[:, 0])  # bricks still vary (the palette multiplies: relative)
    assert 0.45 < np.median(bricks[:, 0]) < 0.56  # a fired red, near physicallybased.info's Brick (L 0.51)


@pytest.mark.parametrize(
    "phrase,lightness,hue",
    [
        ("yellow brick", (0.7, 0.82), (85, 102)),  # a buff stock: light, and yellow rather than olive
        ("cream brick", (0.7, 0.82), (80, 105)),
        ("white brick", (0.75, 0.85), None),  # the lightest brick, not a mid grey
        ("black brick", (0.25, 0.36), None),
        ("blue brick", (0.36, 0.48), (240, 290)),  # a dark engineering brick
    ],
)
def test_a_brick_colour_takes_its_place_among_bricks(phrase, lightness, hue):
    """Fired clay runs from dark engineering bricks through reds to pale stocks: the named colour's
    lightness places it in that run (stdlib/graphs/brick.toml palette.lightness_curve)."""
    baked = _baked(phrase, ("color", "mask"))
    bricks = _oklab(baked["color"].reshape(-1, 3)[baked["mask"].reshape(-1) > 0.95])
    assert lightness[0] < np.median(bricks[:, 0]) < lightness[1]
    if hue is not None:
        median_hue = np.degrees(np.arctan2(np.median(bricks[:, 2]), np.median(bricks[:, 1]))) % 360
        assert hue[0] < median_hue < hue[1]


def test_brick_lightness_keeps_the_order_of_the_named_colours():
    medians = []
    for phrase in ("black brick", "blue brick", "red brick", "yellow brick", "white brick"):
        baked = _baked(phrase, ("color", "mask"))
        medians.append(np.median(_oklab(baked["color"].reshape(-1, 3)[baked["mask"].reshape(-1) > 0.95])[:, 0]))
    assert medians == sorted(medians)


def _brick_lch(phrase: str) -> tuple[float, float, float]:
    """Median OKLab lightness, chroma and hue (degrees) of the bricks (mortar left out)."""
    baked = _baked(phrase, ("color", "mask"))
    lab = np.median(_oklab(baked["color"].reshape(-1, 3)[baked["mask"].reshape(-1) > 0.95]), axis=0)
    return float(lab[0]), float(np.hypot(lab[1], lab[2])), float(np.degrees(np.arctan2(lab[2], lab[1])) % 360)


TERRACOTTA_CHROMA = 0.099  # physicallybased.info Terracotta [0.555, 0.212, 0.11]: the most saturated fired clay


@pytest.mark.parametrize("phrase", ["red brick", "orange brick", "pink brick", "yellow brick", "brick"])
def test_a_clay_colour_stays_in_fired_clays_hues_and_chroma(phrase):
    """Fired clay is coloured by iron oxides: no brick more saturated than measured terracotta, and a
    near hue (the survey's red, pink, yellow) moves into the survey's run of clay names (h 31-86)."""
    _, chroma, hue = _brick_lch(phrase)
    assert chroma <= TERRACOTTA_CHROMA + 0.005
    assert 27 <= hue <= 90


@pytest.mark.parametrize("phrase, hue", [("blue brick", (230, 290)), ("green brick", (120, 170))])
def test_a_colour_fired_clay_never_has_stays_a_tint(phrase, hue):
    """'blue brick' is a blue-grey engineering brick, not a painted blue: its hue kept, its chroma a tint."""
    _, chroma, median_hue = _brick_lch(phrase)
    assert 0.01 < chroma <= 0.035
    assert hue[0] < median_hue < hue[1]


def test_red_brick_is_redder_than_brick_but_no_paint_red():
    brick, red = _brick_lch("brick"), _brick_lch("red brick")
    assert red[2] < brick[2] and red[1] > brick[1]
    assert red[1] < 0.5 * np.hypot(*colour.linear_to_oklab([1.0, 0.0, 0.0])[1:])


def test_grey_slate_is_grey():
    material = _material("grey slate")
    lab = colour.linear_to_oklab(list(material.params.base_color))
    assert np.hypot(lab[1], lab[2]) < 0.03 and 0.3 < lab[0] < 0.8


@pytest.mark.parametrize("phrase", ["white brick", "black brick", "grey brick"])
def test_a_grey_brick_has_no_hue_to_move(phrase):
    """A grey has no hue: the palette's hue range leaves it grey (and says nothing of a hue)."""
    from cnlmc.explain import explain

    _, chroma, _ = _brick_lch(phrase)
    assert chroma < 0.01  # the survey's grey is a near-neutral #929591
    assert "hue" not in explain(api.compile_source(phrase, "<phrase>").ir)
