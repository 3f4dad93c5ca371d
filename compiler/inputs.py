"""Bounded reading of input files: every file the user hands cnlmc is read through `read_text`.

Contract:

- `read_text(path, *, limit=DEFAULT_MAX_BYTES, what="file") -> str`:
  - `path == "-"` reads standard input, at most `limit` bytes (the error names it `<stdin>`);
  - any other path must be a regular file: a folder, a device (/dev/zero), a FIFO (named pipe) or a
    socket is refused with `NotAFile` before a byte is read (a FIFO is opened without blocking);
  - at most `limit` bytes are read; a larger input raises `InputTooLarge`, whose message names the
    file, its size (or "more than" the limit when unknown), the limit and how to raise it
    (`--max-bytes N` unless the caller says otherwise through `option`);
  - bytes with a NUL are not text (`NotUTF8`: "not a text file"); the others are decoded as UTF-8 (a leading byte order mark is dropped); an invalid byte raises
    `NotUTF8` naming file:line:col of the first bad byte (lines as `cnlmc.lines` counts them);
  - an unreadable path (missing, no permission) raises `InputError` with the system's reason.
- All errors are `InputError`, a `cnlmc.errors.UsageError` (the CLI's exit code 2, no traceback).
- `DEFAULT_MAX_BYTES` (16 MiB, about 400k lines of material phrases) is the limit when none is given.
- `input_name(path)` is the name diagnostics use: `<stdin>` for `-`, else the path.
"""

from __future__ import annotations

import os
import stat
import sys
from codecs import BOM_UTF8
from typing import BinaryIO

from .errors import UsageError
from .lines import LineTable

__all__ = [
    "DEFAULT_MAX_BYTES",
    "InputError",
    "InputTooLarge",
    "NotAFile",
    "NotUTF8",
    "decode_utf8",
    "input_name",
    "read_bytes",
    "read_text",
]

DEFAULT_MAX_BYTES = 16 * 1024 * 1024
_CHUNK = 1 << 20


class InputError(UsageError):
    """An input file that cannot be read as text (exit 2)."""


class NotAFile(InputError):
    """A path that is not a regular file (a folder, a device, a FIFO, a socket)."""


class InputTooLarge(InputError):
    """An input larger than the limit."""

    def __init__(self, name: str, limit: int, size: int | None, option: str) -> None:
        self.name, self.limit, self.size = name, limit, size
        amount = f"{size} bytes" if size is not None else f"more than {limit} bytes"
        super().__init__(
            f"{name}: the input is too large ({amount}; the limit is {limit} bytes = {_human(limit)}); "
            f"raise the limit with {option} N if this is really the file you meant"
        )


class NotUTF8(InputError):
    """Bytes that are not UTF-8 text."""


def input_name(path: str) -> str:
    """The name diagnostics give an input: `<stdin>` for `-`, else the path itself."""
    return "<stdin>" if path == "-" else path


def read_text(path: str, *, limit: int = DEFAULT_MAX_BYTES, what: str = "file", option: str = "--max-bytes") -> str:
    """The UTF-8 text of `path` (or standard input for `-`), at most `limit` bytes; see the module doc."""
    data = read_bytes(path, limit=limit, what=what, option=option)
    if b"\x00" in data:
        raise NotUTF8(f"{input_name(path)}: this is not a text file (it contains NUL bytes)")
    return decode_utf8(data, input_name(path))


def read_bytes(path: str, *, limit: int = DEFAULT_MAX_BYTES, what: str = "file", option: str = "--max-bytes") -> bytes:
    """The bytes of a regular file (or standard input for `-`), at most `limit` of them."""
    if path == "-":
        return _stdin(limit, option)
    try:
        _require_regular(os.stat(path).st_mode, path, what)  # a socket cannot even be opened: say what it is
        fd = os.open(path, os.O_RDONLY | getattr(os, "O_NONBLOCK", 0) | getattr(os, "O_CLOEXEC", 0))
    except OSError as exc:
        raise InputError(f"cannot read '{path}': {exc.strerror}") from None
    try:
        info = os.fstat(fd)
        _require_regular(info.st_mode, path, what)  # again: the path may have been swapped in between
    except BaseException:
        os.close(fd)
        raise
    with os.fdopen(fd, "rb") as handle:
        if info.st_size > limit:
            raise InputTooLarge(path, limit, info.st_size, option)
        try:
            return _bounded(handle, path, limit, info.st_size, option)
        except OSError as exc:
            raise InputError(f"cannot read '{path}': {exc.strerror}") from None


def _stdin(limit: int, option: str) -> bytes:
    """Standard input, bounded; a closed one (`<&-`) is said, not a crash."""
    stream = sys.stdin.buffer if sys.stdin is not None else None
    if stream is None:
        raise InputError("cannot read standard input: it is closed; give a file instead of '-'")
    try:
        return _bounded(stream, "<stdin>", limit, None, option)
    except OSError as exc:
        raise InputError(f"cannot read standard input: {exc.strerror}") from None


def _require_regular(mode: int, path: str, what: str) -> None:
    if stat.S_ISREG(mode):
        return
    kind = (
        "a folder"
        if stat.S_ISDIR(mode)
        else "a FIFO (named pipe)"
        if stat.S_ISFIFO(mode)
        else "a socket"
        if stat.S_ISSOCK(mode)
        else "a device"
        if stat.S_ISCHR(mode) or stat.S_ISBLK(mode)
        else "not a regular file"
    )
    raise NotAFile(
        f"cannot read '{path}': it is {kind}; a {what} must be a regular file "
        f"(or give '-' and pipe the text to standard input)"
    )


def _bounded(handle: BinaryIO, name: str, limit: int, size: int | None, option: str) -> bytes:
    """Read until end of file, never more than limit + 1 bytes (the one extra tells 'too large')."""
    chunks: list[bytes] = []
    total = 0
    while total <= limit:
        chunk = handle.read(min(_CHUNK, limit + 1 - total))
        if not chunk:
            return b"".join(chunks)
        chunks.append(chunk)
        total += len(chunk)
    grown = size if size is not None and size > limit else None
    raise InputTooLarge(name, limit, grown, option)


def decode_utf8(data: bytes, name: str) -> str:
    """UTF-8 text (a leading byte order mark dropped); NotUTF8 at file:line:col of the first bad byte."""
    bom = len(BOM_UTF8) if data.startswith(BOM_UTF8) else 0  # utf-8-sig counts its error offsets after the BOM
    try:
        return data[bom:].decode("utf-8")
    except UnicodeDecodeError as exc:
        start = bom + exc.start
        good = data[bom:start].decode("utf-8")
        line, column = LineTable(good).position(len(good))
        raise NotUTF8(
            f"{name}:{line}:{column + 1}: not UTF-8 text (byte 0x{data[start]:02x} at byte offset {start}); "
            f"save the file as UTF-8"
        ) from None


def _human(size: int) -> str:
    for unit, scale in (("GiB", 1 << 30), ("MiB", 1 << 20), ("KiB", 1 << 10)):
        if size >= scale:
            return f"{size / scale:g} {unit}"
    return f"{size} bytes"
