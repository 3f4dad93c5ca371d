"""How large a baked map's features are, measured from the pixels (issue #15: textures at real scale).

The feature size is the period of the map's dominant spatial frequency: the peak of its power
spectrum summed across the other axis (along "u" or "v"), or summed over rings of equal frequency
(in "any" direction), so a brick wall gives its course pitch, Worley cells their spacing and fBm
patches their largest octave. Maps tile, so the FFT needs no window. Sizes are in texture units (fractions of the tile).
"""

from __future__ import annotations

import numpy as np

__all__ = ["dominant_period", "scalar_of"]

MIN_REFINED = 4  # cycles per tile


def scalar_of(array: np.ndarray) -> np.ndarray:
    """A (H, W) signal of a baked map: a scalar map itself, a colour map's mean, a normal map's slope."""
    a = np.asarray(array, np.float64)
    if a.ndim == 2:
        return a
    if a.shape[-1] == 3 and a[..., 2].min() > 0 and np.allclose(np.linalg.norm(a, axis=-1), 1, atol=1e-3):
        return a[..., 0] + a[..., 1]  # a unit normal: its tilt along u plus along v
    return a[..., :3].mean(axis=-1)


def _axis_energy(power: np.ndarray, axis: str) -> tuple[np.ndarray, np.ndarray]:
    """(frequency in cycles per tile, energy per log band) along `axis`, DC left out."""
    n = power.shape[0]
    if axis in ("u", "v"):
        # u runs along columns (axis 1), v along rows (axis 0): the spectrum along one, summed over the other
        line = power.sum(axis=0) if axis == "u" else power.sum(axis=1)
        f = np.arange(1, n // 2)
        return f.astype(np.float64), line[1 : n // 2]
    fy = np.fft.fftfreq(n, 1.0 / n)
    radius = np.rint(np.hypot(fy[:, None], fy[None, :])).astype(np.int64)
    sums = np.bincount(radius.ravel(), power.ravel())
    f = np.arange(1, n // 2)
    return f.astype(np.float64), sums[1 : n // 2]


def dominant_period(array: np.ndarray, axis: str = "any") -> float:
    """The period (texture units) of the strongest spatial frequency of a square baked map,
    along "u", "v" or in "any" direction; from MIN_REFINED cycles per tile up the peak is refined by
    a parabola through its neighbours on a log-frequency axis (below, neighbouring bins are an octave
    or more apart, and a parabola through them says little)."""
    signal = scalar_of(array)
    if signal.shape[0] != signal.shape[1]:
        raise ValueError(f"a square map is needed, got {signal.shape}")
    power = np.abs(np.fft.fft2(signal - signal.mean())) ** 2
    f, energy = _axis_energy(power, axis)
    k = int(np.argmax(energy))
    peak = float(np.log(f[k]))
    if f[k] >= MIN_REFINED and k < len(f) - 1 and energy[k - 1] > 0 and energy[k + 1] > 0:
        y = np.log(energy[k - 1 : k + 2])
        x = np.log(f[k - 1 : k + 2])
        a, b, _ = np.polyfit(x, y, 2)
        if a < 0:
            peak = float(np.clip(-b / (2 * a), x[0], x[2]))
    return float(np.exp(-peak))
