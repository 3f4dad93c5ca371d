"""Filters: blending, blurs (exact and periodic, through the FFT), tone and colour
adjustments, domain warp, transform, threshold.  Inputs are float32 maps (H, W) or (H, W, 3)."""

from __future__ import annotations

import numpy as np

from .colour import as_array, hsv_to_rgb, is_rgb, luminance, rgb_to_hsv
from .grid import Grid, lattice_vector

BLEND_MODES = ("mix", "multiply", "add", "subtract", "screen", "overlay", "max", "min")


def blended(mode: str, a: np.ndarray, b: np.ndarray) -> np.ndarray:
    if mode == "multiply":
        return a * b
    if mode == "add":
        return a + b
    if mode == "subtract":
        return a - b
    if mode == "screen":
        return 1.0 - (1.0 - a) * (1.0 - b)
    if mode == "overlay":
        return np.where(a < 0.5, 2.0 * a * b, 1.0 - 2.0 * (1.0 - a) * (1.0 - b))
    if mode == "max":
        return np.maximum(a, b)
    if mode == "min":
        return np.minimum(a, b)
    return b


def blend(grid: Grid, a=0.0, b=1.0, mode="mix", amount=1.0, clamp=True):
    """Blend b over a with `mode`, then mix with a by `amount` (a map or a number)."""
    a, b, amount = (as_array(x) for x in (a, b, amount))
    if not any(is_rgb(x) for x in (a, b, amount)):
        return full_size(blend_plane(mode, a, b, amount, clamp), grid)
    out = np.empty((grid.size, grid.size, 3), np.float32)
    for c in range(3):  # channel planes written into the interleaved result: no (..., 3)-wide loops
        out[..., c] = blend_plane(mode, channel(a, c), channel(b, c), channel(amount, c), clamp)
    return out


def channel(x: np.ndarray, c: int) -> np.ndarray:
    return x[..., c] if is_rgb(x) else x


def blend_plane(mode: str, a: np.ndarray, b: np.ndarray, amount: np.ndarray, clamp: bool) -> np.ndarray:
    """One channel of `blend`: a + (blended - a) * amount, computed in place where possible."""
    top = np.asarray(blended(mode, a, b), np.float32)
    fresh = top is not a and top is not b
    if not (amount.ndim == 0 and amount == 1.0):
        shape = np.broadcast_shapes(top.shape, a.shape, amount.shape)
        top = np.subtract(top, a, out=top) if fresh and top.shape == shape else np.subtract(top, a, dtype=np.float32)
        top *= amount
        top += a
    elif not fresh:
        top = top.copy()
    return np.clip(top, 0.0, 1.0, out=top) if clamp else top


def full_size(out: np.ndarray, grid: Grid) -> np.ndarray:
    full = (grid.size, grid.size) + out.shape[2:]
    return out if out.shape == full else np.broadcast_to(out, np.broadcast_shapes(out.shape, full)).copy()


def spectral_filter(image: np.ndarray, gain: np.ndarray) -> np.ndarray:
    """Multiply the spectrum of each channel by `gain` (rfft2 layout); periodic by construction."""
    channels = image[..., None] if image.ndim == 2 else image
    spectrum = np.fft.rfft2(channels, axes=(0, 1))
    out = np.fft.irfft2(spectrum * gain[..., None], s=channels.shape[:2], axes=(0, 1))
    return out.reshape(image.shape).astype(np.float32)


def blur(grid: Grid, input=0.0, radius=0.01):
    """Gaussian blur; `radius` is the standard deviation in tile units."""
    fy, fx = grid.frequencies
    gain = np.exp(-2.0 * (np.pi * radius) ** 2 * (fx * fx + fy * fy))
    return spectral_filter(as_array(input), gain)


def directional_blur(grid: Grid, input=0.0, length=0.1, direction=0.0):
    """Gaussian blur along `direction` only (degrees, 0 = +u): streaks of about `length` tiles."""
    fy, fx = grid.frequencies
    angle = np.deg2rad(direction)
    along = fx * np.cos(angle) - fy * np.sin(angle)  # rows run down the image, v runs up
    gain = np.exp(-2.0 * (np.pi * length / 2.0) ** 2 * along * along)
    return spectral_filter(as_array(input), gain)


def levels(grid: Grid, input=0.0, in_low=0.0, in_high=1.0, gamma=1.0, out_low=0.0, out_high=1.0):
    """Photoshop-style levels: remap [in_low, in_high], apply gamma, map to [out_low, out_high]."""
    x = as_array(input)
    span = max(in_high - in_low, 1e-6)
    out = np.empty(x.shape, np.float32)
    if in_low == 0.0 and span == 1.0:
        np.clip(x, 0.0, 1.0, out=out)  # (x - 0) / 1 is x exactly
    else:
        np.subtract(x, in_low, out=out)
        out /= span
        np.clip(out, 0.0, 1.0, out=out)
    power_in_place(out, 1.0 / max(gamma, 1e-3))
    if out_low != 0.0 or out_high != 1.0:
        out *= out_high - out_low
        out += out_low
    return out


def power_in_place(x: np.ndarray, exponent: float) -> None:
    """x **= exponent; small whole exponents by repeated multiplication (float32 rounding)."""
    if exponent == 1.0:
        return
    if exponent in (2.0, 4.0, 8.0):
        for _ in range(int(exponent).bit_length() - 1):
            np.multiply(x, x, out=x)
        return
    np.power(x, np.float32(exponent), out=x)


def contrast(grid: Grid, input=0.0, amount=1.0, pivot=0.5):
    """Scale distances from `pivot` by `amount` (0 = flat, 1 = unchanged), clamped to [0, 1]."""
    out = np.subtract(as_array(input), pivot, dtype=np.float32)
    out *= amount
    out += pivot
    return np.clip(out, 0.0, 1.0, out=out)


