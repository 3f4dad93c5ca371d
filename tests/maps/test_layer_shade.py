"""'darker' / 'lighter' on a material with a layer of its own colours (rust, patina): the layer
moves with the material (cnlmc.passes.layer_shade; stdlib/graphs rust.toml, patina.toml
`[palette] shade`). Measured on the baked colour map, where the mask covers the surface."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from cnlmc.api import Session
from cnlmc.backends.maps.bake import bake
from cnlmc.passes.layer_shade import _shaded

SIZE = 64
LUMA = np.array([0.2126, 0.7152, 0.0722])


def _layer_luminance(material: dict) -> float:
    """The mean luminance of the baked colour where the layer's mask covers the surface (a tarnish,
    a film with no mask of its own: over all of it)."""
    maps = material["maps"]
    baked = bake(maps, {"base_color": material["params"]["base_color"]}, size=SIZE)
    colour = baked["base_color"].reshape(-1, 3) @ LUMA
    mask = baked["mask"].reshape(-1) if "mask" in baked else np.ones_like(colour)  # a tarnish: all of it
    return float((mask * colour).sum() / mask.sum())


def _steps(first: str, *lines: str) -> list[dict]:
    session = Session(first)
    seen = [session.result.ir["materials"][-1]]
    for line in lines:
        session.refine(line)
        assert session.result.ok, [d.message for d in session.result.diagnostics]
        seen.append(session.result.ir["materials"][-1])
    return seen


@pytest.mark.parametrize("first", ["rusty iron", "heavily rusted steel", "verdigris copper", "tarnished brass"])
def test_darker_darkens_the_layer_and_lighter_brings_it_back(first):
    start, dark, back = (_layer_luminance(m) for m in _steps(first, "darker", "lighter"))
    assert dark < 0.7 * start
    assert dark < back <= start * 1.0001  # the bracket: 'lighter' after 'darker' goes half way back


@pytest.mark.parametrize("first", ["rusty iron", "verdigris copper", "tarnished silver"])
def test_lighter_lightens_the_layer(first):
    start, light = (_layer_luminance(m) for m in _steps(first, "lighter"))
    assert light > 1.1 * start


def test_a_material_without_a_layer_is_untouched():
    oak, darker = _steps("oak", "darker")
    assert darker["maps"]["base_color"] == oak["maps"]["base_color"]


@given(
    st.floats(0, 1),
    st.floats(0, 1),
    st.floats(0.05, 20),
)
def test_shade_amounts_stay_in_range_and_a_step_and_its_inverse_cancel(dark, light, ratio):
    d, lt = _shaded(dark, light, ratio)
    assert 0 <= d <= 1 and 0 <= lt <= 1
    if dark == 0 or light == 0:  # one of the two in use, as the steps leave them
        d2, l2 = _shaded(d, lt, 1 / ratio)
        if d < 1 and lt < 1:
            assert d2 == pytest.approx(dark, abs=1e-9) and l2 == pytest.approx(light, abs=1e-9)
