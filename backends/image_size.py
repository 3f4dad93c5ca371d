"""The one size check for images cnlmc reads (a preview's `--env` map, an AR photo): the size is
read from the file's header before anything is decoded, and an image over `MAX_PIXELS` is refused
with an error naming the file and its size, instead of allocating gigabytes (or crashing inside
a decoder) for a header that claims 60000 x 60000 pixels.

    check_image_size(path, what="environment map")   # ImageTooLarge (a ValueError) when too big

PNG and JPEG headers are parsed here; other formats are asked of OpenImageIO (which reads only
the header when it opens a file) when it is installed. A header that cannot be read is left to
the decoder, which then says why it cannot read the file.
"""

from __future__ import annotations

import struct
from pathlib import Path
from typing import BinaryIO

#: the largest image read, in pixels: 2^27 = 16384 x 8192 (a "16K" HDR environment), about
#: 1.6 GB as linear float RGB
MAX_PIXELS = 1 << 27
PNG_SIGNATURE = b"\x89PNG\r\n\x1a\n"
JPEG_SOF = {0xC0, 0xC1, 0xC2, 0xC3, 0xC5, 0xC6, 0xC7, 0xC9, 0xCA, 0xCB, 0xCD, 0xCE, 0xCF}
JPEG_MAX_SEGMENTS = 4096


class ImageTooLarge(ValueError):
    """An image whose header claims more than MAX_PIXELS pixels."""


def _png_size(head: bytes) -> tuple[int, int] | None:
    if head[:8] != PNG_SIGNATURE or head[12:16] != b"IHDR" or len(head) < 24:
        return None
    width, height = struct.unpack(">II", head[16:24])
    return width, height


def _jpeg_size(handle: BinaryIO) -> tuple[int, int] | None:
    """The frame size of a JPEG: walk the segments to the first start-of-frame marker."""
    handle.seek(2)
    for _ in range(JPEG_MAX_SEGMENTS):
        marker = handle.read(2)
        if len(marker) < 2 or marker[0] != 0xFF:
            return None
        if marker[1] in (0xD8, 0x01) or 0xD0 <= marker[1] <= 0xD7 or marker[1] == 0xFF:
            if marker[1] == 0xFF:
                handle.seek(-1, 1)  # a fill byte
            continue
        length = handle.read(2)
        if len(length) < 2:
            return None
        if marker[1] in JPEG_SOF:
            frame = handle.read(5)
            if len(frame) < 5:
                return None
            height, width = struct.unpack(">HH", frame[1:5])
            return width, height
        handle.seek(struct.unpack(">H", length)[0] - 2, 1)
    return None


def _oiio_size(path: Path) -> tuple[int, int] | None:
    try:
        import OpenImageIO as oiio
    except ImportError:
        return None
    image = oiio.ImageInput.open(str(path))
    if image is None:
        oiio.geterror()  # clear it: the decoder will say what is wrong
        return None
    try:
        spec = image.spec()
        return int(spec.width), int(spec.height)
    finally:
        image.close()


def header_size(path: str | Path) -> tuple[int, int] | None:
    """(width, height) from the file's header, without decoding; None when it cannot tell."""
    path = Path(path)
    with path.open("rb") as handle:
        head = handle.read(24)
        if head.startswith(PNG_SIGNATURE):
            return _png_size(head)
        if head.startswith(b"\xff\xd8"):
            return _jpeg_size(handle)
    return _oiio_size(path)


def check_image_size(path: str | Path, what: str = "image") -> None:
    """Raise ImageTooLarge naming the file and its size when its header claims more than MAX_PIXELS."""
    size = header_size(path)
    if size is None:
        return
    width, height = size
    if width * height > MAX_PIXELS:
        raise ImageTooLarge(
            f"{what} {path} is {width} x {height} pixels ({width * height / 1e6:.0f} megapixels); "
            f"cnlmc reads images of at most {MAX_PIXELS / 1e6:.0f} megapixels (16384 x 8192): scale it down"
        )
