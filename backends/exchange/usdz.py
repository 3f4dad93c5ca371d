"""A usdz package written byte for byte the same on every run: the layer first, then the
textures in the order given, stored (not compressed), each file's data aligned to 64 bytes as the
usdz format requires, every entry stamped with the zip epoch (1980-01-01 00:00). Paths inside the
package are the layer's own relative asset paths, unchanged (USD's packager re-paths some of them
to `0/...` and then warns that it cannot resolve them)."""

from __future__ import annotations

import io
import struct
import zipfile
from collections.abc import Sequence

ALIGNMENT = 64  # the usdz format: each file's data starts at a multiple of 64 bytes
EPOCH = (1980, 1, 1, 0, 0, 0)
PADDING_ID = 0x1986  # the extra-field id USD itself uses for alignment padding
LOCAL_HEADER_SIZE = 30
EXTRA_HEADER_SIZE = 4


def package(files: Sequence[tuple[str, bytes]]) -> bytes:
    """(path inside the package, bytes) in order -> the usdz bytes."""
    buffer = io.BytesIO()
    with zipfile.ZipFile(buffer, "w", compression=zipfile.ZIP_STORED) as archive:
        for name, data in files:
            entry = zipfile.ZipInfo(name, date_time=EPOCH)
            entry.compress_type = zipfile.ZIP_STORED
            entry.external_attr = 0o644 << 16
            entry.extra = _padding(buffer.tell() + LOCAL_HEADER_SIZE + len(name.encode("utf-8")))
            archive.writestr(entry, data)
    return buffer.getvalue()


def _padding(data_offset: int) -> bytes:
    """An extra field that moves the entry's data to the next multiple of ALIGNMENT."""
    short = (-data_offset) % ALIGNMENT
    if short == 0:
        return b""
    while short < EXTRA_HEADER_SIZE:
        short += ALIGNMENT
    return struct.pack("<HH", PADDING_ID, short - EXTRA_HEADER_SIZE) + b"\0" * (short - EXTRA_HEADER_SIZE)
