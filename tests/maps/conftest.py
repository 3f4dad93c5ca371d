import numpy as np
import pytest

from cnlmc.backends.maps import graph_names

SMALL = 64


@pytest.fixture(params=graph_names())
def graph_name(request):
    return request.param


def luminance(rgb):
    return rgb @ np.array([0.2126, 0.7152, 0.0722], np.float32)


def seam_ratio(image, axis):
    """Mean |difference| across the wrap-around edge / the largest mean |difference| between
    interior neighbouring rows (or columns).  A seam stands out (ratio >> 1); patterns whose
    lines fall on the tile edge (mortar, grout) stay at or below the interior maximum."""
    wrap = np.abs(np.take(image, 0, axis=axis) - np.take(image, -1, axis=axis)).mean()
    other_axes = tuple(a for a in range(image.ndim) if a != axis)
    interior = np.abs(np.diff(image, axis=axis)).mean(axis=other_axes).max()
    return wrap / max(interior, 1e-9)


def golden_thumbnails():
    """role arrays per graph at 32 px, seed 0: what tests/maps/golden/*.npy hold
    (pytest --update-goldens tests/maps rewrites the ones outside the tolerance)."""
    from cnlmc.backends.maps import evaluate, load_graph

    return {name: evaluate(load_graph(name), 32, seed=0) for name in graph_names()}
