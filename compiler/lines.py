"""Line ends: the ONE definition the compiler, the CLI's error display and the language server share.

Contract:

- `\\r\\n`, `\\n` and a lone `\\r` each end a line (as the Language Server Protocol says). Form feed,
  U+2028/U+2029 (line and paragraph separators), NEL (U+0085) and vertical tab are ordinary
  characters inside a line, NOT line ends (unlike `str.splitlines`).
- Lines are numbered from 1; offsets are indices into the source string (characters, not bytes).
- A source with N line ends has N + 1 lines (the last may be empty); the empty string is one empty line.
- `iter_lines(source)` yields (number, offset, text) for each line, the line end not included in text.
- `line_starts(source)` is the list of the offsets where lines begin ([0] first).
- `LineTable(source)` answers `.line(n)` (text of line n, "" outside the file), `.line_of(offset)`
  (the 1-based line holding an offset) and `.start(n)` in O(log n) after one O(len) pass; make
  one per source (per render, per document version) and reuse it.
"""

from __future__ import annotations

import re
from bisect import bisect_right
from collections.abc import Iterator

__all__ = ["LINE_END", "LineTable", "iter_lines", "line_starts"]

#: A line end: CRLF first so that it counts once, then a lone LF or CR.
LINE_END = re.compile(r"\r\n|\n|\r")


def iter_lines(source: str) -> Iterator[tuple[int, int, str]]:
    """(1-based line number, offset of the line's first character, the line's text without its end)."""
    if "\n" not in source and "\r" not in source:  # one phrase: the common case in an editor or a test
        yield 1, 0, source
        return
    number, offset = 1, 0
    for end in LINE_END.finditer(source):
        yield number, offset, source[offset : end.start()]
        number, offset = number + 1, end.end()
    yield number, offset, source[offset:]


def line_starts(source: str) -> list[int]:
    """The offset of each line's first character, in order; always starts with 0."""
    return [0, *(end.end() for end in LINE_END.finditer(source))]


class LineTable:
    """Line numbers <-> offsets of one source text, built once in O(len(source))."""

    def __init__(self, source: str) -> None:
        self.source = source
        self.starts = line_starts(source)

    def __len__(self) -> int:
        """The number of lines (a source with N line ends has N + 1)."""
        return len(self.starts)

    def start(self, number: int) -> int:
        """The offset of line `number` (1-based); IndexError outside the file."""
        if not 1 <= number <= len(self.starts):
            raise IndexError(f"line {number} is outside 1..{len(self.starts)}")
        return self.starts[number - 1]

    def end(self, number: int) -> int:
        """The offset just past the text of line `number` (before its line end)."""
        start = self.start(number)
        if number == len(self.starts):
            return len(self.source)
        stop = self.starts[number]
        if stop - 2 >= start and self.source.startswith("\r\n", stop - 2):
            return stop - 2
        return stop - 1

    def line(self, number: int) -> str:
        """The text of line `number` (1-based) without its line end; "" outside the file."""
        if not 1 <= number <= len(self.starts):
            return ""
        return self.source[self.start(number) : self.end(number)]

    def line_of(self, offset: int) -> int:
        """The 1-based line holding `offset` (an offset on a line end belongs to that line);
        offsets before 0 or past the end clamp to the first or last line."""
        return max(1, bisect_right(self.starts, offset))

    def position(self, offset: int) -> tuple[int, int]:
        """(1-based line, 0-based column in characters) of `offset`."""
        number = self.line_of(offset)
        return number, max(0, offset - self.starts[number - 1])
