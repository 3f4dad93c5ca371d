"""Evaluation context: the pixel grid over the unit square and per-node seeds."""

from __future__ import annotations

import hashlib
from dataclasses import dataclass
from functools import cached_property

import numpy as np


def derive_seed(*parts) -> int:
    """A stable 63-bit seed from any printable parts (independent of PYTHONHASHSEED)."""
    text = "\x1f".join(str(p) for p in parts).encode()
    return int.from_bytes(hashlib.blake2b(text, digest_size=8).digest(), "little") >> 1


@dataclass(frozen=True)
class Grid:
    """A square pixel grid: pixel (row, col) sits at u = col/size, v = 1 - row/size."""

    size: int
    seed: int = 0

    def rng(self, *salt) -> np.random.Generator:
        return np.random.default_rng(derive_seed(self.seed, *salt))

    def with_seed(self, *salt) -> Grid:
        return Grid(self.size, derive_seed(self.seed, *salt))

    @cached_property
    def axis(self) -> np.ndarray:
        """Pixel positions along one axis in tile units, [0, 1)."""
        return np.arange(self.size, dtype=np.float64) / self.size

    @cached_property
    def frequencies(self) -> tuple[np.ndarray, np.ndarray]:
        """Row and column FFT frequencies in cycles per tile, shaped for rfft2 output."""
        fy = np.fft.fftfreq(self.size, 1.0 / self.size)[:, None]
        fx = np.fft.rfftfreq(self.size, 1.0 / self.size)[None, :]
        return fy, fx


def lattice_vector(direction_deg: float, length: float) -> tuple[int, int]:
    """The integer (du, dv) closest to `length` cycles per tile along `direction_deg`.

    Integer wave vectors keep patterns periodic over the unit square, so directions are
    quantised: the longer the vector, the finer the angle steps.
    """
    angle = np.deg2rad(direction_deg)
    du, dv = int(round(length * np.cos(angle))), int(round(length * np.sin(angle)))
    if du == 0 and dv == 0:
        return (1, 0) if abs(np.cos(angle)) >= abs(np.sin(angle)) else (0, 1)
    return du, dv


def uv(grid: Grid) -> tuple[np.ndarray, np.ndarray]:
    """u as a (1, size) row and v (pointing up the image) as a (size, 1) column."""
    u = grid.axis.astype(np.float32)[None, :]
    v = (1.0 - grid.axis).astype(np.float32)[:, None]
    return u, v


MIN_BLOCK_ELEMENTS = 1 << 15  # row blocks of about this many pixels stay in cache


def row_blocks(cell_rows: np.ndarray, size: int) -> list[tuple[int, int]]:
    """Consecutive pixel-row ranges of at most ~MIN_BLOCK_ELEMENTS pixels, split at lattice
    rows too when cells are tall enough (a block inside one lattice row is separable)."""
    chunk = max(1, MIN_BLOCK_ELEMENTS // size)
    starts = set(range(0, size, chunk))
    cell_starts = np.flatnonzero(np.diff(cell_rows)) + 1
    if size >= (len(cell_starts) + 1) * max(1, chunk // 4):
        starts.update(cell_starts.tolist())
    bounds = sorted(starts) + [size]
    return list(zip(bounds[:-1], bounds[1:]))
