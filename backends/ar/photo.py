"""`cnlmc ar PHOTO`: one photo in, the photo with the object standing on the marker out."""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from cnlmc.output import write_atomic

from ..image_size import ImageTooLarge, check_image_size
from .compositor import composite
from .errors import AROptionError, PhotoUnreadable
from .options import IR, parse_options, pick_material


def read_photo(path) -> np.ndarray:
    """The photo as BGR uint8; its size is checked from the header before decoding
    (cnlmc.backends.image_size: PhotoUnreadable naming the file and its size)."""
    import cv2

    path = Path(path)
    if not path.exists():
        raise PhotoUnreadable(f"photo {path} does not exist")
    try:
        check_image_size(path, "photo")
        image = cv2.imread(str(path), cv2.IMREAD_COLOR)
    except ImageTooLarge as exc:
        raise PhotoUnreadable(str(exc)) from None
    except cv2.error as exc:  # a decoder's own refusal, e.g. its pixel limit for a format without a header check
        raise PhotoUnreadable(f"cannot read {path} as an image: {str(exc).strip().splitlines()[-1]}") from None
    if image is None:
        raise PhotoUnreadable(f"cannot read {path} as an image")
    return image


@dataclass
class ARReport:
    path: Path
    frames: int
    poses: list
    missed: int = 0
    notes: list = field(default_factory=list)


def ar_command(
    photo_path: str | Path, ir: IR, out_path: str | Path, options: Mapping[str, object] | None = None
) -> ARReport:
    """Photo with a printed marker -> the same photo with the material's object standing on it.
    Raises NoMarkerFound ("no marker found in photo.jpg ..."), PhotoUnreadable, AROptionError."""
    opts = parse_options(options)
    material = pick_material(ir, opts.material)
    photo = read_photo(photo_path)
    result = composite(photo, material, opts, source=Path(photo_path).name)
    out_path = Path(out_path)
    write_image_atomic(out_path, result.image)
    return ARReport(out_path, 1, [result.pose])


def write_image_atomic(path: Path, image) -> None:
    """Encode by the file's extension and write it whole or not at all."""
    import cv2

    ok, data = cv2.imencode(path.suffix or ".png", image)
    if not ok:
        raise AROptionError(f"cannot encode an image as '{path.suffix}': use .png or .jpg")
    write_atomic(path, data.tobytes())
