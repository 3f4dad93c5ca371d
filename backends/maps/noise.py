"""Noise generators for the node graph: single octaves, fBm and turbulence."""

from __future__ import annotations

import numpy as np

from .blas import single_threaded_blas
from .grid import MIN_BLOCK_ELEMENTS, Grid
from .lattice import FACTORS, clip01, fractal_sum, noise_sum, perlin_noise, value_noise
from .simplex import simplex_noise, simplex_signed
from .worley import worley_noise

BASES = {"perlin": perlin_noise, "value": value_noise, "simplex": simplex_noise}


def octave_scales(grid: Grid, scale: int, octaves: int) -> list[int]:
    """Lattice periods doubling per octave, stopping before features shrink below 2 px."""
    scales = [max(1, int(round(scale))) * 2**k for k in range(max(1, int(octaves)))]
    return [s for s in scales if s <= grid.size // 2] or [scales[0]]


def signed_layer(grid: Grid, basis: str, period: int, stretch: int, salt) -> np.ndarray:
    """One octave in [-1, 1] (a fresh float32 array the caller may overwrite)."""
    if basis == "simplex":
        layer = simplex_signed(grid, period, stretch, salt)
    else:
        layer = noise_sum(grid, basis, [(period, 1.0, salt)], stretch)
    return np.clip(layer, -1.0, 1.0, out=layer)


def octave_loop(grid: Grid, basis: str, scales, weights, stretch: int, fold: bool, offset: float = 0.0):
    """offset + sum of weight * octave (of |octave| when `fold`), octave by octave."""
    total = np.full((grid.size, grid.size), offset, np.float32)
    for k, (period, weight) in enumerate(zip(scales, weights)):
        layer = signed_layer(grid, basis, period, stretch, (basis, k))
        if fold:
            np.abs(layer, out=layer)
        layer *= np.float32(weight)
        total += layer
    return total


def fbm(grid: Grid, basis="perlin", scale=4, octaves=5, gain=0.5, stretch=1):
    """Fractal Brownian motion: octaves of `basis` noise, each twice as fine, weights * gain.
    Rescaled so the result spans roughly [0, 1] around 0.5."""
    scales = octave_scales(grid, scale, octaves)
    weights = [gain**k for k in range(len(scales))]
    weights = [1.25 * w / sum(weights) for w in weights]
    if basis in FACTORS:
        return clip01(fractal_sum(grid, basis, scales, weights, stretch, basis, offset=0.5))
    return clip01(octave_loop(grid, basis, scales, weights, stretch, fold=False, offset=0.5))


def folded_lattice_sum(grid: Grid, basis: str, scales, weights, stretch: int) -> np.ndarray:
    """sum of weight * min(|octave|, 1) for lattice bases, row block by row block so each
    octave's product, fold and sum stay in cache (weight >= 0 folds into the factors)."""
    factors = [FACTORS[basis](grid, s, stretch, (basis, k)) for k, s in enumerate(scales)]
    pairs = [(left * np.float32(w), right, np.float32(w)) for (left, right), w in zip(factors, weights)]
    total = np.zeros((grid.size, grid.size), np.float32)
    chunk = max(1, MIN_BLOCK_ELEMENTS // grid.size)
    with single_threaded_blas():  # many small products: waking BLAS threads costs more
        for r0 in range(0, grid.size, chunk):
            block = total[r0 : r0 + chunk]
            for left, right, weight in pairs:
                layer = left[r0 : r0 + chunk] @ right
                np.abs(layer, out=layer)
                block += np.minimum(layer, weight, out=layer)
    return total


def turbulence(grid: Grid, basis="perlin", scale=4, octaves=5, gain=0.5, stretch=1):
    """Sum of |noise| octaves: billowy, with sharp creases at the zero crossings."""
    scales = octave_scales(grid, scale, octaves)
    weights = [gain**k for k in range(len(scales))]
    weights = [2.0 * w / sum(weights) for w in weights]
    if basis in FACTORS and min(weights) >= 0.0:
        return clip01(folded_lattice_sum(grid, basis, scales, weights, stretch))
    return clip01(octave_loop(grid, basis, scales, weights, stretch, fold=True))


def single(basis: str):
    def generate(grid: Grid, scale=8, stretch=1):
        return BASES[basis](grid, scale, stretch)

    generate.__doc__ = f"One octave of periodic {basis} noise in [0, 1]."
    return generate


def worley(grid: Grid, scale=8, feature="f1", jitter=1.0, stretch=1):
    """Cellular noise: distance to nearest feature (f1), second nearest (f2),
    edge distance (f2 - f1), or a random value per cell (cell)."""
    return worley_noise(grid, scale, feature, jitter, stretch)
