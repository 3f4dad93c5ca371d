"""A usdz package written byte for byte the same every time (docs/gltf.md, "USDZ for AR Quick Look").

A usdz is a zip archive with rules of its own (the USDZ specification, and OpenUSD's usdUtils
compliance checker): every file stored uncompressed, each file's data starting on a 64-byte
boundary, the root layer (a .usdc) first. This writer adds fixed timestamps (1980-01-01, the zip
epoch) and fixed permissions, so the same files give the same bytes; the alignment is padding in
each local header's extra field (a block of its own, id 0x1986, as OpenUSD's own writer pads).
"""

from __future__ import annotations

import io
import struct
import zipfile
from collections.abc import Sequence

ALIGNMENT = 64
PADDING_ID = 0x1986
LOCAL_HEADER = 30  # bytes before the file name in a zip local file header (APPNOTE 4.3.7)
ZIP_EPOCH = (1980, 1, 1, 0, 0, 0)


def padding_for(offset: int, name: bytes) -> bytes:
    """The extra field that puts a file's data (after its local header at `offset`) on the boundary."""
    start = offset + LOCAL_HEADER + len(name)
    gap = -start % ALIGNMENT
    if gap == 0:
        return b""
    while gap < 4:  # an extra block holds at least its id and its size
        gap += ALIGNMENT
    return struct.pack("<HH", PADDING_ID, gap - 4) + b"\0" * (gap - 4)


def usdz_bytes(files: Sequence[tuple[str, bytes]]) -> bytes:
    """(name inside the package, content) in order (the root .usdc first) -> the package's bytes."""
    buffer = io.BytesIO()
    with zipfile.ZipFile(buffer, "w", zipfile.ZIP_STORED) as archive:
        for name, content in files:
            info = zipfile.ZipInfo(name, date_time=ZIP_EPOCH)
            info.compress_type = zipfile.ZIP_STORED
            info.external_attr = 0o644 << 16
            info.create_system = 3
            info.extra = padding_for(buffer.tell(), name.encode("utf-8"))
            archive.writestr(info, content)
    return buffer.getvalue()
