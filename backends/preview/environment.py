"""Lighting of the preview scene: an HDR environment (equirectangular, linear Rec.709) and a
key light. Environments are generated in numpy (`ENVIRONMENTS`) or read with OpenImageIO.

Direction <-> equirect coordinates follow Mitsuba 3's `envmap` plugin: u = atan2(d.x, -d.z) / 2pi
(wrapped to [0, 1)), v = acos(d.y) / pi (v = 0 is the top, +y up). Texels are read as OpenGL
does: texel (i, j) is the value at the centre u = (i + 0.5) / W, v = (j + 0.5) / H, bilinear in
between (rows clamped at the poles). Mitsuba agrees in u but puts row j at v = j / (H - 1) (its
first and last rows at the poles), so the image it is given is `mitsuba_rows(image)`: the same
bilinear function, resampled onto its rows.
"""

from __future__ import annotations

import hashlib
from dataclasses import dataclass, field
from functools import cached_property
from pathlib import Path

import numpy as np

from ..image_size import check_image_size

ENV_WIDTH, ENV_HEIGHT = 512, 256


@dataclass(frozen=True)
class KeyLight:
    direction: tuple = (0.45, 0.6, 0.66)  # towards the light (world, y up); normalised on use
    irradiance: float = 2.0  # W/m^2 on a surface facing the light (linear RGB grey)

    @property
    def unit(self) -> np.ndarray:
        d = np.asarray(self.direction, np.float64)
        return d / np.linalg.norm(d)


@dataclass
class Environment:
    name: str
    image: np.ndarray  # (H, W, 3) float32 linear radiance, row 0 = top (+y)
    key: KeyLight = field(default_factory=KeyLight)

    @cached_property
    def content_key(self) -> str:
        """A digest of the image and the key light: what GPU textures made from the environment
        are cached by (an environment is not changed once made)."""
        digest = hashlib.blake2b(repr((self.name, self.image.shape, self.key)).encode(), digest_size=16)
        digest.update(np.ascontiguousarray(self.image, np.float32).tobytes())
        return digest.hexdigest()

    @property
    def mean_radiance(self) -> np.ndarray:
        return (self.image * pixel_solid_angles(*self.image.shape[:2])[..., None]).sum((0, 1)) / (4 * np.pi)


class EnvironmentError(ValueError):
    """An environment map that cannot be read."""


# ------------------------------------------------------------------------ mapping


def pixel_directions(height: int, width: int) -> np.ndarray:
    """(H, W, 3) unit directions of the pixel centres (Mitsuba's envmap convention)."""
    u = (np.arange(width) + 0.5) / width
    v = (np.arange(height) + 0.5) / height
    phi, theta = np.meshgrid(u * 2 * np.pi, v * np.pi)
    st = np.sin(theta)
    return np.stack([st * np.sin(phi), np.cos(theta), -st * np.cos(phi)], -1)


def direction_to_uv(d: np.ndarray) -> np.ndarray:
    d = np.asarray(d, np.float64)
    u = np.mod(np.arctan2(d[..., 0], -d[..., 2]) / (2 * np.pi), 1.0)
    v = np.arccos(np.clip(d[..., 1], -1, 1)) / np.pi
    return np.stack([u, v], -1)


def pixel_solid_angles(height: int, width: int) -> np.ndarray:
    theta = (np.arange(height) + 0.5) / height * np.pi
    return np.broadcast_to((2 * np.pi / width) * (np.pi / height) * np.sin(theta)[:, None], (height, width))


# ------------------------------------------------------------------ generated maps


def _smooth_box(d: np.ndarray, centre, half_width: float, half_height: float, softness: float = 0.03):
    """A soft rectangular light (a softbox) facing the origin: 1 inside, smooth edge."""
    c = np.asarray(centre, np.float64)
    c /= np.linalg.norm(c)
    right = np.cross([0.0, 1.0, 0.0], c)
    right /= np.linalg.norm(right) if np.linalg.norm(right) > 0 else 1.0
    up = np.cross(c, right)
    facing = d @ c
    x, y = (d @ right) / np.maximum(facing, 1e-3), (d @ up) / np.maximum(facing, 1e-3)
    edge = lambda q, h: np.clip((h - np.abs(q)) / softness + 0.5, 0, 1)
    return np.where(facing > 0, edge(x, half_width) * edge(y, half_height), 0.0)


def _sky_gradient(d: np.ndarray, zenith, horizon, ground) -> np.ndarray:
    y = d[..., 1:2]
    up = np.clip(y, 0, 1) ** 0.6
    sky = np.asarray(horizon) * (1 - up) + np.asarray(zenith) * up
    below = (
        np.asarray(ground) * (1 - np.exp(-8 * np.clip(-y, 0, 1)))
        + np.asarray(horizon) * np.exp(-8 * np.clip(-y, 0, 1)) * 0.5
    )
    return np.where(y >= 0, sky, below)


