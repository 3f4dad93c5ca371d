"""LSP frames over a byte stream, read with bounds: what a client sends cannot exhaust memory,
crash the reader or leave it waiting for a frame that will never be complete.

A frame is header lines (`Name: value`, each ending in CRLF; a bare LF is accepted too), an
empty line, then exactly Content-Length bytes of JSON. Limits:

- a header line is at most MAX_HEADER_LINE_BYTES, a header block at most MAX_HEADER_LINES lines;
- a body is at most MAX_FRAME_BYTES (64 MiB): a larger Content-Length (10^11, 10^30) is refused
  before anything is allocated;
- a header block without a valid Content-Length, or with one over the limit, is dropped, and so
  is anything between frames that is not a header: the reader then looks for the next
  `Content-Length:` header and carries on from there.

Every drop is written to stderr as one log line (runs of dropped bytes are counted, not echoed).
"""

from __future__ import annotations

import logging
from collections.abc import Callable
from typing import BinaryIO

MAX_HEADER_LINE_BYTES = 8 * 1024
MAX_HEADER_LINES = 32
MAX_FRAME_BYTES = 64 * 1024 * 1024
CONTENT_LENGTH = b"content-length:"
MAX_LENGTH_DIGITS = 12  # enough for any length up to the limit; 10^30 has 31 and is refused as text

log = logging.getLogger("cnlmc.lsp")


class FrameReader:
    """Reads one frame body at a time from a blocking binary stream (stdin); None at the end."""

    def __init__(self, stream: BinaryIO, warn: Callable[[str], None] = log.warning) -> None:
        self.stream = stream
        self.warn = warn
        self.dropped = 0  # bytes skipped since the last good header (reported as one line)
        self._pending: bytes | None = None  # a header line found inside skipped bytes

    def next_frame(self) -> bytes | None:
        """The next frame's body; None when the stream ends."""
        while True:
            headers = self._header_block()
            if headers is None:
                self._report_dropped()
                return None
            length = self._content_length(headers)
            if length is None:
                continue
            self._report_dropped()
            body = self.stream.read(length) if length else b""
            if len(body) < length:
                self.warn(f"the client closed the connection {length - len(body)} bytes before the end of a frame")
                return None
            return body

    def _header_block(self) -> list[bytes] | None:
        """The header lines of the next frame (without line ends); None at the end of the stream."""
        lines: list[bytes] = []
        while True:
            raw = self._raw_line()
            if raw is None:
                return None
            if not raw.endswith(b"\n"):  # over the limit, or cut off by the end of the stream
                if not self._skip_overlong(raw):
                    return None
                lines = []
                continue
            line = raw[:-2] if raw.endswith(b"\r\n") else raw[:-1]
            if not line:
                if lines:
                    return lines
                continue  # a blank line between frames
            if not _is_header(line):
                self._skip(line)
                lines = []
                continue
            lines.append(line)
            if len(lines) > MAX_HEADER_LINES:
                self.warn(f"dropped a frame with more than {MAX_HEADER_LINES} header lines")
                lines = []

    def _raw_line(self) -> bytes | None:
        """One line with its end, at most MAX_HEADER_LINE_BYTES + 1 bytes; None at the end."""
        if self._pending is not None:
            raw, self._pending = self._pending, None
            return raw
        return self.stream.readline(MAX_HEADER_LINE_BYTES + 1) or None

    def _skip_overlong(self, raw: bytes) -> bool:
        """Skip a line over the limit, keeping only its last MAX_HEADER_LINE_BYTES bytes in memory;
        a header glued to its end is read next. False when the stream ended first."""
        window = raw
        while not window.endswith(b"\n"):
            more = self.stream.readline(MAX_HEADER_LINE_BYTES + 1)
            if not more:
                self.dropped += len(window)
                return False
            keep = window[-MAX_HEADER_LINE_BYTES:]
            self.dropped += len(window) - len(keep)
            window = keep + more
        found = window.lower().rfind(CONTENT_LENGTH)
        if found >= 0 and len(window) - found <= MAX_HEADER_LINE_BYTES:
            self.dropped += found
            self._pending = window[found:]
        else:
            self.dropped += len(window)
        return True

    def _skip(self, line: bytes) -> None:
        """Drop a line that is not a header; a header glued to its end is read next."""
        found = line.lower().rfind(CONTENT_LENGTH)
        if found > 0:
            self.dropped += found
            self._pending = line[found:] + b"\r\n"
        else:
            self.dropped += len(line) + 1

    def _content_length(self, headers: list[bytes]) -> int | None:
        """The body length the headers give, or None (and a log line) when the frame is dropped."""
        values = [h.split(b":", 1)[1].strip() for h in headers if h.lower().startswith(CONTENT_LENGTH)]
        if not values:
            self.warn("dropped a frame without a Content-Length header")
            return None
        value = values[-1]
        if not value.isdigit():
            self.warn(f"dropped a frame whose Content-Length is not a number: {_shown(value)}")
            return None
        if len(value) > MAX_LENGTH_DIGITS or int(value) > MAX_FRAME_BYTES:
            self.warn(
                f"dropped a frame of {_shown(value)} bytes: the limit is {MAX_FRAME_BYTES} bytes "
                f"({MAX_FRAME_BYTES // 2**20} MiB)"
            )
            return None
        return int(value)

    def _report_dropped(self) -> None:
        if self.dropped:
            self.warn(f"skipped {self.dropped} bytes that were not an LSP frame (expected 'Content-Length: N')")
            self.dropped = 0


def _is_header(line: bytes) -> bool:
    """`Name: value` with a token for a name; a line with a Content-Length header glued to other
    bytes before it is not one (the reader resynchronises on that header instead)."""
    name, colon, _value = line.partition(b":")
    if not colon or not name or line.lower().rfind(CONTENT_LENGTH) > 0:
        return False
    return all(c in _TOKEN for c in name)


_TOKEN = frozenset(b"!#$%&'*+-.^_`|~0123456789ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz")


def _shown(value: bytes) -> str:
    """A header value for a log line: printable ASCII, at most 40 characters."""
    text = value[:40].decode("ascii", "replace")
    text = "".join(ch if ch.isprintable() else "?" for ch in text)
    return text + ("..." if len(value) > 40 else "")


class PipeWriter:
    """pygls' writer interface over stdout; a broken pipe (the client is gone) stops the server
    once instead of raising in whatever handler was sending."""

    def __init__(self, stream: BinaryIO, on_lost: Callable[[], None]) -> None:
        self.stream = stream
        self.on_lost = on_lost
        self.lost = False

    def write(self, data: bytes) -> None:
        if self.lost:
            return
        try:
            self.stream.write(data)
            self.stream.flush()
        except (OSError, ValueError) as exc:
            self.lost = True
            log.warning("cannot write to the client any more (%s); stopping", exc)
            self.on_lost()

    def close(self) -> None:
        try:
            self.stream.flush()
        except (OSError, ValueError):
            pass
