"""Every stdlib graph: determinism, seeds, tiling, ranges, normals, golden thumbnails."""

import io
from functools import partial
from pathlib import Path

import numpy as np
import pytest

from cnlmc.backends.maps import evaluate, load_graph

from .conftest import SMALL, golden_thumbnails, seam_ratio

GOLDEN = Path(__file__).parent / "golden"


def outputs(name, seed=0, size=SMALL, **params):
    return evaluate(load_graph(name), size, seed=seed, params=params)


def test_bit_identical_per_seed(graph_name):
    first, second = outputs(graph_name, seed=7), outputs(graph_name, seed=7)
    for role in first:
        assert np.array_equal(first[role], second[role]), role


def test_different_seeds_differ(graph_name):
    a, b = outputs(graph_name, seed=1), outputs(graph_name, seed=2)
    assert any(not np.allclose(a[r], b[r]) for r in a if r != "metallic")


def test_ranges_and_shapes(graph_name):
    for role, array in outputs(graph_name).items():
        assert array.dtype == np.float32
        if role == "normal":
            assert array.shape == (SMALL, SMALL, 3)
            assert np.allclose(np.linalg.norm(array, axis=-1), 1.0, atol=1e-5)
            assert (array[..., 2] > 0).all()
        elif role == "color":
            assert array.shape == (SMALL, SMALL, 3)
            assert 0.0 <= array.min() and array.max() <= 1.0
        else:
            assert array.shape == (SMALL, SMALL)
            assert 0.0 <= array.min() and array.max() <= 1.0


def test_outputs_tile_seamlessly(graph_name):
    for role, array in outputs(graph_name, size=128).items():
        if np.ptp(array) < 1e-6:
            continue
        for axis in (0, 1):
            assert seam_ratio(array, axis) <= 1.05, (role, axis)


def npy_bytes(array) -> bytes:
    """The .npy file np.save writes for the float32 array."""
    buffer = io.BytesIO()
    np.save(buffer, array.astype(np.float32))
    return buffer.getvalue()


def close_to_golden(array, role, golden: bytes) -> None:
    expected = np.load(io.BytesIO(golden))
    assert np.abs(array - expected).mean() < 2e-3, role
    assert np.abs(array - expected).max() < 0.05, role


@pytest.mark.parametrize("name", sorted(golden_thumbnails()))
def test_golden_thumbnails(name, goldens):
    """Within tolerance of tests/maps/golden/ (pytest --update-goldens rewrites only those outside it)."""
    for role, array in golden_thumbnails()[name].items():
        goldens.check(GOLDEN / f"{name}__{role}.npy", npy_bytes(array), partial(close_to_golden, array, role))
