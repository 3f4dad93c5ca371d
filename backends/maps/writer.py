"""Writing baked maps through OpenImageIO, atomically, with colour-space metadata.

Colour roles are written sRGB-encoded to PNG (oiio:ColorSpace "sRGB") and linear to EXR
("lin_rec709"); normals as n * 0.5 + 0.5 and parameter maps as-is, as data: "Raw" in EXR,
and "lin_rec709" in PNG (PNG cannot say "Raw"; this writes gAMA 1.0, so readers do not
apply the sRGB curve, whereas an untagged PNG reads back as sRGB).
"""

from __future__ import annotations

import contextlib
import functools
from pathlib import Path
from types import ModuleType

import numpy as np

from cnlmc.filenames import fit_name
from cnlmc.interrupts import signals_deferred
from cnlmc.output import Staging

from .colour import linear_to_srgb
from .errors import MapError
from .roles import COLOR_ROLES

FORMATS = {  # fmt -> (extension, OIIO pixel type)
    "png8": (".png", "uint8"),
    "png16": (".png", "uint16"),
    "exr-half": (".exr", "half"),
    "exr-float": (".exr", "float"),
}


def encode(role: str, array: np.ndarray, extension: str) -> tuple[np.ndarray, str]:
    """Pixels to store and their colour space."""
    png = extension == ".png"
    if role in COLOR_ROLES:
        return (linear_to_srgb(array), "sRGB") if png else (array, "lin_rec709")
    data_space = "lin_rec709" if png else "Raw"
    return (array * 0.5 + 0.5 if role == "normal" else array), data_space


def image_library() -> ModuleType:
    """OpenImageIO (the 'maps' extra), imported on first need. A writer that stages images inside a
    signal guard (cnlmc.interrupts) loads it BEFORE entering the guard: a SIGTERM during the first
    import of this nanobind extension aborted the process (SIGABRT, temps left) instead of cleaning
    up (tests/language/test_signals, a fresh clone without bytecode)."""
    import OpenImageIO as oiio

    return oiio


def write_image(path: Path, pixels: np.ndarray, pixel_type: str, colour_space: str) -> None:
    oiio = image_library()

    pixels = pixels[..., None] if pixels.ndim == 2 else pixels  # OIIO misreads 2-D arrays
    height, width, channels = pixels.shape
    spec = oiio.ImageSpec(width, height, channels, pixel_type)
    spec.attribute("oiio:ColorSpace", colour_space)
    if path.suffix == ".exr":
        spec.attribute("compression", "zip")
    with signals_deferred():  # one image is written whole or not at all (cnlmc.interrupts)
        output = oiio.ImageOutput.create(str(path))
        if output is None or not output.open(str(path), spec):
            raise MapError(f"cannot write {path}: {oiio.geterror()}")
        ok = output.write_image(np.ascontiguousarray(pixels, np.float32))
        error = output.geterror()  # PNG: a failed write (a full disk) is reported here, not by ok (#13)
        closed = output.close()
        error = error or output.geterror()
    if not ok or not closed or error:
        raise MapError(f"cannot write {path}: {error.strip() or 'the image writer failed'}")


def map_file_name(stem: str, role: str, extension: str) -> str:
    """`{stem}_{role}{extension}`; a stem too long for a file name is shortened with a hash
    (the role and the extension stay readable)."""
    return fit_name(stem, suffix=f"_{role}{extension}")


def write_maps(
    arrays: dict, out_dir, fmt: str = "png8", stem: str = "material", staging: Staging | None = None
) -> list[Path]:
    """Write each role to out_dir/{stem}_{role}{.png|.exr} (see map_file_name); returns the paths
    written. All-or-nothing through cnlmc.output, never outside out_dir (a role such as 'a/../..'
    is refused); with `staging`, the files join it and are written when the caller commits it (the
    maps of several materials as one result)."""
    if fmt not in FORMATS:
        raise MapError(f"unknown map format '{fmt}': use one of {', '.join(FORMATS)}")
    extension, pixel_type = FORMATS[fmt]
    out_dir = Path(out_dir)
    paths = []
    image_library()  # before the staging's signal guard (see image_library)
    with contextlib.nullcontext(staging) if staging is not None else Staging(root=out_dir) as files:
        for role, array in arrays.items():
            pixels, colour_space = encode(role, np.asarray(array, np.float32), extension)
            pixels = np.clip(pixels, 0.0, 1.0) if extension == ".png" else pixels
            path = out_dir / map_file_name(stem, role, extension)
            files.add(path, functools.partial(_write_to, pixels=pixels, pixel_type=pixel_type, space=colour_space))
            paths.append(path)
        if staging is None:
            files.commit()
    return paths


def _write_to(temp: Path, pixels: np.ndarray, pixel_type: str, space: str) -> None:
    write_image(temp, pixels, pixel_type, space)