def studio(height: int = ENV_HEIGHT, width: int = ENV_WIDTH) -> np.ndarray:
    """Neutral photo studio: grey cyclorama, a large key softbox, a strip light and a rim light."""
    d = pixel_directions(height, width)
    img = _sky_gradient(d, zenith=(0.22, 0.22, 0.23), horizon=(0.45, 0.45, 0.45), ground=(0.12, 0.115, 0.11))
    img = img + 6.0 * _smooth_box(d, (-0.8, 0.7, 0.9), 0.45, 0.3)[..., None] * np.array([1.0, 0.98, 0.95])
    img = img + 3.0 * _smooth_box(d, (1.0, 0.25, 0.2), 0.08, 0.6)[..., None] * np.array([0.95, 0.97, 1.0])
    img = img + 4.0 * _smooth_box(d, (0.3, 0.5, -1.0), 0.35, 0.2)[..., None]
    return img.astype(np.float32)


def sky(height: int = ENV_HEIGHT, width: int = ENV_WIDTH) -> np.ndarray:
    """Overcast outdoor sky over a dark ground."""
    d = pixel_directions(height, width)
    return _sky_gradient(d, zenith=(0.35, 0.5, 0.9), horizon=(0.9, 0.9, 0.95), ground=(0.12, 0.1, 0.08)).astype(
        np.float32
    )


def sun(height: int = ENV_HEIGHT, width: int = ENV_WIDTH) -> np.ndarray:
    """The sky plus a small, very bright sun (0.5 deg radius x 4): the hard case for IBL."""
    d = pixel_directions(height, width)
    s = np.array([-0.5, 0.45, 0.75])
    s /= np.linalg.norm(s)
    disc = (d @ s > np.cos(np.radians(2.0))).astype(np.float64)
    return (sky(height, width) + 2000.0 * disc[..., None] * np.array([1.0, 0.95, 0.85])).astype(np.float32)


#: name -> generator (H, W) -> image. Any other name is read as a file (.hdr/.exr/...).
ENVIRONMENTS = {"studio": studio, "sky": sky, "sun": sun}


def read_image(path) -> np.ndarray:
    """An environment file as (H, W, 3) float32; its size is checked from the header first
    (cnlmc.backends.image_size: ImageTooLarge, a ValueError naming the file and its size)."""
    import OpenImageIO as oiio

    check_image_size(path, "environment map")
    inp = oiio.ImageInput.open(str(path))
    if inp is None:
        raise EnvironmentError(f"cannot read environment map {path}: {oiio.geterror()}")
    try:
        pixels = inp.read_image(0, 0, 0, 3, oiio.FLOAT)
    finally:
        inp.close()
    if pixels is None:
        raise EnvironmentError(f"cannot read environment map {path}")
    pixels = np.asarray(pixels, np.float32)
    if pixels.ndim == 2:
        pixels = pixels[..., None]
    return np.repeat(pixels, 3, axis=2) if pixels.shape[2] == 1 else pixels[..., :3]


#: above this many rows, mitsuba_rows() resamples to H + 1 rows (not exact) instead of 2H + 1.
MITSUBA_EXACT_ROWS = 1024


def mitsuba_rows(image: np.ndarray) -> np.ndarray:
    """The environment resampled for Mitsuba's `envmap`, which reads row j of an H' row image at
    v = j / (H' - 1) (this module's rows, and the preview's texture, are at v = (j + 0.5) / H).

    With H' = 2H + 1 rows the preview's bilinear function is represented exactly: the odd rows
    are the original rows, the even ones the midpoints between them, the first and last the
    clamped polar rows. Columns need no change (Mitsuba's texel i is at u = (i + 0.5) / W too).
    Images taller than MITSUBA_EXACT_ROWS get H + 1 rows at v = k / H instead (bilinear
    samples of the same function; half a row of extra blur, at a resolution where it is small)."""
    image = np.asarray(image, np.float32)
    h = image.shape[0]
    rows = 2 * h + 1 if h <= MITSUBA_EXACT_ROWS else h + 1
    v = np.arange(rows) / (rows - 1)  # Mitsuba's row positions
    y = np.clip(v * h - 0.5, 0.0, h - 1.0)  # -> continuous row index of the image
    j0 = np.minimum(np.floor(y).astype(np.int64), h - 1)
    j1 = np.minimum(j0 + 1, h - 1)
    w = (y - j0).astype(np.float32)[:, None, None]
    return np.ascontiguousarray(image[j0] * (1 - w) + image[j1] * w, np.float32)


def write_exr(path, image: np.ndarray) -> None:
    import OpenImageIO as oiio

    h, w, c = image.shape
    out = oiio.ImageOutput.create(str(path))
    if out is None:
        raise EnvironmentError(f"cannot write {path}: {oiio.geterror()}")
    out.open(str(path), oiio.ImageSpec(w, h, c, oiio.FLOAT))
    out.write_image(np.ascontiguousarray(image, np.float32))
    out.close()


def environment(name_or_path: str = "studio", key: KeyLight | None = None) -> Environment:
    """A named generated environment or an .hdr/.exr file, made anew (a renderer keeps the ones
    it uses: Renderer.scene)."""
    if name_or_path in ENVIRONMENTS:
        image = ENVIRONMENTS[name_or_path]()
    else:
        path = Path(name_or_path)
        if not path.exists():
            raise EnvironmentError(
                f"environment {name_or_path!r} is neither a file nor one of {', '.join(ENVIRONMENTS)}"
            )
        image = read_image(path)
    if not np.isfinite(image).all():
        image = np.nan_to_num(image, nan=0.0, posinf=0.0, neginf=0.0)
    return Environment(str(name_or_path), np.maximum(image, 0).astype(np.float32), key or KeyLight())
