"""ArUco markers: the dictionary we use and a printable PNG of one marker."""

from __future__ import annotations

from pathlib import Path

import numpy as np

from cnlmc.output import write_atomic

from .errors import AROptionError

DICTIONARY_NAME = "DICT_4X4_50"
MARKER_IDS = 50  # the dictionary's markers: ids 0 ... 49
DEFAULT_ID = 0
BITS = 4 + 2  # 4x4 data bits plus the one-bit black border on each side


def dictionary(name: str = DICTIONARY_NAME):
    import cv2

    return cv2.aruco.getPredefinedDictionary(getattr(cv2.aruco, name))


def marker_image(
    marker_id: int = DEFAULT_ID, pixels: int = 480, quiet_zone: int | None = None, name: str = DICTIONARY_NAME
) -> tuple[np.ndarray, int]:
    """(grey uint8 image with a white quiet zone, quiet-zone width in pixels).
    The black square is `pixels` wide; the quiet zone defaults to one marker cell."""
    import cv2

    pixels = int(pixels) // BITS * BITS
    quiet = pixels // BITS if quiet_zone is None else int(quiet_zone)
    square = cv2.aruco.generateImageMarker(dictionary(name), int(marker_id), pixels)
    return cv2.copyMakeBorder(square, quiet, quiet, quiet, quiet, cv2.BORDER_CONSTANT, value=255), quiet


def write_marker(path, marker_id: int = DEFAULT_ID, pixels: int = 480, name: str = DICTIONARY_NAME) -> Path:
    """Write a printable marker PNG (black square `pixels` wide plus a white quiet zone).
    Print it so the black square measures the `marker_length` given to `ar_command`."""
    import cv2

    if not 0 <= int(marker_id) < MARKER_IDS:
        raise AROptionError(f"marker id {marker_id} is outside {name} (0 ... {MARKER_IDS - 1})")
    image, _ = marker_image(marker_id, pixels, name=name)
    path = Path(path)
    ok, data = cv2.imencode(path.suffix or ".png", image)
    if not ok:
        raise OSError(f"cannot encode a marker as '{path.suffix}': use .png")
    write_atomic(path, data.tobytes())
    return path
