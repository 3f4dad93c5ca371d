"""Direction grids for the stability tests (importable helper, not a test module)."""

from __future__ import annotations

import numpy as np

# θ from 0 to exactly 90° (with near-grazing values) and past it (below the horizon).
THETAS_DEG = np.array(
    [0.0, 1e-6, 0.1, 10.0, 30.0, 45.0, 60.0, 75.0, 85.0, 89.0, 89.9, 89.99999, 90.0, 90.5, 120.0, 180.0]
)
PHIS_DEG = np.array([0.0, 45.0, 90.0, 137.0, 180.0, 270.0])


def sphere_dirs(thetas_deg=THETAS_DEG, phis_deg=PHIS_DEG) -> np.ndarray:
    t, p = np.meshgrid(np.radians(thetas_deg), np.radians(phis_deg), indexing="ij")
    d = np.stack([np.sin(t) * np.cos(p), np.sin(t) * np.sin(p), np.cos(t)], axis=-1)
    d = d.reshape(-1, 3)
    d[np.isclose(thetas_deg.repeat(len(phis_deg)), 90.0), 2] = 0.0  # exactly 90°
    return d


def all_pairs() -> tuple[np.ndarray, np.ndarray]:
    """Every (wo, wi) pair of the grid, plus wo = wi and wo = −wi cases."""
    d = sphere_dirs()
    wo = np.repeat(d, len(d), axis=0)
    wi = np.tile(d, (len(d), 1))
    return np.concatenate([wo, d, d]), np.concatenate([wi, d, -d])
