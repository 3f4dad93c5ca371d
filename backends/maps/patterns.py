"""Periodic pattern generators: waves, gradients, checkerboard, tiles and bricks.

All return float32 maps in [0, 1] over a (size, size) grid that tile over the unit square.
"""

from __future__ import annotations

import numpy as np

from .grid import Grid, lattice_vector, uv

WAVE_SHAPES = ("sine", "saw", "square", "triangle")


def wave_phase(grid: Grid, frequency: float, direction: float, phase=0.0, distortion=1.0) -> np.ndarray:
    """Phase in cycles: du*u + dv*v (+ phase map * distortion), with an integer wave
    vector; a fresh float32 array."""
    du, dv = lattice_vector(direction, frequency)
    u, v = uv(grid)
    ramp = du * u if dv == 0 else (dv * v if du == 0 else du * u + dv * v)  # 0 * u adds exactly 0
    offset = np.asarray(phase, np.float32)
    if offset.ndim == 0 and offset == 0.0:
        return np.array(np.broadcast_to(ramp, (grid.size, grid.size)), np.float32)
    cycles = np.multiply(offset, distortion, dtype=np.float32)
    if cycles.shape != (grid.size, grid.size):
        cycles = np.array(np.broadcast_to(cycles, (grid.size, grid.size)), np.float32)
    cycles += ramp
    return cycles


def periodic_shape(cycles: np.ndarray, shape: str) -> np.ndarray:
    """The wave shape of a phase map, computed in place (`cycles` is overwritten)."""
    cycles -= np.floor(cycles)
    if shape == "sine":
        cycles *= np.float32(2.0 * np.pi)
        np.cos(cycles, out=cycles)
        cycles *= np.float32(0.5)
        return np.subtract(np.float32(0.5), cycles, out=cycles)
    if shape == "saw":
        return cycles
    if shape == "square":
        return (cycles < 0.5).astype(np.float32)
    cycles *= np.float32(2.0)
    cycles -= np.float32(1.0)
    np.abs(cycles, out=cycles)
    return np.subtract(np.float32(1.0), cycles, out=cycles)


def wave(grid: Grid, shape="sine", frequency=1, direction=0.0, phase=0.0, distortion=1.0):
    """A periodic wave along `direction` (degrees, 0 = +u, 90 = +v); `phase` (a map, in
    cycles, times `distortion`) bends the wave fronts."""
    return periodic_shape(wave_phase(grid, frequency, direction, phase, distortion), shape)


def linear_gradient(grid: Grid, direction=0.0, repeat=1, mirror=True):
    """A ramp along `direction`; mirrored (triangle) ramps tile without a seam."""
    return wave(grid, "triangle" if mirror else "saw", repeat, direction)


def wrapped_offset(axis_values: np.ndarray, centre: float) -> np.ndarray:
    offset = axis_values - centre
    return offset - np.round(offset)


def radial_gradient(grid: Grid, centre_u=0.5, centre_v=0.5, radius=0.5):
    """1 at the centre falling to 0 at `radius` (tile units), distance wrapped on the torus."""
    u, v = uv(grid)
    du, dv = wrapped_offset(u, centre_u), wrapped_offset(v, centre_v)
    distance = np.sqrt(du * du + dv * dv)
    return np.clip(1.0 - distance / max(radius, 1e-6), 0.0, 1.0).astype(np.float32)


def even(count) -> int:
    return max(2, 2 * int(round(count / 2.0)))


def checkerboard(grid: Grid, count=8):
    """Alternating cells; `count` per side is rounded to an even number so it tiles."""
    n = even(count)
    u, v = uv(grid)
    parity = np.floor(u * n).astype(np.int32) + np.floor(v * n).astype(np.int32)
    return (parity % 2).astype(np.float32)


def bevel_profile(distance_to_edge: np.ndarray, gap: float, bevel: float) -> np.ndarray:
    """0 in the mortar/grout, rising over `bevel` to 1 on the tile face (cell units)."""
    rise = (distance_to_edge - gap / 2.0) / max(bevel, 1e-6)
    return np.clip(rise, 0.0, 1.0).astype(np.float32)


def cell_edges(position: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Integer cell index and distance to the nearest cell edge, in cell units."""
    cell = np.floor(position)
    fraction = position - cell
    return cell.astype(np.int64), np.minimum(fraction, 1.0 - fraction)


def cell_random(grid: Grid, rows: np.ndarray, cols: np.ndarray, shape: tuple[int, int]):
    table = grid.rng("cells", *shape).random(shape).astype(np.float32)
    return table[rows % shape[0], cols % shape[1]]


def tiles(grid: Grid, count=4, gap=0.05, bevel=0.05, feature="height"):
    """Square tiles with grout; feature 'height' (bevelled) or 'cell' (random per tile)."""
    n = max(1, int(round(count)))
    u, v = uv(grid)
    col, edge_u = cell_edges(np.broadcast_to(u * n, (grid.size, grid.size)))
    row, edge_v = cell_edges(np.broadcast_to(v * n, (grid.size, grid.size)))
    if feature == "cell":
        return cell_random(grid, row, col, (n, n))
    return bevel_profile(np.minimum(edge_u, edge_v), gap, bevel)


def bricks(grid: Grid, rows=8, per_row=4, gap=0.06, bevel=0.04, feature="height"):
    """Running-bond bricks: alternate rows shift by half a brick; `rows` is made even."""
    n_rows, n_cols = even(rows), max(1, int(round(per_row)))
    u, v = uv(grid)
    row, edge_v = cell_edges(np.broadcast_to(v * n_rows, (grid.size, grid.size)))
    shifted = u * n_cols + 0.5 * (row % 2)
    col, edge_u = cell_edges(shifted)
    if feature == "cell":
        return cell_random(grid, row, col, (n_rows, n_cols))
    aspect = n_rows / n_cols  # brick width / height in row units
    return bevel_profile(np.minimum(edge_u * aspect, edge_v), gap, bevel)
