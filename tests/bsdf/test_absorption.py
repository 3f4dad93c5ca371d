"""A glass's colour is Beer-Lambert absorption inside it (cnlmc.bsdf.transmission.absorption):
base_color is the transmittance through transmission_depth metres of the material."""

from __future__ import annotations

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from cnlmc.api import compile_source
from cnlmc.bsdf.transmission import absorption

RED_WINE = compile_source("red wine\n").document.materials[0]


def glass(colour, depth):
    return {
        "name": "g",
        "model": {"base": "glass", "distribution": "ggx", "anisotropic": False, "diffuse": None, "coat": False},
        "params": {"ior": 1.5, "roughness": 0.0, "base_color": list(colour), "transmission_depth": depth},
    }


def test_the_colour_is_the_transmittance_through_the_depth():
    """Red wine's colour is the dataset's transmittance through 1 cm (physicallybased.info
    'Wine (Red)', transmissionDepth 1 cm): 1 cm keeps it, 2 cm squares it, nothing keeps all."""
    assert RED_WINE.params.transmission_depth == 0.01
    np.testing.assert_allclose(absorption(RED_WINE, 0.01), RED_WINE.params.base_color, rtol=1e-12)
    np.testing.assert_allclose(absorption(RED_WINE, 0.02), np.square(RED_WINE.params.base_color), rtol=1e-12)
    np.testing.assert_array_equal(absorption(RED_WINE, 0.0), [1.0, 1.0, 1.0])


def test_edges_are_finite():
    """A channel of 0 passes nothing along any path (and everything along none); a huge path
    underflows to 0, not NaN; a negative length counts as none; colourless glass passes all."""
    black = glass([0.0, 0.5, 1.0], 0.05)
    kept = absorption(black, [0.0, 1e-9, 1e6, -1.0])
    np.testing.assert_allclose(kept, [[1, 1, 1], [0, 1, 1], [0, 0, 1], [1, 1, 1]], atol=1e-6)
    assert kept[1, 0] == 0.0 and kept[2, 1] == 0.0
    assert np.all(np.isfinite(absorption(glass([1e-300, 1.0, 1.0], 1e-5), 100.0)))


@settings(max_examples=60, deadline=None)
@given(
    st.lists(st.floats(0.0, 1.0), min_size=3, max_size=3),
    st.floats(1e-5, 100.0),
    st.floats(0.0, 10.0),
    st.floats(0.0, 10.0),
)
def test_paths_compose(colour, depth, a, b):
    """Beer-Lambert: two paths in a row keep the product of what each keeps, within [0, 1]."""
    m = glass(colour, depth)
    both, first, second = absorption(m, a + b), absorption(m, a), absorption(m, b)
    assert np.all((both >= 0.0) & (both <= 1.0))
    np.testing.assert_allclose(both, first * second, rtol=1e-9, atol=1e-300)


def test_words_keep_the_depth_their_colour_is_seen_through():
    """A glass noun's dataset depth belongs to its colour; a colour word names the colour seen
    through the table's default (5 cm), and a shade restates the glass's colour there first."""
    red_wine, blue_glass, darker = (
        compile_source(p + "\n").document.materials[0] for p in ("red wine", "blue glass", "dark red wine")
    )
    assert blue_glass.params.transmission_depth == 0.05
    assert darker.params.transmission_depth == 0.05
    seen = np.asarray(red_wine.params.base_color) ** 5  # red wine through 5 cm
    assert np.all(np.asarray(darker.params.base_color) <= seen + 1e-12)
    assert compile_source("clear acrylic\n").document.materials[0].params.transmission_depth == 0.05


def test_infinite_and_undefined_paths():
    """A colourless channel passes everything along any path (inf * log 1 is no NaN); a NaN path
    is NaN, not full transmittance."""
    kept = absorption(glass([1.0, 0.5, 0.0], 0.01), [np.inf, np.nan])
    np.testing.assert_array_equal(kept[0], [1.0, 0.0, 0.0])
    assert np.all(np.isnan(kept[1]))
