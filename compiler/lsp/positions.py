"""Character offsets <-> LSP positions (0-based line, column in the negotiated code units)."""

from __future__ import annotations

from bisect import bisect_right

from lsprotocol import types

from ..spans import Span


def code_units(text: str, encoding: str) -> int:
    """How many code units `text` takes in the client's position encoding."""
    if text.isascii() or encoding == "utf-32":
        return len(text)
    if encoding == "utf-8":
        return len(text.encode("utf-8"))
    return len(text) + sum(1 for ch in text if ord(ch) > 0xFFFF)


def chars_for_units(line: str, units: int, encoding: str) -> int:
    """The character column that `units` code units into `line` reach (clamped to the line)."""
    if line.isascii() or encoding == "utf-32":
        return max(0, min(units, len(line)))
    used = 0
    for i, ch in enumerate(line):
        if used >= units:
            return i
        used += code_units(ch, encoding)
    return len(line)


class LineIndex:
    """Line starts of one text, for converting compiler offsets and spans to LSP ranges."""

    def __init__(self, text: str, encoding: str = "utf-16"):
        self.text = text
        self.encoding = encoding
        self.lines = [line.rstrip("\r") for line in text.split("\n")]
        self.starts = []
        offset = 0
        for raw in text.split("\n"):
            self.starts.append(offset)
            offset += len(raw) + 1

    def line_of(self, offset: int) -> int:
        return max(0, bisect_right(self.starts, offset) - 1)

    def position(self, offset: int) -> types.Position:
        offset = max(0, min(offset, len(self.text)))
        line = self.line_of(offset)
        col = min(offset - self.starts[line], len(self.lines[line]))
        return types.Position(line, code_units(self.lines[line][:col], self.encoding))

    def span_range(self, span: Span) -> types.Range:
        return types.Range(self.position(span.start), self.position(span.end))

    def line_col(self, position: types.Position) -> tuple[int, int] | None:
        """(0-based line, character column) of an LSP position; None when the line does not exist."""
        if position.line < 0 or position.line >= len(self.lines):
            return None
        line = self.lines[position.line]
        return position.line, chars_for_units(line, max(0, position.character), self.encoding)

    def offset(self, position: types.Position) -> int | None:
        found = self.line_col(position)
        if found is None:
            return None
        line, col = found
        return self.starts[line] + col

    def line_end(self, line: int) -> types.Position:
        return types.Position(line, code_units(self.lines[line], self.encoding))

    def range_of(self, line: int, start_col: int, end_col: int) -> types.Range:
        text = self.lines[line]
        return types.Range(
            types.Position(line, code_units(text[:start_col], self.encoding)),
            types.Position(line, code_units(text[:end_col], self.encoding)),
        )
