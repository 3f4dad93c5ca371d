"""Each registered generator on its own: periodic, deterministic, in [0, 1]."""

import numpy as np
import pytest

from cnlmc.backends.maps import NODE_TYPES
from cnlmc.backends.maps.grid import Grid

from .conftest import seam_ratio

GENERATORS = [name for name, t in NODE_TYPES.items() if t.category == "generator"]


@pytest.mark.parametrize("name", GENERATORS)
def test_generator_tiles_and_repeats(name):
    function = NODE_TYPES[name].function
    first, again, other = function(Grid(128, 4)), function(Grid(128, 4)), function(Grid(128, 5))
    assert np.array_equal(first, again)
    assert 0.0 <= first.min() and first.max() <= 1.0
    for axis in (0, 1):
        assert seam_ratio(first, axis) <= 1.05
    if name in ("value", "perlin", "simplex", "fbm", "turbulence", "worley"):
        assert not np.array_equal(first, other)


def test_seam_check_catches_a_seam():
    ramp = np.tile(np.linspace(0.0, 1.0, 128, dtype=np.float32), (128, 1))
    assert seam_ratio(ramp, 1) > 10


@pytest.mark.parametrize("feature", ["f1", "f2", "edge", "cell"])
def test_worley_features(feature):
    from cnlmc.backends.maps.worley import worley_noise

    out = worley_noise(Grid(64, 1), 8, feature)
    assert out.shape == (64, 64) and 0.0 <= out.min() and out.max() <= 1.0
