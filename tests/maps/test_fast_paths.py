"""The fast paths compute what the plain formulas compute (to float32 rounding)."""

import numpy as np
import pytest

from cnlmc.backends.maps.blas import openblas_controls, single_threaded_blas
from cnlmc.backends.maps.grid import Grid
from cnlmc.backends.maps.lattice import axis_weights, periods
from cnlmc.backends.maps.noise import fbm
from cnlmc.backends.maps.simplex import NORMALISATION, simplex_signed
from cnlmc.backends.maps.worley import feature_points, nearest_two


def test_single_threaded_blas_restores_the_thread_count():
    controls = openblas_controls()
    if controls is None:
        pytest.skip("numpy's OpenBLAS not found")
    before = controls[0]()
    with single_threaded_blas():
        assert controls[0]() == 1
    assert controls[0]() == before


def reference_simplex(grid, scale, stretch, salt="simplex"):
    """Three corners of the containing triangle, float64."""
    py, px = periods(scale, stretch)
    angle = grid.rng(salt, py, px).uniform(0.0, 2.0 * np.pi, (py, px))
    y, x = (grid.axis * py)[:, None], (grid.axis * px)[None, :]
    iy, ix = np.floor(y).astype(int), np.floor(x).astype(int)
    upper = (x - ix) > (y - iy)
    total = 0.0
    for cx, cy in ((ix, iy), (ix + upper, iy + ~upper), (ix + 1, iy + 1)):
        a = angle[cy % py, cx % px]
        dx, dy = x - cx, y - cy
        falloff = np.maximum(0.5 - dx * dx - dy * dy, 0.0) ** 4
        total = total + falloff * (np.cos(a) * dx + np.sin(a) * dy)
    return total * NORMALISATION


@pytest.mark.parametrize("scale,stretch", [(3, 1), (8, 2), (40, 1)])
def test_simplex_matches_three_corner_reference(scale, stretch):
    grid = Grid(128, 5)
    assert np.abs(simplex_signed(grid, scale, stretch) - reference_simplex(grid, scale, stretch)).max() < 1e-5


@pytest.mark.parametrize("scale,stretch", [(2, 1), (6, 2), (50, 1)])  # tall cells, mixed, short cells
def test_worley_blocks_match_brute_force(scale, stretch):
    grid = Grid(64, 9)
    py, px = periods(scale, stretch)
    offsets, values = feature_points(grid, py, px, 1.0, "worley")
    y, x = (grid.axis * py)[:, None, None, None], (grid.axis * px)[None, :, None, None]
    fy = np.arange(py)[None, None, :, None] + offsets[0][None, None]
    fx = np.arange(px)[None, None, None, :] + offsets[1][None, None]
    dy = (fy - y + py / 2) % py - py / 2  # wrapped distances to every feature point
    dx = (fx - x + px / 2) % px - px / 2
    dist = np.sqrt(dy * dy + dx * dx).reshape(64, 64, -1)
    ordered = np.sort(dist, axis=-1)
    f1, f2, cell = nearest_two(grid, py, px, 1.0, "worley")
    assert np.abs(f1 - ordered[..., 0]).max() < 1e-5
    assert np.abs(f2 - ordered[..., 1]).max() < 1e-5
    nearest = values.ravel()[np.argmin(dist, axis=-1)]
    assert np.mean(cell == nearest) > 0.999


def test_fbm_matches_full_rank_octave_products():
    grid = Grid(64, 2)
    expected = np.zeros((64, 64))
    weights = [0.6**k for k in range(3)]
    for k, period in enumerate((8, 16, 32)):
        py, px = periods(period, 4)
        lattice = grid.rng(("value", k), py, px).random((py, px)) * 2.0 - 1.0
        expected += weights[k] * axis_weights(64, py)[0] @ lattice @ axis_weights(64, px)[0].T
    expected = np.clip(0.5 + 1.25 * expected / sum(weights), 0.0, 1.0)
    assert np.abs(fbm(grid, "value", 8, 3, 0.6, 4) - expected).max() < 1e-5