def invert(grid: Grid, input=0.0):
    return np.subtract(np.float32(1.0), as_array(input), dtype=np.float32)


def colorize(grid: Grid, input=0.0, colors=((0, 0, 0), (1, 1, 1)), positions=None):
    """Gradient map: scalar map values pick colours from evenly spaced (or given) stops."""
    x = as_array(input)
    x = luminance(x) if is_rgb(x) else x
    stops = np.asarray(colors, np.float32).reshape(-1, 3)
    where = np.linspace(0.0, 1.0, len(stops)) if positions is None else np.asarray(positions, np.float32)
    return np.stack([np.interp(x, where, stops[:, c]).astype(np.float32) for c in range(3)], axis=-1)


def hsv_adjust(grid: Grid, input=(0.5, 0.5, 0.5), hue=0.0, saturation=1.0, value=1.0):
    """Shift hue (turns), scale saturation and value of an RGB map."""
    rgb = np.broadcast_to(as_array(input), (grid.size, grid.size, 3))
    h, s, v = np.moveaxis(rgb_to_hsv(rgb), -1, 0)
    hsv = np.stack([(h + hue) % 1.0, np.clip(s * saturation, 0, 1), np.clip(v * value, 0, 1)], axis=-1)
    return hsv_to_rgb(hsv)


def threshold(grid: Grid, input=0.0, low=0.45, high=0.55):
    """Smoothstep mask: 0 below `low`, 1 above `high`."""
    x = as_array(input)
    t = np.subtract(x, low, dtype=np.float32)
    t /= max(high - low, 1e-6)
    np.clip(t, 0.0, 1.0, out=t)
    return (t * t * (3.0 - 2.0 * t)).astype(np.float32, copy=False)


def sample_periodic(image: np.ndarray, rows: np.ndarray, cols: np.ndarray) -> np.ndarray:
    """Bilinear lookup at fractional pixel positions, wrapping around the tile."""
    size_r, size_c = image.shape[:2]
    r0, c0 = np.floor(rows), np.floor(cols)
    fr, fc = rows - r0, cols - c0
    r0, c0 = r0.astype(np.int64) % size_r, c0.astype(np.int64) % size_c
    r1, c1 = (r0 + 1) % size_r, (c0 + 1) % size_c
    fr, fc = (fr[..., None], fc[..., None]) if image.ndim == 3 else (fr, fc)
    top = image[r0, c0] * (1 - fc) + image[r0, c1] * fc
    bottom = image[r1, c0] * (1 - fc) + image[r1, c1] * fc
    return (top * (1 - fr) + bottom * fr).astype(np.float32)


def pixel_grid(grid: Grid) -> tuple[np.ndarray, np.ndarray]:
    index = np.arange(grid.size, dtype=np.float32)
    return np.broadcast_to(index[:, None], (grid.size,) * 2), np.broadcast_to(index[None, :], (grid.size,) * 2)


def warp(grid: Grid, input=0.0, by=0.5, by_v=None, amount=0.1):
    """Domain warp: look `input` up at uv + amount * (by - 0.5, by_v - 0.5) (tile units).
    Without `by_v`, the v displacement reads `by` half a tile away."""
    shift_u = np.broadcast_to(as_array(by) - 0.5, (grid.size, grid.size))
    half = grid.size // 2
    shift_v = np.roll(shift_u, (half, half), axis=(0, 1)) if by_v is None else as_array(by_v) - 0.5
    rows, cols = pixel_grid(grid)
    scale = amount * grid.size
    return sample_periodic(as_array(input), rows - shift_v * scale, cols + shift_u * scale)


def transform(grid: Grid, input=0.0, scale=1, rotate=0.0, offset_u=0.0, offset_v=0.0):
    """Repeat `input` `scale` times, rotated by `rotate` degrees, shifted by the offsets.
    The linear part is an integer matrix so the result still tiles: the rotation snaps
    to the nearest angle whose lattice vector at this scale has integer components."""
    du, dv = lattice_vector(rotate, max(1, int(round(scale))))
    rows, cols = pixel_grid(grid)
    u, v = cols / grid.size, -rows / grid.size
    source_u = du * u - dv * v + offset_u
    source_v = dv * u + du * v + offset_v
    return sample_periodic(as_array(input), -source_v * grid.size, source_u * grid.size)


def normalize(grid: Grid, input=0.0, spread=0.18):
    """Re-centre a scalar map to mean 0.5 and standard deviation `spread` (clamped to [0, 1]);
    restores contrast lost by blurring and makes parameters act on a known range."""
    x = as_array(input)
    deviation = float(x.std())
    out = np.subtract(x, x.mean(), dtype=np.float32)
    out *= np.float32(spread / deviation if deviation > 1e-8 else 0.0)
    out += np.float32(0.5)
    return np.clip(out, 0.0, 1.0, out=out)


def coverage_mask(grid: Grid, input=0.0, coverage=0.5, softness=0.05):
    """Mask covering about `coverage` of the tile where `input` is highest: a smoothstep
    centred on the (1 - coverage) quantile of `input`, `softness` wide in quantile units."""
    x = as_array(input)
    if coverage <= 0.0:
        return np.zeros_like(x)
    if coverage >= 1.0:
        return np.ones_like(x)
    low, centre, high = np.quantile(
        x, [max(0.0, 1 - coverage - softness), 1 - coverage, min(1.0, 1 - coverage + softness)]
    )
    return threshold(grid, x, min(low, centre - 1e-6), max(high, centre + 1e-6))
