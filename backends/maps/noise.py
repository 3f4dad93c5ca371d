"""Noise generators for the node graph: single octaves, fBm and turbulence."""
from __future__ import annotations

import numpy as np

from .grid import Grid
from .lattice import SIGNED, fractal_sum, perlin_noise, value_noise
from .simplex import simplex_noise
from .worley import worley_noise

BASES = {"perlin": perlin_noise, "value": value_noise, "simplex": simplex_noise}


def octave_scales(grid: Grid, scale: int, octaves: int) -> list[int]:
    """Lattice periods doubling per octave, stopping before features shrink below 2 px."""
    scales = [max(1, int(round(scale))) * 2**k for k in range(max(1, int(octaves)))]
    return [s for s in scales if s <= grid.size // 2] or [scales[0]]


def fractal(grid: Grid, basis: str, scale: int, octaves: int, gain: float, stretch: int, fold: bool):
    """Normalised weighted octave sum in [-1, 1] (of |octaves| when `fold`)."""
    scales = octave_scales(grid, scale, octaves)
    weights = [gain**k for k in range(len(scales))]
    if basis in SIGNED and not fold:
        return fractal_sum(grid, basis, scales, weights, stretch, basis) / np.float32(sum(weights))
    return octave_loop(grid, basis, scales, weights, stretch, fold)


def octave_loop(grid: Grid, basis: str, scales, weights, stretch: int, fold: bool):
    total = np.zeros((grid.size, grid.size), np.float32)
    for k, (period, weight) in enumerate(zip(scales, weights)):
        layer = BASES[basis](grid, period, stretch, salt=(basis, k)) * 2.0 - 1.0
        total += np.float32(weight) * (np.abs(layer) if fold else layer)
    return total / np.float32(sum(weights))


def fbm(grid: Grid, basis="perlin", scale=4, octaves=5, gain=0.5, stretch=1):
    """Fractal Brownian motion: octaves of `basis` noise, each twice as fine, weights * gain.
    Rescaled so the result spans roughly [0, 1] around 0.5."""
    signed = fractal(grid, basis, scale, octaves, gain, stretch, fold=False)
    return np.clip(0.5 + signed * 1.25, 0.0, 1.0).astype(np.float32)


def turbulence(grid: Grid, basis="perlin", scale=4, octaves=5, gain=0.5, stretch=1):
    """Sum of |noise| octaves: billowy, with sharp creases at the zero crossings."""
    folded = fractal(grid, basis, scale, octaves, gain, stretch, fold=True)
    return np.clip(folded * 2.0, 0.0, 1.0).astype(np.float32)


def single(basis: str):
    def generate(grid: Grid, scale=8, stretch=1):
        return BASES[basis](grid, scale, stretch)
    generate.__doc__ = f"One octave of periodic {basis} noise in [0, 1]."
    return generate


def worley(grid: Grid, scale=8, feature="f1", jitter=1.0, stretch=1):
    """Cellular noise: distance to nearest feature (f1), second nearest (f2),
    edge distance (f2 - f1), or a random value per cell (cell)."""
    return worley_noise(grid, scale, feature, jitter, stretch)
